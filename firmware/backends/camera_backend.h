#pragma once
// The camera seam's factory: camera.backend "file" always, "v4l2" (a UVC camera) and
// "libcamera" (a CSI camera) when this build carries hal/v4l2 and hal/libcamera.
#include <memory>
#include <string>

#include "firmware/config.h"
#include "hal/camera.h"
#include "hal/clock.h"

namespace icacam::fw {

// "" when this build carries camera.backend, else the config mistake in words.
std::string cameraBackendIssue(const Config &cfg);

// The camera camera.backend names, not configured yet: fw::Device configures it and, while
// it is missing, looks for it again, so a camera that is not there is no error here.
// Errors: Invalid (a backend this build does not carry).
hal::Result<std::unique_ptr<hal::Camera>> makeCamera(const Config &cfg, hal::Clock &clock);

} // namespace icacam::fw
