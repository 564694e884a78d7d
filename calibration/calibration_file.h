#pragma once
// The camera calibration file written by `icacam calibrate` and read by `icacam measure`
// and the device (icacam-fw): plain text, one `key = value` a line, '#' comments
// (docs/calibration.md). One parser for both, outside vision/ because it reads files;
// it throws nothing, so the firmware (built without exceptions) links it as is.
#include <string>

#include "vision/plane_calibration.h"

namespace icacam::calibration {

struct CalibrationFile {
    vision::PlaneCalibration plane; // heightMm is per specimen: 0 in the file
    int imageWidth = 0, imageHeight = 0;
    double rmsPx = 0;            // RMS reprojection error of the calibration views
    int views = 0;               // views used
    std::string board;           // the board as given to --board
    double boardThicknessMm = 0; // already applied to the fixture pose
};

// Writes the file; returns an empty string or the reason it could not.
std::string writeCalibrationFile(const std::string &path, const CalibrationFile &c);
// Parses text / reads a file; returns an empty string or a message naming the line.
std::string parseCalibrationText(const std::string &text, CalibrationFile *out);
std::string readCalibrationFile(const std::string &path, CalibrationFile *out);

} // namespace icacam::calibration
