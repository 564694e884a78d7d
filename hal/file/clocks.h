#pragma once
// Two clocks: the system's (for the program on a PC or the board) and a manual one that tests
// set and advance (ArduPilot SITL's idea: the simulation owns time).
#include <time.h>

#include <atomic>
#include <cstdint>

#include "hal/clock.h"

namespace icacam::hal {

class SystemClock final : public Clock {
public:
    int64_t monotonicMs() const override { return read(CLOCK_MONOTONIC); }
    int64_t wallMs() const override { return read(CLOCK_REALTIME); }
    void sleepMs(int64_t ms) override
    {
        if (ms <= 0) return;
        timespec ts{time_t(ms / 1000), long(ms % 1000) * 1000000L};
        while (nanosleep(&ts, &ts) != 0) {}
    }

private:
    static int64_t read(clockid_t id)
    {
        timespec ts{};
        clock_gettime(id, &ts);
        return int64_t(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
    }
};

class ManualClock final : public Clock {
public:
    explicit ManualClock(int64_t startMs = 0, int64_t wallOriginMs = 1767225600000) // 2026-01-01
            : now_(startMs), wallOrigin_(wallOriginMs)
    {}
    int64_t monotonicMs() const override { return now_.load(); }
    int64_t wallMs() const override { return wallOrigin_ + now_.load(); }
    void sleepMs(int64_t ms) override { advance(ms); }
    void advance(int64_t ms)
    {
        if (ms > 0) now_.fetch_add(ms);
    }

private:
    std::atomic<int64_t> now_;
    int64_t wallOrigin_;
};

} // namespace icacam::hal
