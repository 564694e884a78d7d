#include "firmware/camera_health.h"

namespace icacam::fw {

const char *CameraHealth::stateName(State s)
{
    switch (s) {
    case State::Unknown: return "unknown";
    case State::Ok: return "ok";
    case State::Missing: return "missing";
    case State::Lost: return "lost";
    }
    return "unknown";
}

bool CameraHealth::attempt()
{
    nextTryMs_ = clock_.monotonicMs() + retryMs_;
    if (hal::Error e = camera_.configure(format_); !e.ok()) {
        problem_ = e.message;
        if (state_ != State::Lost) state_ = State::Missing;
        return false;
    }
    state_ = State::Ok;
    problem_.clear();
    return true;
}

bool CameraHealth::open()
{
    return attempt();
}

bool CameraHealth::poll()
{
    if (state_ == State::Ok || clock_.monotonicMs() < nextTryMs_) return false;
    return attempt();
}

bool CameraHealth::ready()
{
    return state_ == State::Ok || attempt();
}

void CameraHealth::onCapture(const hal::Error &e, const hal::CapturedFrame *frame)
{
    if (e.ok()) {
        timeouts_ = 0;
        if (frame) {
            lastLatencyUs_ = frame->latencyUs;
            lastControls_ = frame->controls;
        }
        return;
    }
    // A camera that went away, or delivered nothing twice running (one timeout can be a
    // frame lost on the bus), is configured afresh; a refused frame (format, size) is a
    // camera that answers and stays as it is.
    const bool silent = e.code == hal::Errc::Timeout && ++timeouts_ >= kTimeoutsLost;
    if (silent || e.code == hal::Errc::Closed || e.code == hal::Errc::Io || e.code == hal::Errc::NotFound ||
        e.code == hal::Errc::Invalid) {
        timeouts_ = 0;
        state_ = State::Lost;
        problem_ = e.message;
        nextTryMs_ = clock_.monotonicMs(); // the next poll tries at once
    }
}

} // namespace icacam::fw
