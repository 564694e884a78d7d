// Capturing a frame for a measurement: the frame is lit by the ring from its first row to its
// last, shown photometrically, not only by timestamps (firmware/lit_frame.h). An LED, driver
// or led.active fault gives a fresh dark frame, and a camera that buffers or blends frames
// can hand out one lit in part; both are refused and captured again, then reported as
// "LED ring not lit".
#include <algorithm>

#include "firmware/device.h"
#include "firmware/frame_luma.h"

namespace icacam::fw {

LitFrameOptions Device::litOptions(int width, int height) const
{
    LitFrameOptions o;
    o.minRiseLevels = cfg_.litMinRise;
    // The specimen's region: a square as wide as the original end face (at least d0 across
    // after upsetting: it and the inner part of the immigrated ring, PRODUCT.md §1), centred
    // as aim mode asks; its rows span the specimen's middle, top to bottom, which is where
    // a frame that straddled the LED's edge shows. Without a scale, or larger than the frame:
    // the middle half, or the frame's full height.
    //
    // Judged against the LED-off frame alone, band by band (16 bands): a band the ring adds
    // less than led.min_rise to is not lit; the first and last bands' thin strips against
    // their band (lit_frame.h), so a dark sliver of a few rows at the top or bottom is seen.
    // The top-to-bottom ratio test is off: a real end face's reflectance differs top to
    // bottom more than that test allows (the devset's photographs). What it cannot see: a
    // sliver thinner than a strip (1/128 of the region's height, at least a row), a sliver
    // the room light does not reach, and rows above or below the region.
    o.bands = 16;
    o.partialRatio = 0;
    const double facePx = cfg_.mmPerPx > 0 ? cfg_.d0Mm / cfg_.mmPerPx : 0;
    int side = facePx > 0 ? int(facePx) : std::min(width, height) / 2;
    side = std::clamp(side, std::min(o.bands * 4, std::min(width, height)), std::min(width, height));
    o.region = {(width - side) / 2, (height - side) / 2, side, side};
    return o;
}

bool Device::captureLuma(int64_t notBeforeMs, hal::CapturedFrame *frame, vision::LumaView *luma, std::string *problem)
{
    const hal::Error e = hal_.camera.capture({notBeforeMs, cfg_.captureTimeoutMs}, frame);
    cameraHealth_.onCapture(e, e.ok() ? frame : nullptr);
    if (!e.ok()) {
        *problem = std::string("camera ") + hal::errcName(e.code) + ": " + e.message;
        return false;
    }
    if (const vision::ErrorCode le = frameLuma(frame->view, lumaScratch_.get(), lumaScratchBytes_, luma);
        le != vision::ErrorCode::None) {
        *problem = std::string("frame: ") + vision::errorMessage(le);
        return false;
    }
    return true;
}

bool Device::takeDarkReference(hal::CapturedFrame *frame, std::string *problem)
{
    // Any frame exposed after the ring went dark: one is usually waiting in the camera's queue.
    vision::LumaView dark;
    if (!captureLuma(ledOffMs_ + cfg_.ledSettleMs, frame, &dark, problem)) return false;
    litCheck_ = LitFrameCheck(litOptions(dark.width, dark.height));
    if (!litCheck_.setDarkReference(lumaPlane(dark))) {
        *problem = "frame too small for the lit check";
        return false;
    }
    return true;
}

bool Device::captureFrame(hal::CapturedFrame *frame, vision::LumaView *luma, std::string *problem, bool withSegments)
{
    triggerMs_ = hal_.clock.monotonicMs();
    lastLit_ = {};
    unlitFrames_ = 0;
    litInTurn_.count = 0;
    segmentProblem_.clear();
    if (!cameraHealth_.ready()) {
        *problem =
            std::string("camera ") + CameraHealth::stateName(cameraHealth_.state()) + ": " + cameraHealth_.problem();
        return false;
    }
    state_ = State::Capture;
    if (!takeDarkReference(frame, problem)) return false;
    // The segments before the whole ring: the frame measured is the last one captured, so
    // the camera's buffer it lies in stays valid until it is measured and journaled.
    if (withSegments && cfg_.ledSegments >= vision::kMinTiltSegments) {
        state_ = State::LedOn;
        (void)captureSegments(frame, &segmentProblem_);
        state_ = State::Capture;
    }
    state_ = State::LedOn;
    if (hal::Error e = hal_.led.set(true); !e.ok()) *problem = "LED: " + e.message;
    hal_.clock.sleepMs(cfg_.ledSettleMs);
    // From here on the ring is lit and steady: only a frame exposed after now is measured,
    // and only one the light reached top to bottom.
    const int64_t litMs = hal_.clock.monotonicMs();
    state_ = State::Capture;
    bool captured = false;
    for (int attempt = 0; problem->empty() && attempt < cfg_.litAttempts; ++attempt) {
        if (!captureLuma(litMs, frame, luma, problem)) break;
        captured = true;
        lastLit_ = litCheck_.check(lumaPlane(*luma));
        if (lastLit_.verdict == LitVerdict::Lit) break;
        ++unlitFrames_;
    }
    if (captured && problem->empty() && lastLit_.verdict != LitVerdict::Lit)
        *problem = std::string("LED ring not lit: ") + lastLit_.reason + " (" + std::to_string(unlitFrames_) +
                   " frames refused)";
    state_ = State::LedOff;
    if (hal::Error e = hal_.led.set(false); !e.ok() && problem->empty()) *problem = "LED: " + e.message;
    ledOffMs_ = hal_.clock.monotonicMs();
    state_ = State::Measure;
    return captured;
}

} // namespace icacam::fw
