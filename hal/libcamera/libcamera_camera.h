#pragma once
// A CSI camera through libcamera behind the Camera seam. A still configuration is set up
// once and kept streaming, so a trigger costs one frame, not a reconfiguration; exposure,
// gain and colour gains are fixed (no auto-exposure drift between shots); capture() hands
// out the first completed frame whose sensor timestamp is after the call, and the luma
// plane (R8, NV12, YUV420) is viewed in place in the mapped buffer, without a copy.
// libcamera's types stay in the .cpp: nothing here depends on its version.
#include <memory>
#include <string>

#include "hal/camera.h"
#include "hal/clock.h"

namespace icacam::hal {

struct LibcameraOptions {
    std::string cameraId;      // "" = the first camera
    int exposureUs = 10000;    // fixed exposure (the LED ring lights the specimen)
    float analogueGain = 1.0f; // fixed gain
    float redGain = 1.6f, blueGain = 1.6f; // locked colour gains (AWB off)
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
    Error capture(int timeoutMs, CapturedFrame *out) override;

private:
    struct Session; // CameraManager, camera, allocator, mapped buffers, requests
    void stop();
    const Clock &clock_;
    LibcameraOptions options_;
    CameraFormat wanted_{};
    bool configured_ = false;
    std::unique_ptr<Session> session_;
};

} // namespace icacam::hal
