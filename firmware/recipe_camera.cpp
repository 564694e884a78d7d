#include "firmware/recipe_camera.h"

namespace icacam::fw {

hal::Error RecipeCamera::configure(const hal::CameraFormat &fmt)
{
    format_ = fmt;
    configured_ = true;
    if (!inner_) return hal::Error::make(hal::Errc::NotFound, "no camera");
    return inner_->configure(fmt);
}

hal::Error RecipeCamera::capture(const hal::CaptureRequest &req, hal::CapturedFrame *out)
{
    if (!inner_) return hal::Error::make(hal::Errc::NotFound, "no camera");
    return inner_->capture(req, out);
}

hal::Result<hal::CameraControls> RecipeCamera::setControls(const hal::CameraControls &asked)
{
    if (!inner_) return hal::Result<hal::CameraControls>::fail(hal::Errc::NotFound, "no camera");
    hal::Result<hal::CameraControls> r = inner_->setControls(asked);
    if (r.ok()) hal::mergeControls(&held_, asked);
    return r;
}

hal::Error RecipeCamera::setStampDelayUs(int us)
{
    if (!inner_) return hal::Error::make(hal::Errc::NotFound, "no camera");
    hal::Error e = inner_->setStampDelayUs(us);
    if (e.ok()) stampDelayUs_ = us;
    return e;
}

hal::Result<double> RecipeCamera::focusOnce(int timeoutMs)
{
    if (!inner_) return hal::Result<double>::fail(hal::Errc::NotFound, "no camera");
    hal::Result<double> r = inner_->focusOnce(timeoutMs);
    if (r.ok()) held_.lensPosition = r.value;
    return r;
}

hal::Error RecipeCamera::remake(const Config &cfg)
{
    inner_.reset(); // a camera is held by one user at a time: the old one lets it go first
    auto r = make_(cfg);
    if (!r.ok()) return r.error;
    inner_ = std::move(r.value);
    if (configured_)
        if (hal::Error e = inner_->configure(format_); !e.ok()) return e;
    if (stampDelayUs_ >= 0) (void)inner_->setStampDelayUs(stampDelayUs_);
    return {};
}

bool RecipeCamera::needsRemake(const Config &from, const Config &to)
{
    auto unset = [](double a, double b) { return a >= 0 && b < 0; };
    return from.whiteBalanceK != to.whiteBalanceK || unset(from.exposureUs, to.exposureUs) ||
           unset(from.analogueGain, to.analogueGain) || unset(from.redGain, to.redGain) ||
           unset(from.blueGain, to.blueGain) || unset(from.sharpness, to.sharpness) ||
           (from.noiseReduction != to.noiseReduction && cameraControlsOf(to).noiseReduction < 0);
}

hal::Error RecipeCamera::follow(const Config &from, const Config &to)
{
    if (inner_ && !needsRemake(from, to)) {
        const hal::CameraControls change = changedControls(cameraControlsOf(from), cameraControlsOf(to));
        if (!hal::anyControlSet(change)) return {};
        const hal::Result<hal::CameraControls> r = setControls(change);
        // A camera that is away now is made again with them below, so it comes back with them.
        if (r.ok() || r.error.code == hal::Errc::Invalid) return r.error;
    }
    const hal::CameraControls before = held_;
    if (hal::Error e = remake(to); !e.ok()) {
        // Back as it was: made with the old config, then the changes made since.
        if (remake(made_).ok()) {
            const hal::CameraControls since = changedControls(cameraControlsOf(made_), before);
            if (hal::anyControlSet(since)) (void)inner_->setControls(since);
        }
        return e;
    }
    made_ = to;
    held_ = cameraControlsOf(to);
    return {};
}

hal::CameraControls changedControls(const hal::CameraControls &a, const hal::CameraControls &b)
{
    hal::CameraControls c;
    if (b.exposureUs >= 0 && b.exposureUs != a.exposureUs) c.exposureUs = b.exposureUs;
    if (b.analogueGain >= 0 && b.analogueGain != a.analogueGain) c.analogueGain = b.analogueGain;
    // Colour gains go as a pair.
    if (b.redGain >= 0 && b.blueGain >= 0 && (b.redGain != a.redGain || b.blueGain != a.blueGain))
        c.redGain = b.redGain, c.blueGain = b.blueGain;
    if (b.lensPosition >= 0 && b.lensPosition != a.lensPosition) c.lensPosition = b.lensPosition;
    if (b.sharpness >= 0 && b.sharpness != a.sharpness) c.sharpness = b.sharpness;
    if (b.noiseReduction >= 0 && b.noiseReduction != a.noiseReduction) c.noiseReduction = b.noiseReduction;
    return c;
}

} // namespace icacam::fw
