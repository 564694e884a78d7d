#pragma once
// Logins checked off the web server's thread. An Argon2id check takes about a third of a
// second by design (web_auth.h); on libmicrohttpd's one polling thread it would hold every
// page and picture for that long. The server suspends a login's connection and posts it here;
// one worker checks one login at a time and hands the answer back, and the server resumes the
// connection (MHD_ALLOW_SUSPEND_RESUME). Logins waiting are bounded: one more than
// kWaiting is refused at once (the server answers 503), not queued without end.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "firmware/net/web_api.h"

namespace icacam::fw::net {

// A login as the server took it in: the request's own copies (the connection's buffers are
// not the worker's to read), and the answer once checked.
struct LoginJob {
    std::string method, path, query, body, contentType, session;
    int64_t nowMs = 0;
    HttpResponse answer;
    bool answered = false;      // set by the worker before done() is called
    void *connection = nullptr; // the server's: what done() resumes
};

class LoginQueue {
public:
    static constexpr size_t kWaiting = 4;
    // check: the answer to a login request (WebApi::handle). done: called on the worker once
    // a job is answered, or at stop() for one never checked (answered false); the job is not
    // touched after it.
    using Check = std::function<HttpResponse(const HttpRequest &)>;
    using Done = std::function<void(LoginJob *)>;

    LoginQueue(Check check, Done done);
    ~LoginQueue() { stop(); }
    LoginQueue(const LoginQueue &) = delete;
    LoginQueue &operator=(const LoginQueue &) = delete;

    // False when kWaiting logins wait already (or the queue is stopped): not taken.
    bool post(LoginJob *job);
    // The login being checked is finished; the ones waiting are handed back unchecked.
    void stop();

private:
    void run();

    Check check_;
    Done done_;
    std::mutex m_;
    std::condition_variable cv_;
    std::deque<LoginJob *> waiting_;
    bool stopping_ = false;
    std::thread worker_;
};

} // namespace icacam::fw::net
