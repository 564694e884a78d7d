// `measure-latency`: how late a webcam's buffer timestamps are, measured from the frames
// themselves. uvcvideo stamps a buffer when the frame's first USB packet arrives, after the
// exposure by the camera's readout, processing and (MJPEG) encoding time, which no driver
// reports; the freshness rule needs a bound of it (hal/fresh_frame.h), and a bound too small
// lets a frame exposed before the light in.
//
// One step: with the ring off, a reference frame; at T the ring goes on; frames follow until
// one is lit top to bottom (firmware/lit_frame.h). The check passes a frame whose first rows
// got part of their exposure lit, so all that frame proves is that its first row's exposure
// ended after T: its stamp S, less T, is at least the camera's delay (more by the time from T
// to that exposure's end, under a frame interval and an exposure). Steps land at different
// phases of the frame clock: the smallest of them is the tightest bound that is still safe,
// and is what is saved.
#include <algorithm>
#include <climits>

#include "firmware/device.h"
#include "firmware/screen.h"

namespace icacam::fw {

namespace {
constexpr int kSteps = 5;          // steps at different phases
constexpr int kFramesPerStep = 12; // the ring must light a whole frame within these
constexpr int kDarkMs = 150;       // the ring off before each step: the queue empties of lit frames
} // namespace

void Device::applyStampDelay()
{
    if (cfg_.stampDelayUs < 0 || !cameraHealth_.ok()) return;
    (void)hal_.camera.setStampDelayUs(cfg_.stampDelayUs); // only cameras with a stamp delay take it
}

int64_t Device::latencyStep(std::string *problem)
{
    (void)hal_.led.set(false);
    hal_.clock.sleepMs(kDarkMs);
    ledOffMs_ = hal_.clock.monotonicMs();
    hal::CapturedFrame frame;
    if (!takeDarkReference(&frame, problem)) return -1;
    // Every frame from the step on, in order: asked from well before it, so the freshness
    // rule (which this measures) refuses none.
    const int64_t askedFromMs = hal_.clock.monotonicMs() - 1000;
    if (hal::Error e = hal_.led.set(true); !e.ok()) {
        *problem = "LED: " + e.message;
        return -1;
    }
    const int64_t onMs = hal_.clock.monotonicMs();
    int64_t bound = -1;
    for (int k = 0; k < kFramesPerStep && bound < 0; ++k) {
        vision::LumaView luma;
        if (!captureLuma(askedFromMs, &frame, &luma, problem)) break;
        if (frame.latencyUs < 0) {
            *problem = "the camera gives no exposure start to measure from";
            break;
        }
        if (litCheck_.check({luma.data, luma.width, luma.height, luma.stride, luma.pixelStep}).verdict !=
            LitVerdict::Lit)
            continue;
        // The exposure start as the backend computed it, plus the exposure and the delay it
        // assumed, is the driver's stamp.
        const int64_t stampUs = askedFromMs * 1000 + frame.latencyUs + frame.exposureUs + frame.stampDelayUs;
        bound = std::max<int64_t>(0, stampUs - onMs * 1000);
    }
    (void)hal_.led.set(false);
    ledOffMs_ = hal_.clock.monotonicMs();
    if (bound < 0 && problem->empty())
        *problem =
            "no frame lit top to bottom within " + std::to_string(kFramesPerStep) + " frames of the ring going on";
    return bound;
}

void Device::measureLatency(const Command &c)
{
    if (!cameraHealth_.ready()) {
        sendError("latency_failed", std::string("camera ") + CameraHealth::stateName(cameraHealth_.state()), c.tag);
        return;
    }
    drawProblem(&screen_, "measuring latency", "the ring flashes; keep the specimen still");
    showOrLog(screen_);
    int64_t best = INT64_MAX, worst = -1;
    int steps = 0;
    std::string problem;
    for (int i = 0; i < kSteps; ++i) {
        // Steps a prime number of milliseconds apart, so they fall at different phases.
        hal_.clock.sleepMs(7 * i);
        const int64_t b = latencyStep(&problem);
        if (b < 0) break;
        best = std::min(best, b);
        worst = std::max(worst, b);
        ++steps;
    }
    if (steps < kSteps) {
        sendError("latency_failed", problem, c.tag);
        drawProblem(&screen_, "latency failed", problem);
        showOrLog(screen_);
        return;
    }
    const int old = cfg_.stampDelayUs;
    if (hal::Error e = hal_.camera.setStampDelayUs(int(best)); !e.ok()) {
        sendError("latency_failed", e.message, c.tag);
        return;
    }
    cfg_.stampDelayUs = int(best);
    persistSettings();
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "latency").integer("stamp_delay_us", best).integer("largest_us", worst).integer("steps", steps);
    j.integer("was_us", old).boolean("saved", true);
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    send(out_);
    drawProblem(&screen_, "latency measured", "stamp delay " + std::to_string(best) + " us, saved");
    showOrLog(screen_);
}

} // namespace icacam::fw
