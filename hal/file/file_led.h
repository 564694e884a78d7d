#pragma once
// The LED ring as a log: one line "MONOTONIC_MS on|off" per switch of the whole ring and
// "MONOTONIC_MS segment K" per segment lit alone, so a test can check that the ring was lit
// exactly around each capture. With a ScriptedLight, each switch also reaches the light the
// file camera's frames are lit by (hal/file/scripted_light.h).
#include <string>

#include "hal/clock.h"
#include "hal/file/scripted_light.h"
#include "hal/led_ring.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class FileLed final : public LedRing {
public:
    // A ring of `segments` lines (1: one line, no segment lit alone); the light is told how
    // many.
    explicit FileLed(Clock &clock, ScriptedLight *light = nullptr, int segments = 1)
            : clock_(clock), light_(light), segments_(segments)
    {
        if (light_) (void)light_->setSegments(segments); // a count below 1 is refused by open()
    }
    // An empty path: no log, state only. Errors: Io, Invalid (fewer than 1 segment).
    Error open(const std::string &logPath);
    Error set(bool on) override;
    bool isOn() const override { return lit_ != kDark; }
    int segments() const override { return segments_; }
    // Errors: Invalid (one segment, k out of range; nothing logged or changed), Io (the log).
    Error lightSegment(int k) override;
    // Changes of what is lit (dark, the whole ring, one segment).
    int switchCount() const { return switches_; }

private:
    static constexpr int kDark = -2, kWholeRing = -1; // what is lit: these, or a segment
    Error log(const char *what, int k);

    Clock &clock_;
    ScriptedLight *light_;
    int segments_;
    UniqueFd fd_;
    int lit_ = kDark;
    int switches_ = 0;
};

} // namespace icacam::hal
