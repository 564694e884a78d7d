#pragma once
// Camera calibration from photos of a chessboard or circle grid: intrinsics, distortion and
// the fixture plane's pose, as a calibration file (docs/calibration.md). `icacam calibrate`
// and the synthetic calibrated condition sets both make their files here.
#include <cstddef>
#include <string>

#include "calibration/calibration_file.h"

namespace icacam::host {

struct CameraCalibrationInputs {
    std::string imagesDir; // photos of the board in different poses (png/jpg/tif/bmp/pgm)
    // chessboard:COLSxROWS:SQUARE_MM (inner corners, square side) or circles:COLSxROWS:SPACING_MM
    std::string board;
    std::string flatPhoto;       // the board lying flat on the fixture: a path, or a name in imagesDir
    double boardThicknessMm = 0; // the board's surface above the fixture
    double maxRmsPx = 0.5;       // refuse a calibration whose RMS reprojection error is above this
    double maxBlurPx = 0;        // refuse views whose board edges are wider than this (0: no limit)
    bool freeK3 = false;         // fit k3 too (else fixed at 0: ill-determined in a narrow field)
};

struct CameraCalibration {
    calibration::CalibrationFile file;
    std::string viewsNotUsed;                   // one line per photo left out or dropped, with why
    size_t photos = 0;                          // image files in imagesDir
    double medianViewPx = 0, largestViewPx = 0; // per-view RMS reprojection errors
    double coverage = 0;                        // share of the frame's 8 × 6 cells that hold corners
    double flatRmsPx = 0;                       // the flat view's reprojection error
    double fixtureDistanceMm = 0;               // along the camera's axis
    double tiltDeg = 0;                         // of the fixture plane against the image plane
};

// Calibrates from the photos; returns an empty string, or why no calibration could be made
// (out->viewsNotUsed then says which photos were left out so far).
std::string calibrateCamera(const CameraCalibrationInputs &in, CameraCalibration *out);

// Calibrates, says which views were not used (standard error) and what the camera is
// (standard output), and writes the calibration file to outPath. Throws std::runtime_error
// with the reason when no file is written.
void writeCameraCalibration(const CameraCalibrationInputs &in, const std::string &outPath);

} // namespace icacam::host
