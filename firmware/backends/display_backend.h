#pragma once
// The display's factory: display.backend "file" (PNG pictures in a folder) and "none"
// always, "ssd1306" (an SSD1306 or SH1106 OLED on I2C) when this build carries hal/ssd1306.
#include <memory>
#include <string>

#include "firmware/config.h"
#include "hal/display.h"

namespace icacam::fw {

// "" when this build carries display.backend, else the config mistake in words.
std::string displayBackendIssue(const Config &cfg);

// The display, opened ("none": one that shows nothing). An OLED that does not answer its
// start-up sequence is not an error: it is reported on stderr, and by each show() after.
// Errors: the backend's open() (NotFound, Io), Invalid (a backend this build does not carry).
hal::Result<std::unique_ptr<hal::Display>> makeDisplay(const Config &cfg);

} // namespace icacam::fw
