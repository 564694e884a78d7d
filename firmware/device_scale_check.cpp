// `scalecheck`: a reference disc of known diameter measured under the ring, its diameter
// against the scale in use.
#include "firmware/device.h"

#include <cstdio>

#include "firmware/iso_time.h"
#include "firmware/scale_check.h"
#include "firmware/screen.h"
#include "vision/reference_disc.h"

namespace icacam::fw {

void Device::scaleCheck(const Command &c)
{
    const int64_t t0 = hal_.clock.monotonicMs();
    const long id = lastId_ + 1;
    drawBusy(&screen_, id);
    showOrLog(screen_);
    std::string problem;
    hal::CapturedFrame frame;
    vision::LumaView luma;
    const bool captured = captureFrame(&frame, &luma, &problem);
    ScaleCheckResult r;
    if (captured && problem.empty())
        r = checkScale(luma, {c.diameterMm, c.tolerancePct, c.thicknessMm}, cal_, cfg_.mmPerPx, discWork_.get());

    state_ = State::Report;
    lastId_ = id;
    std::string storageProblem;
    const std::string imageName = captured && problem.empty() ? journalFrame(id, luma, &storageProblem) : "";
    out_.clear();
    reading::JsonBuilder j(&out_);
    char when[96];
    isoTime(hal_.clock.wallMs(), when);
    const char *status = !problem.empty() || !r.measured ? "error" : r.pass ? "pass" : "fail";
    j.str("type", "scalecheck").integer("id", id).str("time", when).str("status", status);
    j.num("diameter_mm", c.diameterMm, 4);
    if (r.measured) j.num("measured_mm", r.measuredMm, 7).num("ratio", r.ratio, 7);
    j.num("tolerance_pct", c.tolerancePct, 3).num("thickness_mm", c.thicknessMm, 3);
    j.str("message", !problem.empty() ? problem : r.message);
    j.str("calibration", cal_.present ? cal_.name : "").num("mm_per_px", cfg_.mmPerPx, 8);
    j.str("image", imageName).str("source", captured ? std::string_view(frame.source) : std::string_view());
    j.str("trigger", "serial").integer("ms", long(hal_.clock.monotonicMs() - t0));
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    if (hal::Error e = journal_.append(out_); !e.ok())
        storageProblem = e.code == hal::Errc::Full ? "storage full: result not journaled" : "journal: " + e.message;
    else
        journaled(id);
    send(out_);
    if (!problem.empty()) sendError("measurement_failed", problem, c.tag);
    if (!storageProblem.empty()) sendError("storage", storageProblem, c.tag);

    char title[48], words[64];
    std::snprintf(title, sizeof title, "#%ld scale %s", id, status);
    if (r.measured) std::snprintf(words, sizeof words, "ratio %.4f (tol %.2f %%)", r.ratio, c.tolerancePct);
    drawProblem(&screen_, title,
                r.measured ? std::string_view(words) : std::string_view(problem.empty() ? r.message : problem));
    showOrLog(screen_);
    state_ = State::Idle;
}

} // namespace icacam::fw
