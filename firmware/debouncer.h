#pragma once
// Turns raw, timestamped button edges into presses. A down/up pair shorter than the debounce
// time is contact bounce and ignored; a press held at least longPressMs is a long press
// (reported as soon as it has been held that long); anything between is a short press,
// reported on release. Pure logic on timestamps, so tests drive it without a clock.
#include <cstdint>

#include "hal/trigger_button.h"

namespace icacam::fw {

enum class Press { None, Short, Long };

class Debouncer {
public:
    Debouncer(int debounceMs, int longPressMs) : debounce_(debounceMs), long_(longPressMs) {}
    Press onEdge(const hal::ButtonEdge &e);
    Press poll(int64_t nowMs); // long presses fire while the button is still held
    bool isDown() const { return down_; }
    // The line's level read directly: a button found up while held here was released
    // without its edge reaching us (a full event queue); no press is reported for it.
    void resync(bool pressedNow)
    {
        if (!pressedNow) down_ = false;
    }

private:
    int64_t debounce_, long_;
    bool down_ = false;
    bool longFired_ = false;
    int64_t downAt_ = 0;
};

} // namespace icacam::fw
