#include "firmware/debouncer.h"

namespace icacam::fw {

Press Debouncer::onEdge(const hal::ButtonEdge &e)
{
    if (e.pressed) {
        if (!down_) {
            down_ = true;
            longFired_ = false;
            downAt_ = e.timeMs;
        }
        return Press::None;
    }
    if (!down_) return Press::None;
    down_ = false;
    const int64_t held = e.timeMs - downAt_;
    if (held < debounce_ || longFired_) return Press::None;
    return held >= long_ ? Press::Long : Press::Short;
}

Press Debouncer::poll(int64_t nowMs)
{
    if (down_ && !longFired_ && nowMs - downAt_ >= long_) {
        longFired_ = true;
        return Press::Long;
    }
    return Press::None;
}

} // namespace icacam::fw
