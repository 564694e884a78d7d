#include "firmware/net/login_queue.h"

namespace icacam::fw::net {

LoginQueue::LoginQueue(Check check, Done done) : check_(std::move(check)), done_(std::move(done))
{
    worker_ = std::thread([this] { run(); });
}

bool LoginQueue::post(LoginJob *job)
{
    {
        std::lock_guard<std::mutex> lock(m_);
        if (stopping_ || waiting_.size() >= kWaiting) return false;
        waiting_.push_back(job);
    }
    cv_.notify_one();
    return true;
}

void LoginQueue::stop()
{
    {
        std::lock_guard<std::mutex> lock(m_);
        if (stopping_ && !worker_.joinable()) return;
        stopping_ = true;
    }
    cv_.notify_one();
    if (worker_.joinable()) worker_.join();
}

void LoginQueue::run()
{
    for (;;) {
        LoginJob *job = nullptr;
        {
            std::unique_lock<std::mutex> lock(m_);
            cv_.wait(lock, [this] { return stopping_ || !waiting_.empty(); });
            if (stopping_) {
                for (LoginJob *j : waiting_) done_(j); // unanswered: the server refuses them
                waiting_.clear();
                return;
            }
            job = waiting_.front();
            waiting_.pop_front();
        }
        HttpRequest r;
        r.method = job->method;
        r.path = job->path;
        r.query = job->query;
        r.body = job->body;
        r.contentType = job->contentType;
        r.session = job->session;
        r.nowMs = job->nowMs;
        job->answer = check_(r);
        job->answered = true;
        done_(job);
    }
}

} // namespace icacam::fw::net
