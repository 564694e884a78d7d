#pragma once
// The quick scale check on the device: a reference disc of known diameter lies on the
// fixture; its diameter measured through the calibration (or mm_per_px without one) is
// compared with the declared one. A ratio outside the tolerance means the scale the
// measurements use is wrong (camera moved, wrong calibration or mm_per_px).
#include <cstdint>
#include <string>

#include "firmware/device_calibration.h"
#include "vision/luma_view.h"

namespace icacam::fw {

struct ScaleCheckRequest {
    double diameterMm = 0;
    double tolerancePct = 0.5; // |measured / declared − 1| allowed, percent
    double thicknessMm = 0;    // the disc's top face above the fixture (its edge is measured there)
};

struct ScaleCheckResult {
    bool measured = false; // false: no disc (message says why)
    bool pass = false;
    double measuredMm = 0, ratio = 0;
    double centreX = 0, centreY = 0; // disc centre, pixels
    std::string message;
};

// `work` must hold vision::ReferenceDiscFinder::kWorkBytes.
ScaleCheckResult checkScale(const vision::LumaView &frame, const ScaleCheckRequest &req, const DeviceCalibration &cal,
                            double mmPerPx, uint8_t *work);

} // namespace icacam::fw
