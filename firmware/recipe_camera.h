#pragma once
// The camera as a recipe sets it. Exposure, gains, lens, sharpening and noise reduction change
// on the running backend (hal::Camera::setControls), between measurements, on the device's
// thread. Only what a backend takes when it opens makes it again: a white balance colour
// temperature (camera.white_balance_k, which a V4L2 camera is opened with), or a control
// going back to unset (the camera's own automatic or default value, which no running camera
// is asked for). Made again, the backend is configured as before and keeps the stamp delay.
//
// A file camera made again starts its list of images over, as a real sensor restarted
// shows the specimen again.
#include <functional>
#include <memory>

#include "firmware/config.h"
#include "hal/camera.h"

namespace icacam::fw {

class RecipeCamera final : public hal::Camera {
public:
    // make: the backend for a config (firmware/backends/camera_backend.h's makeCamera).
    using Factory = std::function<hal::Result<std::unique_ptr<hal::Camera>>(const Config &)>;

    RecipeCamera(Factory make, std::unique_ptr<hal::Camera> first, const Config &madeWith)
            : make_(std::move(make)), inner_(std::move(first)), made_(madeWith), held_(cameraControlsOf(madeWith))
    {}

    hal::Error configure(const hal::CameraFormat &fmt) override;
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override;
    std::string describe() const override { return inner_ ? inner_->describe() : "no camera"; }
    hal::Result<hal::CameraControls> setControls(const hal::CameraControls &asked) override;
    hal::Error setStampDelayUs(int us) override;
    hal::Result<double> focusOnce(int timeoutMs) override;

    // The camera from the controls of `from` to those of `to` (whole configs): the changed
    // ones set on the running backend, or the backend made again with `to` where one needs
    // it (above). On an error the camera is as it was.
    hal::Error follow(const Config &from, const Config &to);
    // Whether going from `from` to `to` makes the backend again.
    static bool needsRemake(const Config &from, const Config &to);

private:
    hal::Error remake(const Config &cfg);

    Factory make_;
    std::unique_ptr<hal::Camera> inner_;
    Config made_;              // the config the backend was made with
    hal::CameraControls held_; // the controls in effect: made_'s and every change since
    hal::CameraFormat format_;
    bool configured_ = false;
    int stampDelayUs_ = -1;
};

// The controls set in `to` that differ from `from` (the others unset); a control that `to`
// leaves unset is not among them, and colour gains come as a pair.
hal::CameraControls changedControls(const hal::CameraControls &from, const hal::CameraControls &to);

} // namespace icacam::fw
