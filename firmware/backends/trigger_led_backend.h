#pragma once
// The trigger button's and the LED ring's factories: trigger.backend and led.backend "file"
// always (a script or FIFO of presses, a log of the ring's states), "gpiod" (GPIO lines)
// when this build carries hal/gpiod.
#include <memory>
#include <string>

#include "firmware/config.h"
#include "hal/clock.h"
#include "hal/led_ring.h"
#include "hal/trigger_button.h"

namespace icacam::fw {

// "" when this build carries trigger.backend (led.backend), else the config mistake in words.
std::string triggerBackendIssue(const Config &cfg);
std::string ledBackendIssue(const Config &cfg);

// The button, opened: the file backend's trigger.script (none: triggers come over serial
// only) or the gpiod line. Errors: the backend's open() (NotFound, Io), Invalid (a backend
// this build does not carry).
hal::Result<std::unique_ptr<hal::TriggerButton>> makeTrigger(const Config &cfg, hal::Clock &clock);
// The ring, opened and off: the file backend's led.log (none: state only) or the gpiod
// line. Errors as makeTrigger.
hal::Result<std::unique_ptr<hal::LedRing>> makeLed(const Config &cfg, hal::Clock &clock);

} // namespace icacam::fw
