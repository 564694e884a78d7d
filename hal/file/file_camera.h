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
// once it has been seen lit by the whole ring: a frame lit not at all, only in part, or by a
// segment of the ring shows the same image again at the next capture, as the specimen under a
// real camera stays where it is (a device takes a specimen's segment frames before or after
// its whole-ring frame).
//
// A frame lit by segment k alone (it lit the middle row's exposure more than anything else
// did) is decoded from the entry's segment image k, its rows dimmed by the part of their
// exposure segment k gave light in; an entry without segment images gives the scene's image
// with each row at ambient + (1 − ambient) · lit / segments() (one segment's share of the
// ring's light). Errors: Invalid (the entry names another count of segment images than the
// light has segments), BadFormat (a segment image of another size than the scene's).
//
// Source: a folder (its .png/.jpg/.jpeg/.pgm files in name order; no segment images) or a
// list file: one entry a line, "IMAGE" or "IMAGE | S0 | S1 | … | S(N−1)" with N = 3 … 8
// segment images in azimuth order, paths relative to the list's folder; '#' comments;
// "!timeout" simulates a hung sensor.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hal/camera.h"
#include "hal/clock.h"
#include "hal/file/scripted_light.h"

namespace icacam::hal {

struct DecodedImage;

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
    struct Entry {
        std::string image;                 // the scene, or "!timeout"
        std::vector<std::string> segments; // lit by segment k alone, in azimuth order; or none
        bool operator==(const Entry &) const = default;
    };
    static constexpr int kWholeRing = -1;

    Error readList(std::vector<Entry> *entries) const;
    // What lit the middle row's exposure most: a segment k, or the whole ring (kWholeRing,
    // also when nothing did).
    int litBy(int64_t startMs, int height) const;
    // Dims each row for the part of its exposure the light (the whole ring or segment k) was
    // off, its light times share; true when every row was lit throughout.
    bool light(uint8_t *rows, int width, int height, int stride, int channels, int64_t startMs, int by,
               double share) const;
    // Decodes path into the buffer. Errors: those of decodeImage, BadFormat (channels).
    Error decode(const std::string &path, DecodedImage *img);

    Clock &clock_;
    FileCameraOptions opts_;
    CameraFormat fmt_;
    std::vector<Entry> entries_;
    size_t next_ = 0;
    std::unique_ptr<uint8_t[]> buffer_;
    size_t capacity_ = 0;
};

} // namespace icacam::hal
