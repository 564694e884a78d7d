#pragma once
// Which sensor mode a CSI camera runs in, and at which size the processed (luma) stream is
// taken. A pure function of the sensor's mode list, so it is tested against the real lists
// (tests/hal/sensor_mode_test.cpp) without a camera.
//
// Why this is needed: on a Raspberry Pi the processed stream's listed sizes come from
// libcamera's table of common resolutions (StreamFormats::sizes() on a size range,
// src/libcamera/stream.cpp), not from the sensor: the largest within an imx708's 4608x2592
// is 3840x2400, a 16:10 crop the ISP rescales. The pipeline picks the sensor mode from the
// largest raw stream, else from the sensor configuration, else from the processed size
// (RPiCameraConfiguration::validate(), pipeline/rpi/common/pipeline_base.cpp), so asking
// for the mode's own size, and naming the mode through a raw stream or `sensorConfig`, is
// what makes the luma the sensor's pixels. rpicam-still does the same for the same reason
// ("Always request a raw stream as this forces the full resolution capture mode",
// RPiCamApp::ConfigureStill, rpicam-apps core/rpicam_app.cpp).
#include <span>
#include <string_view>

namespace icacam::hal {

struct SensorMode {
    int width = 0, height = 0;
    int bitDepth = 0; // bits per raw pixel (10 for SRGGB10_CSI2P)
};

struct SensorModeChoice {
    bool found = false;
    SensorMode mode;                 // the sensor mode to run
    int outWidth = 0, outHeight = 0; // the processed stream: the luma that is measured
    // The processed stream is not the mode pixel for pixel: a size was configured that no
    // mode has, or no mode fits the maximum and the ISP scales down.
    bool scaled = false;
};

// Without a configured size (width or height <= 0): the mode with the most pixels within
// maxWidth x maxHeight (ties: more bits), its own size for the processed stream. No mode
// fits: the smallest mode, scaled by the ISP to fit the maximum with its aspect ratio kept.
// With a configured size: that size for the processed stream (not found when above the
// maximum), from the smallest mode that covers it (ties: more bits), else the largest mode.
SensorModeChoice chooseSensorMode(std::span<const SensorMode> modes, int maxWidth, int maxHeight, int width = 0,
                                  int height = 0);

// The bit depth in a raw pixel format's name as libcamera prints it ("SRGGB10_CSI2P" 10,
// "SBGGR8" 8, "R12_CSI2P" 12 for a mono sensor); 0 for a format that is not raw Bayer or
// raw mono (NV12, YUYV, MJPEG, "BGGR_PISP_COMP1").
int rawBitDepth(std::string_view formatName);

} // namespace icacam::hal
