#pragma once
// Requests a second per client address: a token bucket per address (a fixed table; the
// longest idle address makes room for a new one). Over the rate, a request is refused with
// 429 before any work is done for it.
#include <array>
#include <cstdint>
#include <mutex>

namespace icacam::fw::net {

class RateLimiter {
public:
    static constexpr int kClients = 64;

    RateLimiter(double perSecond, double burst) : rate_(perSecond), burst_(burst) {}
    // address: an IPv4 or IPv6 address's bytes folded to 64 bits.
    bool allow(uint64_t address, int64_t nowMs);

private:
    struct Bucket {
        uint64_t address = 0;
        double tokens = 0;
        int64_t lastMs = 0;
        bool used = false;
    };
    double rate_, burst_;
    std::mutex mutex_;
    std::array<Bucket, kClients> buckets_{};
};

} // namespace icacam::fw::net
