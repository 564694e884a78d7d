#include "firmware/net/mqtt_publisher.h"

#include <mosquitto.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "firmware/journal.h"

namespace icacam::fw::net {

namespace {

int64_t nowMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

constexpr const char *kOnline = "online", *kOffline = "offline";

// The record's type decides the topic: scale checks are not results.
bool isScaleCheck(std::string_view line)
{
    return line.rfind("{\"type\":\"scalecheck\"", 0) == 0;
}

} // namespace

MqttPublisher::MqttPublisher(MqttSettings s, hal::Storage &journalDir, std::string journalPath)
        : s_(std::move(s)), dir_(journalDir), tail_(std::move(journalPath))
{
    stateTopic_ = s_.topic + "/state";
    resultTopic_ = s_.topic + "/result";
    scaleTopic_ = s_.topic + "/scalecheck";
    if (s_.clientId.empty()) {
        char host[64] = "device";
        gethostname(host, sizeof host - 1);
        s_.clientId = std::string("icacam-") + host;
    }
}

MqttPublisher::~MqttPublisher()
{
    stop();
}

hal::Error MqttPublisher::start()
{
    if (std::string e = tail_.refresh(); !e.empty()) return hal::Error::make(hal::Errc::Io, e);
    hal::Result<std::string> saved = dir_.read(kStateFile);
    if (saved.ok()) {
        char *end = nullptr;
        const long id = std::strtol(saved.value.c_str(), &end, 10);
        if (end == saved.value.c_str() || id < 0)
            return hal::Error::make(hal::Errc::Invalid, std::string(kStateFile) + ": not an id: " + saved.value);
        ackedId_ = id;
        // A journal started afresh (its ids below the acknowledged one) is published from its start.
        if (ackedId_ > tail_.newestId()) ackedId_ = 0;
    } else if (saved.error.code == hal::Errc::NotFound) {
        // MQTT newly configured: the results from now on, not the journal's whole past.
        ackedId_ = tail_.newestId();
    } else {
        return saved.error;
    }
    persistedId_ = -1;
    persist(true);
    publishedId_ = ackedId_;
    {
        std::lock_guard<std::mutex> lock(statsMutex_);
        stats_.ackedId = ackedId_;
    }
    static const int init = mosquitto_lib_init();
    if (init != MOSQ_ERR_SUCCESS) return hal::Error::make(hal::Errc::Io, "libmosquitto: cannot initialise");
    thread_ = std::thread([this] { run(); });
    return {};
}

void MqttPublisher::stop()
{
    if (!thread_.joinable()) return;
    stop_ = true;
    thread_.join();
}

MqttStats MqttPublisher::stats() const
{
    std::lock_guard<std::mutex> lock(statsMutex_);
    return stats_;
}

void MqttPublisher::problem(const std::string &what)
{
    std::lock_guard<std::mutex> lock(statsMutex_);
    if (stats_.lastProblem != what) std::fprintf(stderr, "icacam-fw: mqtt: %s\n", what.c_str());
    stats_.lastProblem = what;
}

bool MqttPublisher::connect()
{
    mosq_ = mosquitto_new(s_.clientId.c_str(), true, this);
    if (!mosq_) {
        problem("cannot create a client");
        return false;
    }
    mosquitto_connect_callback_set(
        mosq_, [](mosquitto *, void *self, int rc) { static_cast<MqttPublisher *>(self)->onConnect(rc); });
    mosquitto_publish_callback_set(
        mosq_, [](mosquitto *, void *self, int mid) { static_cast<MqttPublisher *>(self)->onPublish(mid); });
    mosquitto_int_option(mosq_, MOSQ_OPT_SEND_MAXIMUM, kWindow);
    mosquitto_will_set(mosq_, stateTopic_.c_str(), int(std::string_view(kOffline).size()), kOffline, 1, true);
    // Non-blocking: the TCP handshake finishes inside mosquitto_loop.
    const int rc = mosquitto_connect_async(mosq_, s_.host.c_str(), s_.port, s_.keepaliveS);
    if (rc != MOSQ_ERR_SUCCESS) {
        drop(rc == MOSQ_ERR_ERRNO ? "broker unreachable" : mosquitto_strerror(rc));
        return false;
    }
    return true;
}

void MqttPublisher::drop(const char *why)
{
    if (mosq_) {
        mosquitto_destroy(mosq_);
        mosq_ = nullptr;
    }
    if (connected_)
        problem(std::string("disconnected: ") + why);
    else
        problem(std::string("cannot connect to ") + s_.host + ":" + std::to_string(s_.port) + ": " + why);
    connected_ = false;
    // What the broker did not acknowledge goes again on the next connection.
    inFlight_.clear();
    publishedId_ = ackedId_;
    backoffMs_ = backoffMs_ == 0 ? 500 : std::min(backoffMs_ * 2, s_.maxBackoffMs);
    nextAttemptMs_ = nowMs() + backoffMs_;
    std::lock_guard<std::mutex> lock(statsMutex_);
    stats_.connected = false;
}

void MqttPublisher::onConnect(int rc)
{
    if (rc != 0) { // dropped after mosquitto_loop returns: the client is in use here
        refusedRc_ = rc;
        return;
    }
    connected_ = true;
    backoffMs_ = 0;
    mosquitto_publish(mosq_, nullptr, stateTopic_.c_str(), int(std::string_view(kOnline).size()), kOnline, 1, true);
    std::lock_guard<std::mutex> lock(statsMutex_);
    stats_.connected = true;
    ++stats_.connections;
    stats_.lastProblem.clear();
}

void MqttPublisher::onPublish(int mid)
{
    for (InFlight &f : inFlight_)
        if (f.mid == mid) f.acked = true;
    while (!inFlight_.empty() && inFlight_.front().acked) {
        ackedId_ = inFlight_.front().id;
        inFlight_.pop_front();
    }
    std::lock_guard<std::mutex> lock(statsMutex_);
    stats_.ackedId = ackedId_;
}

void MqttPublisher::persist(bool force)
{
    if (ackedId_ == persistedId_) return;
    const int64_t now = nowMs();
    // At most twice a second while a burst is acknowledged: a crash in between only sends
    // those results again.
    if (!force && now - lastPersistMs_ < 500) return;
    if (hal::Error e = dir_.writeAtomic(kStateFile, std::to_string(ackedId_) + "\n"); !e.ok()) {
        problem(std::string(kStateFile) + ": " + e.message);
        return;
    }
    persistedId_ = ackedId_;
    lastPersistMs_ = now;
}

void MqttPublisher::publishPending()
{
    if (newest_.load(std::memory_order_relaxed) <= publishedId_ && tail_.newestId() <= publishedId_) return;
    if (inFlight_.size() >= size_t(kWindow)) return;
    if (std::string e = tail_.refresh(); !e.empty()) {
        problem(e);
        return;
    }
    const auto lines = tail_.after(publishedId_, size_t(kWindow) - inFlight_.size());
    for (const std::string &line : lines) {
        const long id = Journal::checkLine(line);
        if (id <= publishedId_) continue;
        int mid = 0;
        const std::string &topic = isScaleCheck(line) ? scaleTopic_ : resultTopic_;
        const int rc = mosquitto_publish(mosq_, &mid, topic.c_str(), int(line.size()), line.data(), 1, false);
        if (rc != MOSQ_ERR_SUCCESS) {
            problem(std::string("publish: ") + mosquitto_strerror(rc));
            return;
        }
        inFlight_.push_back({mid, id, false});
        publishedId_ = id;
        std::lock_guard<std::mutex> lock(statsMutex_);
        ++stats_.published;
    }
}

void MqttPublisher::run()
{
    while (!stop_) {
        if (!mosq_) {
            if (nowMs() < nextAttemptMs_ || !connect()) {
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
                continue;
            }
        }
        // Waits on the socket up to 50 ms: a new record is published within that.
        const int rc = mosquitto_loop(mosq_, 50, 1);
        if (rc != MOSQ_ERR_SUCCESS) {
            drop(rc == MOSQ_ERR_ERRNO ? "connection lost" : mosquitto_strerror(rc));
            continue;
        }
        if (refusedRc_ != 0) {
            drop(mosquitto_connack_string(refusedRc_));
            refusedRc_ = 0;
            continue;
        }
        if (connected_) publishPending();
        persist(false);
    }
    if (mosq_) {
        // A clean stop: the state said by hand (a disconnect the broker was told of sends no will).
        if (connected_) {
            mosquitto_publish(mosq_, nullptr, stateTopic_.c_str(), int(std::string_view(kOffline).size()), kOffline, 1,
                              true);
            for (int i = 0; i < 10; ++i) mosquitto_loop(mosq_, 20, 1);
            mosquitto_disconnect(mosq_);
        }
        mosquitto_destroy(mosq_);
        mosq_ = nullptr;
    }
    persist(true);
}

} // namespace icacam::fw::net
