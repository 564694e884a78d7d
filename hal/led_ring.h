#pragma once
// The LED ring around the lens, switched through driver transistors: one GPIO line for the
// whole ring, or one line per segment (a sector of the ring) where the ring is wired so.
// A segmented ring lights a segment alone for the frames the contact edge's tilt is read
// from (vision/contact_tilt.h): segment k's centre at the image azimuth the config gives
// for segment 0 plus k · 360° / segments(), from +x toward +y (rows down).
#include "hal/error.h"

namespace icacam::hal {

class LedRing {
public:
    virtual ~LedRing() = default;
    // The whole ring (every segment) on, or everything off.
    virtual Error set(bool on) = 0;
    // True while any part of the ring is switched on.
    virtual bool isOn() const = 0;
    // Segments that can be lit alone; 1: the ring is one line.
    virtual int segments() const { return 1; }
    // Segment k (0 … segments() − 1) on alone, every other off; set(false) ends it. Errors:
    // Invalid (no such segment; a ring of one line has none), Io.
    virtual Error lightSegment(int /*k*/)
    {
        return Error::make(Errc::Invalid, "the LED ring is one line: no segment to light alone");
    }
};

} // namespace icacam::hal
