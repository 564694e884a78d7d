#pragma once
// The camera as a recipe sets it: the backends take exposure, gains, white balance,
// sharpening and noise reduction when they are made and configured, and only the lens while
// they run (hal/camera.h). A recipe (or aim mode's live controls) that changes the others
// makes the backend again with them, configures it as before, and holds the lens and the
// stamp delay where they were; between measurements only, on the device's thread.
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
            : make_(std::move(make)), inner_(std::move(first)), made_(madeWith)
    {}

    hal::Error configure(const hal::CameraFormat &fmt) override;
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override;
    std::string describe() const override { return inner_ ? inner_->describe() : "no camera"; }
    hal::Error setLensPosition(double position) override;
    hal::Error setStampDelayUs(int us) override;
    hal::Result<double> focusOnce(int timeoutMs) override;

    // The backend as cfg's start controls make it (firmware/recipe.h: cameraStartControlsDiffer);
    // made again only when they differ from the ones it was made with. On an error it is
    // made again as it was.
    hal::Error setStartControls(const Config &cfg);

private:
    hal::Error remake(const Config &cfg);

    Factory make_;
    std::unique_ptr<hal::Camera> inner_;
    Config made_;
    hal::CameraFormat format_;
    bool configured_ = false;
    double lens_ = -1;
    int stampDelayUs_ = -1;
};

} // namespace icacam::fw
