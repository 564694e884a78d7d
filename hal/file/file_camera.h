#pragma once
// A camera that "captures" image files in turn, and behaves like a sensor: frames of another
// pixel format or larger than configured are refused, the row stride can be padded the way
// ISPs pad it, and once the list is exhausted (or at a "!timeout" entry) a capture waits its
// full timeout and fails with Errc::Timeout.
//
// configure() again over the same frames carries on at the same position, and so does
// setControls(): the controls it is given are reported on every frame after it, as a sensor
// reports what it used, and the list of images goes on where it was.
//
// Lit by a ScriptedLight (hal/file/scripted_light.h), the images are the scene under the LED
// ring: each row is dimmed to `ambient` for the part of its exposure the ring gave no light,
// the rows read out top to bottom over readoutMs (a rolling shutter). The scene changes only
// once it has been seen lit: a frame lit not at all or only in part shows the same image
// again at the next capture, as the specimen under a real camera stays where it is.
//
// Source: a folder (its .png/.jpg/.jpeg/.pgm files in name order) or a list file (one path a
// line, relative to the list's folder; '#' comments; "!timeout" simulates a hung sensor).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hal/camera.h"
#include "hal/clock.h"
#include "hal/file/scripted_light.h"

namespace icacam::hal {

struct FileCameraOptions {
    FileCameraOptions() = default;
    FileCameraOptions(std::string src, int align = 1, bool loopAtEnd = false, int latencyMs = 0,
                      CameraControls reported = {}, const ScriptedLight *litBy = nullptr)
            : source(std::move(src)), strideAlign(align), loop(loopAtEnd), exposureMs(latencyMs), controls(reported),
              light(litBy)
    {}

    std::string source;                   // folder or list file
    int strideAlign = 1;                  // rows padded to a multiple of this many bytes (e.g. 64)
    bool loop = false;                    // start over at the end instead of timing out
    int exposureMs = 0;                   // simulated capture latency
    CameraControls controls;              // reported back on every frame, as a sensor reports what it used
    const ScriptedLight *light = nullptr; // none: every image as it is, each used once
    double ambient = 0.1;                 // the scene's brightness without the ring, of the image's
    int readoutMs = 0;                    // first row's exposure start to the last's
    bool fixedFocus = false;              // no lens: setControls() refuses a lens position
};

class FileCamera final : public Camera {
public:
    FileCamera(Clock &clock, FileCameraOptions opts) : clock_(clock), opts_(std::move(opts)) {}

    Error configure(const CameraFormat &fmt) override;
    using Camera::capture;
    // The "exposure" starts when the call is made (or at req.notBeforeMs, waited for, if later).
    Error capture(const CaptureRequest &req, CapturedFrame *out) override;
    std::string describe() const override;
    // Records the controls (reported from the next frame on); takes every value as asked,
    // but a lens position on a fixed-focus one (Errc::Invalid, nothing changed).
    Result<CameraControls> setControls(const CameraControls &asked) override;

private:
    // Dims each row for the part of its exposure the light was off; true when every row was
    // lit throughout.
    bool light(uint8_t *rows, int width, int height, int stride, int channels, int64_t startMs) const;

    Clock &clock_;
    FileCameraOptions opts_;
    CameraFormat fmt_;
    std::vector<std::string> files_;
    size_t next_ = 0;
    std::unique_ptr<uint8_t[]> buffer_;
    size_t capacity_ = 0;
};

} // namespace icacam::hal
