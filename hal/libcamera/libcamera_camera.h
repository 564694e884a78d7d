#pragma once
// A CSI camera through libcamera behind the Camera seam. A still configuration is set up
// once and kept streaming, so a trigger costs one frame, not a reconfiguration. The sensor
// runs in the mode chooseSensorMode() picks from the modes the camera lists (its full
// resolution when the maximum allows), named to the pipeline as rpicam-still does, and the
// processed stream is that mode's size, so the luma is the sensor's pixels, not an ISP
// crop (hal/libcamera/sensor_mode.h). The tone curve is fixed: the Raspberry Pi tuning file
// with adaptive contrast off (hal/libcamera/tuning.h) unless told otherwise. Exposure,
// gain and colour gains are fixed (no auto-exposure drift between shots), autofocus is off
// at a set lens position, sharpening and noise reduction as configured; capture() hands out
// the first completed frame whose exposure (SensorTimestamp − ExposureTime) started after
// the LED settled, with the control values the pipeline reports for it, and the luma plane
// (R8, NV12, YUV420) is viewed in place in the mapped buffer, without a copy.
// libcamera's types stay in the .cpp: nothing here depends on its version.
#include <memory>
#include <string>
#include <vector>

#include "hal/camera.h"
#include "hal/clock.h"
#include "hal/libcamera/sensor_mode.h"

namespace icacam::hal {

struct LibcameraOptions {
    // "" = the first camera; else a camera id (`cam --list`) or a part of the sensor's
    // model name ("imx708").
    std::string camera;
    // Fixed exposure and gain (the LED ring lights the specimen), locked colour gains (AWB
    // off); lens position and ISP settings only when set (>= 0).
    CameraControls controls{10000, 1.0, 1.6, 1.6, -1, -1, -1};
    // Stream size: 0 × 0 = the sensor's largest mode that fits the configured maximum
    // (a full-resolution mode, not an ISP upscale to the buffer limit).
    int width = 0, height = 0;
    int bufferCount = 4;
    // The tone curve. "": fixed, the sensor's Raspberry Pi tuning file with adaptive
    // contrast off, written to a directory of this process's (tuningDir, else
    // $RUNTIME_DIRECTORY, else /tmp) and found by libcamera through LIBCAMERA_IPA_CONFIG_PATH;
    // "system": libcamera's installed file as it is; else the path of a tuning file
    // (LIBCAMERA_RPI_TUNING_FILE, for every camera of the process).
    std::string tuning;
    std::string tuningDir;
    // The tone curve the override writes, linear^(1/toneGamma) (1: linear luma); the
    // pipeline is told the same (camera.tone_gamma). A tuning file of one's own keeps its curve.
    double toneGamma = 1;
};

// What configure() set up, for `status`, the journal and the hardware-in-the-loop test.
struct LibcameraMode {
    std::string model;                   // the sensor (properties::Model: imx708, imx477 ...)
    std::vector<SensorMode> sensorModes; // the raw modes the camera lists (empty: none listed)
    SensorModeChoice choice;             // what chooseSensorMode() made of them
    // How the mode was named to the pipeline: "sensor configuration", "raw stream", or
    // "stream size" (a pipeline without raw modes: it picks the mode from the size).
    std::string namedBy;
    int width = 0, height = 0; // the processed stream the pipeline agreed to
    std::string pixelFormat;   // NV12, YUV420, R8 ...
    std::string tuning;        // which tuning file, adaptive contrast on or off
};

class LibcameraCamera final : public Camera {
public:
    LibcameraCamera(const Clock &clock, LibcameraOptions options);
    ~LibcameraCamera() override;
    LibcameraCamera(const LibcameraCamera &) = delete;
    LibcameraCamera &operator=(const LibcameraCamera &) = delete;

    // Errors: NotFound (no camera), BadFormat (no luma format at that size), Io.
    Error configure(const CameraFormat &fmt) override;
    // Errors: Timeout, Closed (the camera went away; the next call tries again), Io.
    using Camera::capture;
    Error capture(const CaptureRequest &req, CapturedFrame *out) override;
    std::string describe() const override;
    // ExposureTime, AnalogueGain (within the limits the camera lists), ColourGains (AWB off),
    // LensPosition (dioptres, AfMode Manual), Sharpness and NoiseReductionMode on the next
    // request queued; capture() then hands out only a frame whose metadata shows the new
    // exposure, gain and lens (control_settle.h), or, after kSettleFrames that do not, the
    // next as it is (its controls say what it used).
    Result<CameraControls> setControls(const CameraControls &asked) override;
    // AfMode Auto and AfTrigger Start, frames until AfState says Focused (or Failed), then
    // the LensPosition the frame reports held as setControls() holds it.
    Result<double> focusOnce(int timeoutMs) override;
    // Valid after a successful configure().
    const LibcameraMode &mode() const { return mode_; }

    // Frames after a setControls() that may still not show it (a Raspberry Pi sensor's
    // exposure lags its request by two frames, gain by one) before one is taken anyway.
    static constexpr int kSettleFrames = 6;

private:
    struct Session; // CameraManager, camera, allocator, mapped buffers, requests
    void stop();
    Error openSession(std::unique_ptr<Session> *out);
    Error prepareTuning(const std::string &model, bool *restart);
    Error configureStreams(Session &s, const CameraFormat &fmt);
    const Clock &clock_;
    LibcameraOptions options_;
    CameraFormat wanted_{};
    std::string description_ = "libcamera: not opened";
    std::string notes_;  // what the camera lacks of the controls asked
    std::string source_; // the frame's `source`: camera, mode, tuning
    bool configured_ = false;
    LibcameraMode mode_;
    std::string tuningDir_;   // the fixed-tone override's directory (removed at destruction)
    std::string tuningModel_; // the sensor it was written for
    std::string tuningNote_;
    std::unique_ptr<Session> session_;
};

} // namespace icacam::hal
