// The lens at the press: `lens POSITION` holds it there, `focus` runs one autofocus sweep on
// the specimen under the ring and holds it where it ended (Camera Module 3: AfMode Auto with
// AfTrigger Start, then Manual at the LensPosition found). Either is saved as lens_position,
// so the focus found once is the focus every measurement after has, across restarts.
#include <cstdio>

#include "firmware/device.h"
#include "firmware/screen.h"

namespace icacam::fw {

namespace {
constexpr int kFocusTimeoutMs = 5000; // a CM3 sweep takes about a second; a webcam's, a few
} // namespace

void Device::sendLens(const char *by, const std::string &tag)
{
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "lens").num("lens_position", cfg_.lensPosition, 5).str("by", by).boolean("saved", true);
    if (!tag.empty()) j.str("tag", tag);
    j.end();
    send(out_);
    char words[48];
    std::snprintf(words, sizeof words, "lens %.3f, saved", cfg_.lensPosition);
    drawProblem(&screen_, by[0] == 'a' ? "focus locked" : "lens set", words);
    showOrLog(screen_);
}

void Device::setLens(const Command &c)
{
    if (!cameraHealth_.ready()) {
        sendError("lens_failed", std::string("camera ") + CameraHealth::stateName(cameraHealth_.state()), c.tag);
        return;
    }
    Config trial = cfg_;
    trial.lensPosition = c.lensPosition;
    char why[64];
    std::snprintf(why, sizeof why, "lens %.5g (%s command)", c.lensPosition, lineOrigin_);
    if (std::string e = applyRecipe(trial, recipes_.active().id, lineOrigin_, why); !e.empty()) {
        sendError("lens_failed", e, c.tag);
        return;
    }
    sendLens("set", c.tag);
}

void Device::focus(const Command &c)
{
    if (!cameraHealth_.ready()) {
        sendError("focus_failed", std::string("camera ") + CameraHealth::stateName(cameraHealth_.state()), c.tag);
        return;
    }
    drawProblem(&screen_, "focusing...", "hold the specimen still");
    showOrLog(screen_);
    // Focused on the picture a measurement sees: the specimen under the ring.
    if (hal::Error e = hal_.led.set(true); !e.ok()) {
        sendError("focus_failed", "LED: " + e.message, c.tag);
        return;
    }
    hal_.clock.sleepMs(cfg_.ledSettleMs);
    const hal::Result<double> r = hal_.camera.focusOnce(kFocusTimeoutMs);
    (void)hal_.led.set(false);
    ledOffMs_ = hal_.clock.monotonicMs();
    if (!r.ok()) {
        sendError("focus_failed", r.error.message, c.tag);
        drawProblem(&screen_, "focus failed", r.error.message);
        showOrLog(screen_);
        return;
    }
    // The lens is where the sweep left it: the recipe's version follows it.
    Config trial = cfg_;
    trial.lensPosition = r.value;
    char why[64];
    std::snprintf(why, sizeof why, "autofocus to %.5g (%s command)", r.value, lineOrigin_);
    if (std::string e = applyRecipe(trial, recipes_.active().id, lineOrigin_, why); !e.empty()) {
        sendError("focus_failed", e, c.tag);
        return;
    }
    sendLens("autofocus", c.tag);
}

} // namespace icacam::fw
