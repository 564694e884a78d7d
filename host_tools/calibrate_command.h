#pragma once
// `icacam calibrate`: the options of a camera calibration (host_tools/camera_calibrator.h:
// intrinsics, distortion and the fixture plane's pose from photos of a chessboard or circle
// grid), written to a calibration file.
#include <string>
#include <vector>

namespace icacam::host {

// Returns the process exit code; throws std::runtime_error with a message for the user.
int calibrateCommand(const std::vector<std::string> &args);

} // namespace icacam::host
