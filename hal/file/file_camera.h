#pragma once
// A camera that "captures" image files in turn, and behaves like a sensor: frames of another
// pixel format or larger than configured are refused, the row stride can be padded the way
// ISPs pad it, and once the list is exhausted (or at a "!timeout" entry) a capture waits its
// full timeout and fails with Errc::Timeout.
//
// configure() again over the same frames carries on at the same position.
//
// Source: a folder (its .png/.jpg/.jpeg/.pgm files in name order) or a list file (one path a
// line, relative to the list's folder; '#' comments; "!timeout" simulates a hung sensor).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hal/camera.h"
#include "hal/clock.h"

namespace icacam::hal {

struct FileCameraOptions {
    FileCameraOptions() = default;
    FileCameraOptions(std::string src, int align = 1, bool loopAtEnd = false, int latencyMs = 0,
                      CameraControls reported = {})
            : source(std::move(src)), strideAlign(align), loop(loopAtEnd), exposureMs(latencyMs), controls(reported)
    {}

    std::string source;      // folder or list file
    int strideAlign = 1;     // rows padded to a multiple of this many bytes (e.g. 64)
    bool loop = false;       // start over at the end instead of timing out
    int exposureMs = 0;      // simulated capture latency
    CameraControls controls; // reported back on every frame, as a sensor reports what it used
};

class FileCamera final : public Camera {
public:
    FileCamera(Clock &clock, FileCameraOptions opts) : clock_(clock), opts_(std::move(opts)) {}

    Error configure(const CameraFormat &fmt) override;
    using Camera::capture;
    // The "exposure" starts when the call is made (or at req.notBeforeMs, waited for, if later).
    Error capture(const CaptureRequest &req, CapturedFrame *out) override;
    std::string describe() const override;

private:
    Clock &clock_;
    FileCameraOptions opts_;
    CameraFormat fmt_;
    std::vector<std::string> files_;
    size_t next_ = 0;
    std::unique_ptr<uint8_t[]> buffer_;
    size_t capacity_ = 0;
};

} // namespace icacam::hal
