#pragma once
// The LED ring around the lens, switched by one GPIO line through a driver transistor.
#include "hal/error.h"

namespace icacam::hal {

class LedRing {
public:
    virtual ~LedRing() = default;
    virtual Error set(bool on) = 0;
    virtual bool isOn() const = 0;
};

} // namespace icacam::hal
