#pragma once
// The LED ring as a log: one line "MONOTONIC_MS on|off" per change, so a test can check that
// the ring was lit exactly around each capture. With a ScriptedLight, each switch also
// reaches the light the file camera's frames are lit by (hal/file/scripted_light.h).
#include <string>

#include "hal/clock.h"
#include "hal/file/scripted_light.h"
#include "hal/led_ring.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class FileLed final : public LedRing {
public:
    explicit FileLed(Clock &clock, ScriptedLight *light = nullptr) : clock_(clock), light_(light) {}
    Error open(const std::string &logPath); // an empty path: no log, state only
    Error set(bool on) override;
    bool isOn() const override { return on_; }
    int switchCount() const { return switches_; }

private:
    Clock &clock_;
    ScriptedLight *light_;
    UniqueFd fd_;
    bool on_ = false;
    int switches_ = 0;
};

} // namespace icacam::hal
