#include "firmware/recipe_camera.h"

#include "firmware/recipe.h"

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

hal::Error RecipeCamera::setLensPosition(double position)
{
    if (!inner_) return hal::Error::make(hal::Errc::NotFound, "no camera");
    hal::Error e = inner_->setLensPosition(position);
    if (e.ok()) lens_ = position;
    return e;
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
    if (r.ok()) lens_ = r.value;
    return r;
}

hal::Error RecipeCamera::remake(const Config &cfg)
{
    inner_.reset(); // a camera is held by one user at a time: the old one lets it go first
    Config with = cfg;
    if (lens_ >= 0) with.lensPosition = lens_;
    auto r = make_(with);
    if (!r.ok()) return r.error;
    inner_ = std::move(r.value);
    if (configured_)
        if (hal::Error e = inner_->configure(format_); !e.ok()) return e;
    if (lens_ >= 0) (void)inner_->setLensPosition(lens_);
    if (stampDelayUs_ >= 0) (void)inner_->setStampDelayUs(stampDelayUs_);
    return {};
}

hal::Error RecipeCamera::setStartControls(const Config &cfg)
{
    if (!cameraStartControlsDiffer(cfg, made_) && inner_) return {};
    if (hal::Error e = remake(cfg); !e.ok()) {
        (void)remake(made_);
        return e;
    }
    made_ = cfg;
    return {};
}

} // namespace icacam::fw
