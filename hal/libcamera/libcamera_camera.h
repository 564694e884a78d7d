#pragma once
// A CSI camera through libcamera behind the Camera seam. A still configuration is set up
// once and kept streaming, so a trigger costs one frame, not a reconfiguration; exposure,
// gain and colour gains are fixed (no auto-exposure drift between shots), autofocus is off
// at a set lens position, sharpening and noise reduction as configured; capture() hands out
// the first completed frame whose exposure (SensorTimestamp − ExposureTime) started after
// the LED settled, with the control values the pipeline reports for it, and the luma plane
// (R8, NV12, YUV420) is viewed in place in the mapped buffer, without a copy.
// libcamera's types stay in the .cpp: nothing here depends on its version.
#include <memory>
#include <string>

#include "hal/camera.h"
#include "hal/clock.h"

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
    std::string describe() const override { return description_; }

private:
    struct Session; // CameraManager, camera, allocator, mapped buffers, requests
    void stop();
    const Clock &clock_;
    LibcameraOptions options_;
    CameraFormat wanted_{};
    std::string description_ = "libcamera: not opened";
    bool configured_ = false;
    std::unique_ptr<Session> session_;
};

} // namespace icacam::hal
