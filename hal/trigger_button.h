#pragma once
// The trigger button: raw, timestamped edges in order. Debounce and long press are decided
// by the firmware from the timestamps (a real GPIO line bounces; libgpiod hands out edges
// with kernel timestamps, and so does the file backend).
#include <cstddef>
#include <cstdint>

#include "hal/error.h"

namespace icacam::hal {

struct ButtonEdge {
    int64_t timeMs = 0;   // Clock::monotonicMs() time of the edge
    bool pressed = false; // true: the button went down
};

class TriggerButton {
public:
    virtual ~TriggerButton() = default;
    // Copies up to cap edges that have happened by now into out, oldest first, and returns
    // how many. Never blocks. Errors: Io, Closed.
    virtual Result<size_t> readEdges(ButtonEdge *out, size_t cap) = 0;
    // The button's level now (true = pressed). After a measurement the firmware reads it
    // again, so a release lost in a full event queue (libgpiod 1.6 drops the newest event)
    // does not leave the button "held". Backends without a level: Invalid.
    virtual Result<bool> pressed() { return Result<bool>::fail(Errc::Invalid, "no level"); }
};

} // namespace icacam::hal
