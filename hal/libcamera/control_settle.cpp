#include "hal/libcamera/control_settle.h"

#include <cmath>

namespace icacam::hal {

namespace {

bool nearerAsked(double before, double asked, double reported)
{
    if (asked < 0 || before < 0 || reported < 0) return true;
    return std::fabs(reported - asked) <= std::fabs(reported - before);
}

} // namespace

bool showsChange(const ControlChange &c, const CameraControls &r)
{
    return nearerAsked(c.before.exposureUs, c.asked.exposureUs, r.exposureUs) &&
           nearerAsked(c.before.analogueGain, c.asked.analogueGain, r.analogueGain) &&
           nearerAsked(c.before.lensPosition, c.asked.lensPosition, r.lensPosition);
}

} // namespace icacam::hal
