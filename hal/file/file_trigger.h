#pragma once
// Trigger presses from a script file or a FIFO, as timestamped raw edges.
//
// One command a line ('#' starts a comment):
//   press [HOLD_MS]   button down now (or at the script cursor), up HOLD_MS later (default 100)
//   down | up         one raw edge at the cursor
//   wait MS           moves the cursor MS later (scripts: presses spaced in time)
//   T down | T up     an edge at T ms after the backend started (absolute script time)
// The cursor never lies before the arrival time of the line, so lines written into a FIFO
// act "now". Edges are delivered once the clock reaches them, in time order, like a GPIO
// line's edge events; bounce is written as explicit short down/up pairs.
#include <cstdint>
#include <deque>
#include <string>

#include "hal/clock.h"
#include "hal/trigger_button.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class FileTrigger final : public TriggerButton {
public:
    explicit FileTrigger(Clock &clock) : clock_(clock) {}
    // Opens a script file or a FIFO (a FIFO is opened read-write so it never reports EOF).
    Error open(const std::string &path);
    // Feeds script text directly (tests).
    void feed(std::string_view text);

    Result<size_t> readEdges(ButtonEdge *out, size_t cap) override;
    size_t pending() const { return queue_.size(); }
    const std::string &lastError() const { return lastError_; }

private:
    void parseLine(std::string_view line);
    void pushEdge(int64_t t, bool pressed);

    Clock &clock_;
    UniqueFd fd_;
    int64_t start_ = 0;
    int64_t cursor_ = 0;
    int64_t lastQueued_ = 0;
    std::string partial_;
    std::deque<ButtonEdge> queue_;
    std::string lastError_;
};

} // namespace icacam::hal
