#pragma once
// Time is a HAL service (STYLE.md §4): debounce, timeouts and the capture watchdog read it;
// tests set it. Monotonic milliseconds for intervals, wall-clock for timestamps in records.
#include <cstdint>

namespace icacam::hal {

class Clock {
public:
    virtual ~Clock() = default;
    // Monotonic milliseconds since an arbitrary origin; never goes back.
    virtual int64_t monotonicMs() const = 0;
    // Milliseconds since the Unix epoch (UTC), for record timestamps only.
    virtual int64_t wallMs() const = 0;
    // Sleeps (or, for a manual clock, advances) by ms.
    virtual void sleepMs(int64_t ms) = 0;
};

} // namespace icacam::hal
