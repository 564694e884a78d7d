#pragma once
// The light the LED ring gives, as the file camera sees it: when the ring was switched on and
// off (hal::FileLed tells it), and when it really gave light, from a script of the faults a
// real ring has. One line per switch-on, used in order ('#' starts a comment); once the script
// is used up the ring lights when switched:
//   ok         lights at once, until switched off
//   late MS    lights MS after being switched on (a slow driver, a soft-start supply)
//   dead       gives no light (a broken LED, driver transistor or wire, led.active wrong)
//   flash MS   lights for MS only, then goes dark (a failing driver, a thermal cut-out)
// A segmented ring (hal::FileLed with segments) lights one segment alone as a switch-on of
// its own: it takes the next script line as the whole ring does, and the light remembers
// which lit each interval, the whole ring or one segment.
// hal::FileCamera asks, row by row, how much of each row's exposure was lit, so a frame taken
// across the light's edge is lit only in part, as a rolling-shutter sensor's is.
#include <cstdint>
#include <string>
#include <string_view>

#include "hal/clock.h"
#include "hal/error.h"

namespace icacam::hal {

class ScriptedLight {
public:
    explicit ScriptedLight(Clock &clock) : clock_(clock) {}
    // Reads a script file ("" : no script, the ring lights when switched). Errors: NotFound,
    // Invalid (a line it does not know, with its number).
    Error open(const std::string &path);
    // Appends script text (tests). Errors: Invalid.
    Error feed(std::string_view script);

    // The ring's segments (hal::FileLed sets it): the share of the ring's light one segment
    // gives is 1 / segments(). Errors: Invalid (fewer than 1; the count is kept).
    Error setSegments(int n);
    int segments() const { return segments_; }

    // The whole ring was switched now: on, or everything off (a lit segment too).
    void switched(bool on);
    // Segment k (0 … segments() − 1) was lit alone now: whatever was lit ends, and k lights as
    // a new switch-on. Lit already: nothing changes. A negative k is ignored.
    void switchedSegment(int k);
    // The part of [fromMs, toMs] the whole ring gave light in (0 … 1); fromMs == toMs: at
    // that instant, 0 or 1. A segment lit alone is not counted.
    double litFraction(double fromMs, double toMs) const;
    // The same for the light of `segment` (0 … segments() − 1) lit alone; the whole ring's
    // light is not counted.
    double litFraction(double fromMs, double toMs, int segment) const;

private:
    enum class Fault : uint8_t { Ok, Late, Dead, Flash };
    struct Step {
        Fault fault = Fault::Ok;
        int ms = 0;
    };
    static constexpr int kDark = -2, kWholeRing = -1; // what is lit: these, or a segment
    struct Interval {
        double onMs = 0, offMs = 0; // lit in [onMs, offMs)
        int by = kWholeRing;        // the whole ring or segment k
    };
    static constexpr int kSteps = 64;     // script lines kept
    static constexpr int kIntervals = 32; // light intervals remembered (the newest)

    Clock &clock_;
    Step steps_[kSteps];
    int stepCount_ = 0, nextStep_ = 0;
    Interval lit_[kIntervals];
    int litCount_ = 0; // intervals held, the newest last
    int switchedTo_ = kDark;
    int segments_ = 1;

    void switchTo(int what);
    double fraction(double fromMs, double toMs, int by) const;
};

} // namespace icacam::hal
