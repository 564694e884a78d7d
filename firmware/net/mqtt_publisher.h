#pragma once
// Every journaled record published to an MQTT broker (libmosquitto), QoS 1, from the
// journal itself: the payload is the record's journal line (with its CRC), on
// TOPIC/result (scale checks on TOPIC/scalecheck). The broker's PUBACK moves the last
// acknowledged id, kept in STATE_FILE beside the journal, so results made while the broker
// was away, or before a restart, are sent when it is back; a result is sent again only when
// its PUBACK was lost (a consumer de-duplicates by the record's id). TOPIC/state is
// "online", retained, while connected, and the broker's last will makes it "offline".
// One thread of its own owns the client: connects with a doubling back-off, reads the
// journal, publishes. The device only stores the newest id in an atomic.
#include <atomic>
#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

#include "firmware/net/device_listener.h"
#include "firmware/net/journal_tail.h"
#include "hal/storage.h"

struct mosquitto;

namespace icacam::fw::net {

struct MqttSettings {
    std::string host;
    int port = 1883;
    std::string topic = "icacam";
    std::string clientId;
    int keepaliveS = 30;
    int maxBackoffMs = 30000;
};

struct MqttStats {
    bool connected = false;
    long ackedId = 0;
    long published = 0;   // PUBLISH packets sent (resends included)
    long connections = 0; // successful connects
    std::string lastProblem;
};

class MqttPublisher final : public DeviceListener {
public:
    static constexpr const char *kStateFile = "mqtt.acked";
    static constexpr int kWindow = 20; // unacknowledged records on the wire at most

    // journalDir: storage on the journal's folder (the state file is written through it);
    // journalPath: journal.jsonl in that folder.
    MqttPublisher(MqttSettings s, hal::Storage &journalDir, std::string journalPath);
    ~MqttPublisher() override;
    // Reads the state file, starts the thread. An error only for a state file that exists
    // and cannot be read; a broker away is not an error.
    hal::Error start();
    void stop();

    void onLine(std::string_view) override {}
    void onJournaled(long id) override { newest_.store(id, std::memory_order_relaxed); }

    MqttStats stats() const;

private:
    void run();
    bool connect();
    void drop(const char *why);
    void publishPending();
    void onConnect(int rc);
    void onPublish(int mid);
    void persist(bool force);
    void problem(const std::string &what);

    MqttSettings s_;
    hal::Storage &dir_;
    JournalTail tail_;
    std::atomic<long> newest_{0};
    std::atomic<bool> stop_{false};
    std::thread thread_;
    mosquitto *mosq_ = nullptr;
    // Read and written on the publishing thread alone (mosquitto's callbacks run there too):
    bool connected_ = false;
    int refusedRc_ = 0;    // the broker's refusal, seen in onConnect
    long publishedId_ = 0; // the newest record handed to the client on this connection
    long ackedId_ = 0, persistedId_ = 0;
    int64_t lastPersistMs_ = 0;
    int backoffMs_ = 0;
    int64_t nextAttemptMs_ = 0;
    struct InFlight {
        int mid;
        long id;
        bool acked;
    };
    std::deque<InFlight> inFlight_;
    std::string stateTopic_, resultTopic_, scaleTopic_;
    mutable std::mutex statsMutex_;
    MqttStats stats_;
};

} // namespace icacam::fw::net
