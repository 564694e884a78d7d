#pragma once
// The trigger button and the LED ring on GPIO lines through libgpiod's character-device API.
// One interface for libgpiod 1.6 (Debian bookworm) and 2.x (trixie): the version is chosen
// at compile time in gpiod_lines.cpp; nothing here depends on it. libgpiod is a C API: it
// reports errors through errno, which is turned into hal::Error values.
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

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

// The LED ring: one output line, or one line per segment where the ring is wired in sectors;
// every line off when opened and when closed.
class GpiodLed final : public LedRing {
public:
    GpiodLed();
    ~GpiodLed() override;
    // A ring of one line: segments() is 1.
    Error open(const GpioLineSpec &spec, const char *consumer = "icacam-led");
    // A ring of segments, one line each in azimuth order (segment 0 first). Each line is its
    // own request, so the lines may sit on different chips. Errors: Invalid (no line),
    // NotFound, Io (naming the line); on an error no line stays requested.
    Error open(const std::vector<GpioLineSpec> &lines, const char *consumer = "icacam-led");
    void close();
    // Every line. Errors: Invalid (not open), Io (naming the first line that failed; the
    // others are still switched).
    Error set(bool on) override;
    bool isOn() const override;
    int segments() const override { return lines_.empty() ? 1 : int(lines_.size()); }
    // The other lines off first, then line k on: two segments are never lit together.
    // Errors: Invalid (not open, one line, k out of range), Io (naming the line that could
    // not be switched off; every other line is then off, k too).
    Error lightSegment(int k) override;

private:
    struct Line; // one line's libgpiod objects, its level and where it was found
    static Error drive(Line &line, bool on);

    std::vector<std::unique_ptr<Line>> lines_; // segment 0 first
};

} // namespace icacam::hal
