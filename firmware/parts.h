#pragma once
// The device's parts besides the camera: the display, the serial line, the trigger button and
// the LED ring. A part that is not there (I2C or the header UART not enabled on a fresh
// Raspberry Pi OS, a cable off, a group missing) does not stop the device: its stand-in does
// nothing in its place, the part is opened again every retry interval, and every change is
// reported on whatever output is left (fw::Device: serial, display and journal; the log sink:
// stderr, which systemd keeps for journalctl). Whatever else is there goes on measuring.
//
// A part that opened but then fails a call (a display that stops acknowledging) is Failing
// until a call succeeds again; its backend recovers by itself (the SSD1306 starts its next
// picture with its init sequence, the UART reopens after a hang-up).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "hal/clock.h"
#include "hal/display.h"
#include "hal/led_ring.h"
#include "hal/serial_port.h"
#include "hal/trigger_button.h"

namespace icacam::fw {

class Part {
public:
    enum class State { Ok, Missing, Failing };
    static const char *stateName(State s); // "ok", "missing", "failing"

    explicit Part(const char *name) : name_(name) {}
    virtual ~Part() = default;
    Part(const Part &) = delete;
    Part &operator=(const Part &) = delete;

    const char *name() const { return name_; }
    State state() const { return state_; }
    bool ok() const { return state_ == State::Ok; }
    const std::string &problem() const { return problem_; }
    // The last open's or call's error code (Invalid on open: a mistake in the config, which
    // no retry mends).
    hal::Errc problemCode() const { return code_; }
    // Opens the part (again); Ok or Missing with the reason.
    hal::Error open();
    // True once after each change of state, for the one who reports it.
    bool takeChange();

protected:
    virtual hal::Error openBackend() = 0;
    // After a call on the opened part: a failure makes it Failing, a success Ok again.
    void note(const hal::Error &e);

private:
    const char *name_;
    State state_ = State::Missing;
    std::string problem_ = "not opened yet";
    hal::Errc code_ = hal::Errc::NotFound;
    bool changed_ = false;
};

// One seam's stand-in: the opened backend from its factory, or nothing while it is missing.
template <typename Interface> class PartOf : public Part {
public:
    using Factory = std::function<hal::Result<std::unique_ptr<Interface>>()>;
    PartOf(const char *name, Factory factory) : Part(name), factory_(std::move(factory)) {}
    Interface *backend() const { return backend_.get(); }

protected:
    hal::Error openBackend() override
    {
        backend_.reset();
        hal::Result<std::unique_ptr<Interface>> r = factory_();
        if (!r.ok()) return r.error;
        backend_ = std::move(r.value);
        return {};
    }
    std::unique_ptr<Interface> backend_;

private:
    Factory factory_;
};

// Missing: shows nothing (the picture is lost; the next one after it comes is shown).
class DisplayPart final : public PartOf<hal::Display>, public hal::Display {
public:
    explicit DisplayPart(Factory f) : PartOf("display", std::move(f)) {}
    hal::Error show(const hal::MonoBitmap &picture) override;
};

// Missing: nothing arrives, what is written is lost (Closed).
class SerialPart final : public PartOf<hal::SerialPort>, public hal::SerialPort {
public:
    explicit SerialPart(Factory f) : PartOf("serial", std::move(f)) {}
    hal::Result<size_t> read(char *buf, size_t cap) override;
    hal::Error write(std::string_view data) override;
};

// Missing: no presses (triggers still come over serial).
class TriggerPart final : public PartOf<hal::TriggerButton>, public hal::TriggerButton {
public:
    explicit TriggerPart(Factory f) : PartOf("trigger", std::move(f)) {}
    hal::Result<size_t> readEdges(hal::ButtonEdge *out, size_t cap) override;
    hal::Result<bool> pressed() override;
};

// Missing: set() fails (NotFound), so a capture that needs light says why it has none.
class LedPart final : public PartOf<hal::LedRing>, public hal::LedRing {
public:
    explicit LedPart(Factory f) : PartOf("LED", std::move(f)) {}
    hal::Error set(bool on) override;
    bool isOn() const override { return backend_ && backend_->isOn(); }
    int segments() const override { return backend_ ? backend_->segments() : 1; }
    hal::Error lightSegment(int k) override;
};

// The four parts, opened and retried together.
class Parts {
public:
    static constexpr int kCount = 4;
    using LogSink = std::function<void(std::string_view)>;

    Parts(DisplayPart &display, SerialPart &serial, TriggerPart &trigger, LedPart &led, hal::Clock &clock, int retryMs);
    // Opens every part now; a part that does not open is Missing, retried by poll().
    void openAll();
    // From the main loop: opens the missing parts again once the retry interval has passed.
    void poll();
    int retryMs() const { return retryMs_; }
    Part &at(int i) const { return *parts_[i]; }
    // "" when all are there, else the missing or failing parts' names: "serial LED".
    std::string missingNames() const;

    // Where the changes are written besides the device's own outputs (icacam-fw: stderr).
    void setLog(LogSink sink) { log_ = std::move(sink); }
    void log(std::string_view line) const
    {
        if (log_) log_(line);
    }

private:
    Part *parts_[kCount];
    hal::Clock &clock_;
    int retryMs_;
    int64_t nextTryMs_ = 0;
    LogSink log_;
};

} // namespace icacam::fw
