#pragma once
// The device's camera calibration (docs/calibration.md): the file named by
// calibration.file, read and checked at start-up (icacam-fw --check reports it like any
// config mistake) and again when the key is set over serial. The end face's plane height
// is per specimen (specimen.h_final_mm, else h0_mm / 2) and set for each measurement.
#include <string>

#include "calibration/calibration_file.h"
#include "firmware/config.h"

namespace icacam::fw {

struct DeviceCalibration {
    bool present = false;
    calibration::CalibrationFile file;
    std::string path; // as opened (relative names resolved against Config::baseDir)
    std::string name; // the file's name, journaled with each result
};

// Reads and checks cfg.calibrationFile: "" (and present = false) when none is named, else
// the file's problem in words (cannot read, wrong format, not physical, image size beyond
// the camera's largest frame).
std::string loadDeviceCalibration(const Config &cfg, DeviceCalibration *out);

// A frame of another size than the calibration's cannot be mapped: the message, or "".
std::string frameSizeIssue(const DeviceCalibration &cal, int width, int height);

} // namespace icacam::fw
