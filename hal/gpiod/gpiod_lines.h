#pragma once
// The trigger button and the LED ring on GPIO lines through libgpiod's character-device API.
// One interface for libgpiod 1.6 (Debian bookworm) and 2.x (trixie): the version is chosen
// at compile time in gpiod_lines.cpp; nothing here depends on it. libgpiod is a C API: it
// reports errors through errno, which is turned into hal::Error values.
#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include "hal/clock.h"
#include "hal/led_ring.h"
#include "hal/trigger_button.h"

namespace icacam::hal {

struct GpioLineSpec {
    GpioLineSpec() = default;
    GpioLineSpec(std::string chip, unsigned line, bool activeLowLevel = false, bool withPullUp = false)
            : chipPath(std::move(chip)), offset(line), activeLow(activeLowLevel), pullUp(withPullUp)
    {}

    std::string chipPath = "/dev/gpiochip0";
    unsigned offset = 0;
    bool activeLow = false; // true: the logical "on"/"pressed" is the low level
    bool pullUp = false;    // input only: enable the SoC's pull-up
    bool pullDown = false;  // input only: enable the pull-down instead
    bool biasOff = false;   // input only: no resistor (an external one is fitted)
    // A line name ("GPIO17" on a Raspberry Pi): looked up on chipPath, then on every
    // /dev/gpiochipN; offset is then ignored.
    std::string name;
    // Input only: the kernel's debounce (libgpiod 2.x; 1.6 has none: the firmware's
    // debouncer does it either way).
    int debounceUs = 0;
};

// "GPIO17" / "17" as a spec's name or offset.
void parseGpioLine(const std::string &text, GpioLineSpec *spec);

// The trigger: both edges with kernel timestamps, read without blocking. For the usual
// wiring (button to ground, pull-up) use activeLow = true and pullUp = true.
class GpiodTrigger final : public TriggerButton {
public:
    explicit GpiodTrigger(const Clock &clock);
    ~GpiodTrigger() override;
    // Errors: NotFound (no chip), Io (line busy or refused).
    Error open(const GpioLineSpec &spec, const char *consumer = "icacam-trigger");
    void close();
    Result<size_t> readEdges(ButtonEdge *out, size_t cap) override;
    // The button's level now (true = pressed).
    Result<bool> pressed() override;
    // Where the line was found ("/dev/gpiochip0:17"), after open().
    const std::string &where() const { return where_; }

private:
    struct Lines; // the libgpiod objects of the compiled API version
    const Clock &clock_;
    std::string where_;
    std::unique_ptr<Lines> lines_;
    bool activeLow_ = false;
};

// The LED ring: one output line, off when opened and when closed.
class GpiodLed final : public LedRing {
public:
    GpiodLed();
    ~GpiodLed() override;
    Error open(const GpioLineSpec &spec, const char *consumer = "icacam-led");
    void close();
    Error set(bool on) override;
    bool isOn() const override { return on_; }

private:
    struct Lines;
    std::unique_ptr<Lines> lines_;
    bool on_ = false;
    bool activeLow_ = false;
};

} // namespace icacam::hal
