#pragma once
// The light the LED ring gives, as the file camera sees it: when the ring was switched on and
// off (hal::FileLed tells it), and when it really gave light, from a script of the faults a
// real ring has. One line per switch-on, used in order ('#' starts a comment); once the script
// is used up the ring lights when switched:
//   ok         lights at once, until switched off
//   late MS    lights MS after being switched on (a slow driver, a soft-start supply)
//   dead       gives no light (a broken LED, driver transistor or wire, led.active wrong)
//   flash MS   lights for MS only, then goes dark (a failing driver, a thermal cut-out)
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

    // The ring was switched now.
    void switched(bool on);
    // The part of [fromMs, toMs] the ring gave light in (0 … 1); fromMs == toMs: at that
    // instant, 0 or 1.
    double litFraction(double fromMs, double toMs) const;

private:
    enum class Fault : uint8_t { Ok, Late, Dead, Flash };
    struct Step {
        Fault fault = Fault::Ok;
        int ms = 0;
    };
    struct Interval {
        double onMs = 0, offMs = 0; // lit in [onMs, offMs)
    };
    static constexpr int kSteps = 64;     // script lines kept
    static constexpr int kIntervals = 32; // light intervals remembered (the newest)

    Clock &clock_;
    Step steps_[kSteps];
    int stepCount_ = 0, nextStep_ = 0;
    Interval lit_[kIntervals];
    int litCount_ = 0; // intervals held, the newest last
    bool on_ = false;
};

} // namespace icacam::hal
