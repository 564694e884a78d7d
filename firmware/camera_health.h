#pragma once
// Whether the camera is there and answering, in words for the display, `hello` and
// `status`. A camera missing at start does not stop the device: it is looked for again
// every retry interval (and before each trigger) and measuring starts once it answers; a
// camera that stops answering (a loose CSI ribbon: captures time out) or goes away (USB
// unplug) is configured afresh, which re-acquires it.
#include <cstdint>
#include <string>

#include "hal/camera.h"
#include "hal/clock.h"

namespace icacam::fw {

class CameraHealth {
public:
    enum class State { Unknown, Ok, Missing, Lost };
    static constexpr int kTimeoutsLost = 2;

    CameraHealth(hal::Camera &camera, hal::Clock &clock, hal::CameraFormat format, int retryMs)
            : camera_(camera), clock_(clock), format_(format), retryMs_(retryMs)
    {}

    // Configures the camera now; false (and the words in problem()) when it is not there.
    bool open();
    // From the main loop: tries again once the retry interval has passed. True when the
    // camera has just come (back).
    bool poll();
    // Before a capture: ready, or one more attempt now.
    bool ready();
    // After a capture: a timeout or a closed camera marks it lost (re-acquired by the next
    // attempt); a frame records its latency.
    void onCapture(const hal::Error &e, const hal::CapturedFrame *frame);

    State state() const { return state_; }
    bool ok() const { return state_ == State::Ok; }
    const std::string &problem() const { return problem_; }
    static const char *stateName(State s);
    std::string describe() const { return camera_.describe(); }
    int64_t lastLatencyUs() const { return lastLatencyUs_; }
    // The controls the camera reported for the last frame.
    const hal::CameraControls &lastControls() const { return lastControls_; }

private:
    bool attempt();
    hal::Camera &camera_;
    hal::Clock &clock_;
    hal::CameraFormat format_;
    int retryMs_;
    State state_ = State::Unknown;
    std::string problem_;
    int64_t nextTryMs_ = 0;
    int64_t lastLatencyUs_ = -1;
    hal::CameraControls lastControls_;
    int timeouts_ = 0;
};

} // namespace icacam::fw
