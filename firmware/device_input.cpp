// Where commands come from: the button (a press measures, a long press aims), serial lines
// and the web's inbox, each line parsed into a command.
#include "firmware/device.h"

#include "firmware/screen.h"

namespace icacam::fw {

void Device::pollButton()
{
    // Held here since an earlier batch: the level is read before the queue is drained, so a
    // release that happened is either in the queue or was lost (libgpiod 1.6 drops the newest
    // event when the queue is full, e.g. while a measurement ran).
    hal::Result<bool> level = hal::Result<bool>::fail(hal::Errc::Invalid, "");
    if (debouncer_.isDown()) level = hal_.trigger.pressed();
    hal::ButtonEdge edges[16];
    hal::Result<size_t> r = hal_.trigger.readEdges(edges, 16);
    if (!r.ok()) {
        // A part stand-in reports its own failures (device_parts.cpp).
        if (!hal_.parts && lastProblem_ != r.error.message) {
            lastProblem_ = r.error.message;
            sendError("trigger_failed", r.error.message, "");
        }
        return;
    }
    for (size_t i = 0; i < r.value; ++i) {
        const Press p = debouncer_.onEdge(edges[i]);
        if (p != Press::Short) continue;
        if (aimUntilMs_ >= 0) { // a press ends aiming; it does not measure
            stopAim("button");
            continue;
        }
        measure("button", "");
    }
    if (level.ok() && !level.value && r.value == 0) debouncer_.resync(false);
    if (debouncer_.poll(hal_.clock.monotonicMs()) == Press::Long) {
        // Long press: aim mode; held again while aiming: the settings page.
        if (aimUntilMs_ < 0) {
            startAim(60, "");
        } else {
            stopAim("button");
            drawSettings(&screen_, cfg_);
            showOrLog(screen_);
        }
    }
}

void Device::pollSerial()
{
    char buf[4096];
    for (int chunk = 0; chunk < 64; ++chunk) { // at most 256 KiB a tick, so buttons stay responsive
        hal::Result<size_t> r = hal_.serial.read(buf, sizeof buf);
        if (!r.ok() || r.value == 0) return;
        std::string_view data(buf, r.value);
        for (;;) {
            const LineAssembler::Event ev = lines_.push(&data);
            if (ev == LineAssembler::Event::None) break;
            if (ev == LineAssembler::Event::Overflow)
                sendError("line_too_long", "line longer than 1024 bytes: ignored up to its end", "");
            else
                handleLine(lines_.line());
        }
    }
}

void Device::pollInbox()
{
    if (!inbox_) return;
    if (!inboxLine_) inboxLine_ = std::make_unique<char[]>(net::CommandInbox::kMaxLine);
    for (int i = 0; i < 4; ++i) { // a few a tick, so buttons stay responsive
        const size_t n = inbox_->pop(inboxLine_.get());
        if (n == 0) return;
        lineOrigin_ = "web";
        handleLine(std::string_view(inboxLine_.get(), n));
        lineOrigin_ = "serial";
    }
}

void Device::handleLine(std::string_view line)
{
    if (line.empty() || line == "\r") return;
    const CommandParse p = parseCommand(line);
    if (!p.ok) {
        sendError(p.code, p.message, "");
        return;
    }
    handleCommand(p.cmd);
}

} // namespace icacam::fw
