#include "firmware/scale_check.h"

#include <cmath>
#include <cstdio>

#include "vision/plane_calibration.h"
#include "vision/reference_disc.h"

namespace icacam::fw {

ScaleCheckResult checkScale(const vision::LumaView &frame, const ScaleCheckRequest &req, const DeviceCalibration &cal,
                            double mmPerPx, uint8_t *work)
{
    ScaleCheckResult r;
    char msg[240];
    vision::PlaneCalibration plane;
    if (cal.present) {
        if (std::string e = frameSizeIssue(cal, frame.width, frame.height); !e.empty()) {
            r.message = e;
            return r;
        }
        plane = cal.file.plane;
        plane.heightMm = req.thicknessMm; // the disc's edge lies in its top face
    }
    // Where to look: the declared diameter through the scale at the frame's centre.
    const double scale =
        cal.present ? vision::planeScaleAt(plane, 0.5 * (frame.width - 1), 0.5 * (frame.height - 1)) : mmPerPx;
    if (!(scale > 0)) {
        r.message =
            cal.present ? "calibration does not map the frame's centre" : "no scale: set mm_per_px or calibration_file";
        return r;
    }
    const double radiusPx = 0.5 * req.diameterMm / scale;
    const vision::ReferenceDiscFinder finder(work);
    const vision::DiscFit fit = finder.find(frame, radiusPx);
    switch (fit.error) {
    case vision::ErrorCode::None: break;
    case vision::ErrorCode::BadSpecimen:
        std::snprintf(msg, sizeof msg, "a %.3f mm disc would be %.0f px across in a %dx%d frame: not measurable",
                      req.diameterMm, 2 * radiusPx, frame.width, frame.height);
        r.message = msg;
        return r;
    case vision::ErrorCode::OuterEdgeNotFound:
        std::snprintf(msg, sizeof msg, "disc found but its edge only in parts (cut off, covered or out of focus?)");
        r.message = msg;
        return r;
    default:
        std::snprintf(msg, sizeof msg,
                      "no reference disc in view: nothing round %.0f-%.0f px across (a %.3f mm disc at the "
                      "current scale, +-%.0f %%)",
                      2 * radiusPx * (1 - vision::ReferenceDiscFinder::kRadiusSpan),
                      2 * radiusPx * (1 + vision::ReferenceDiscFinder::kRadiusSpan), req.diameterMm,
                      100 * vision::ReferenceDiscFinder::kRadiusSpan);
        r.message = msg;
        return r;
    }
    r.centreX = fit.centreX, r.centreY = fit.centreY;
    if (cal.present) {
        const double rMm = vision::equivalentRadiusMm(fit.edge, fit.centreX, fit.centreY, plane);
        if (!(rMm > 0)) {
            r.message = "the disc's edge lies where the calibration cannot map it";
            return r;
        }
        r.measuredMm = 2 * rMm;
    } else {
        r.measuredMm = 2 * fit.edge.rEqPx * mmPerPx;
    }
    r.measured = true;
    r.ratio = r.measuredMm / req.diameterMm;
    const double offPct = 100 * (r.ratio - 1);
    r.pass = std::fabs(offPct) <= req.tolerancePct;
    if (!r.pass) {
        std::snprintf(msg, sizeof msg,
                      "scale off by %+.2f %%: the disc measures %.4f mm, declared %.4f mm (tolerance %.2f %%); "
                      "check the %s",
                      offPct, r.measuredMm, req.diameterMm, req.tolerancePct,
                      cal.present ? "calibration (camera moved?) and the disc's thickness" : "mm_per_px setting");
        r.message = msg;
    }
    return r;
}

} // namespace icacam::fw
