// The ring lit in turn (led.segments 3-8): before the whole ring's frame, one frame per
// segment lit alone, from which the contact edge is placed by the surface's tilt
// (vision/contact_tilt.h). The frames are compared pixel by pixel, so all of them share one
// fixed exposure (led.segment_exposure_us, by default the recipe's times the segments: as
// bright as the whole ring's frame), set before the first and the recipe's set back after
// the last. Each is checked lit against a frame taken at that exposure with the ring off (a
// segment's LED, driver or line that fails gives a dark or partly lit frame, and a tilt read
// from it would be wrong), and copied out of the camera's buffer, which the next capture
// recycles. Anything that fails leaves the measurement to the whole ring's frame alone,
// with the reason on the record and on serial: never a tilt from frames that were not all
// lit as asked.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "firmware/device.h"
#include "firmware/frame_luma.h"

namespace icacam::fw {

namespace {

// The frame's luma row by row into dst (width × height bytes).
void copyLuma(const vision::LumaView &v, uint8_t *dst)
{
    for (int y = 0; y < v.height; ++y) {
        const uint8_t *row = v.data + size_t(y) * size_t(v.stride);
        uint8_t *out = dst + size_t(y) * size_t(v.width);
        if (v.pixelStep == 1)
            std::memcpy(out, row, size_t(v.width));
        else
            for (int x = 0; x < v.width; ++x) out[x] = row[size_t(x) * size_t(v.pixelStep)];
    }
}

} // namespace

void Device::sizeSegmentFrames()
{
    segmentFrameBytes_ = 0;
    segmentPixels_.reset();
    if (cfg_.ledSegments < vision::kMinTiltSegments) return;
    segmentFrameBytes_ = size_t(cfg_.cameraMaxWidth) * size_t(cfg_.cameraMaxHeight);
    segmentPixels_ = std::make_unique<uint8_t[]>(segmentFrameBytes_ * size_t(cfg_.ledSegments));
}

bool Device::captureSegments(hal::CapturedFrame *frame, std::string *why)
{
    litInTurn_.count = 0;
    const int n = cfg_.ledSegments;
    // led.segments is read at start only (no setting or recipe changes it): its frames are
    // sized then.
    if (!segmentPixels_) {
        *why = "no segment frames sized at start";
        return false;
    }
    if (hal_.led.segments() != n) {
        *why = "the LED ring switches " + std::to_string(hal_.led.segments()) + " segment(s), led.segments says " +
               std::to_string(n);
        return false;
    }
    const int exposureUs = segmentExposureUs(cfg_);
    hal::CameraControls asked;
    asked.exposureUs = exposureUs;
    if (const auto r = hal_.camera.setControls(asked); !r.error.ok()) {
        *why = "segment exposure " + std::to_string(exposureUs) + " us: " + r.error.message;
        return false;
    }
    const bool ok = litSegments(frame, exposureUs, why);
    if (hal::Error e = hal_.led.set(false); !e.ok() && why->empty()) *why = "LED: " + e.message;
    ledOffMs_ = hal_.clock.monotonicMs();
    // The whole ring's frame is taken at the recipe's exposure (aim's live controls ended
    // before a measurement).
    asked.exposureUs = cfg_.exposureUs;
    if (const auto r = hal_.camera.setControls(asked); !r.error.ok() && why->empty())
        *why = "exposure back to " + std::to_string(cfg_.exposureUs) + " us: " + r.error.message;
    if (!ok || !why->empty()) {
        litInTurn_.count = 0;
        return false;
    }
    litInTurn_.count = n;
    litInTurn_.azimuth0Deg = cfg_.ledSegment0Deg;
    return true;
}

std::string Device::misplacedSegments(const vision::EndFaceGeometry &g) const
{
    char words[160];
    if (g.segmentWay < 0)
        std::snprintf(words, sizeof words,
                      "the segments light the specimen the other way round: list led.gpio_line's lines in reverse "
                      "after segment 0 (segment 0 lights from %.0f deg)",
                      g.segment0SeenDeg);
    else
        std::snprintf(words, sizeof words,
                      "segment 0 lights the specimen from %.0f deg, led.segment0_deg says %g: set segment0_deg %.0f",
                      g.segment0SeenDeg, cfg_.ledSegment0Deg, g.segment0SeenDeg);
    return words;
}

bool Device::litSegments(hal::CapturedFrame *frame, int exposureUs, std::string *why)
{
    const int n = cfg_.ledSegments;
    vision::LumaView luma;
    // The ring is off: the reference at the segments' exposure.
    if (!captureLuma(ledOffMs_ + cfg_.ledSettleMs, frame, &luma, why)) return false;
    if (size_t(luma.width) * size_t(luma.height) > segmentFrameBytes_) {
        *why = "frame larger than camera.max_width x max_height";
        return false;
    }
    LitFrameOptions o = litOptions(luma.width, luma.height);
    // A segment gives its share of the ring's light, over the exposure asked for it.
    const double share = cfg_.exposureUs > 0 ? double(exposureUs) / (double(cfg_.exposureUs) * n) : 1.0;
    o.minRiseLevels = std::max(1, int(std::lround(cfg_.litMinRise * std::min(1.0, share))));
    LitFrameCheck check(o);
    if (!check.setDarkReference(lumaPlane(luma))) {
        *why = "frame too small for the lit check";
        return false;
    }
    const int width = luma.width, height = luma.height;
    for (int k = 0; k < n; ++k) {
        if (hal::Error e = hal_.led.lightSegment(k); !e.ok()) {
            *why = "LED segment " + std::to_string(k) + ": " + e.message;
            return false;
        }
        hal_.clock.sleepMs(cfg_.ledSettleMs);
        const int64_t litMs = hal_.clock.monotonicMs();
        LitCheckResult verdict;
        int attempt = 0;
        for (; attempt < cfg_.litAttempts; ++attempt) {
            if (!captureLuma(litMs, frame, &luma, why)) return false;
            if (luma.width != width || luma.height != height) {
                *why = "segment " + std::to_string(k) + "'s frame is another size";
                return false;
            }
            verdict = check.check(lumaPlane(luma));
            if (verdict.verdict == LitVerdict::Lit) break;
        }
        if (verdict.verdict != LitVerdict::Lit) {
            *why = "LED segment " + std::to_string(k) + " not lit: " + verdict.reason + " (" + std::to_string(attempt) +
                   " frames refused)";
            return false;
        }
        uint8_t *dst = segmentPixels_.get() + size_t(k) * segmentFrameBytes_;
        copyLuma(luma, dst);
        litInTurn_.segment[k] = vision::LumaView{dst, width, height, width, 1};
    }
    return true;
}

} // namespace icacam::fw
