#pragma once
// The camera seam. configure() once with the largest frame the program will accept; then
// capture() hands out one frame at a time. The frame's memory belongs to the camera and stays
// valid until the next capture() (the way libcamera recycles its request buffers).
//
// A measurement needs a frame lit by the LED ring from its first row's exposure on: capture()
// takes the moment the light settled and hands out only a frame whose exposure started at or
// after it (hal/fresh_frame.h), and says how long after that the exposure started.
#include <cstdint>
#include <limits>
#include <string>

#include "hal/error.h"
#include "hal/frame.h"

namespace icacam::hal {

struct CameraFormat {
    PixelFormat format = PixelFormat::Grey8;
    int maxWidth = 0;
    int maxHeight = 0;
};

// Imaging controls: what the config asks for, and (on a captured frame) what the camera
// reports it used. A negative value means "not set" (asked) or "not reported" (read back).
struct CameraControls {
    int exposureUs = -1;                // exposure time; auto-exposure is off whenever it is set
    double analogueGain = -1;           // sensor gain (1 = none)
    double redGain = -1, blueGain = -1; // colour gains; auto white balance off when set
    double lensPosition = -1;           // dioptres (1 / distance in m); autofocus off when set
    double sharpness = -1;              // ISP sharpening (libcamera: 0 = off, 1 = default)
    int noiseReduction = -1;            // 0 off, 1 fast, 2 high quality (libcamera's enumeration)
};

struct CaptureRequest {
    // Sentinel: the exposure must start after capture() was called.
    static constexpr int64_t kAtCall = std::numeric_limits<int64_t>::min();
    int64_t notBeforeMs = kAtCall; // Clock::monotonicMs() time the LED ring settled
    int timeoutMs = 2000;
};

struct CapturedFrame {
    FrameView view;
    int64_t timestampMs = 0; // Clock::monotonicMs() time the exposure started (first row)
    // Exposure start minus CaptureRequest::notBeforeMs, microseconds (>= 0 for a frame
    // handed out; -1 unknown). For V4L2 a lower bound of the start (fresh_frame.h).
    int64_t latencyUs = -1;
    int64_t exposureUs = -1; // exposure time the frame's start was computed with
    uint32_t sequence = 0;   // the driver's frame counter (gaps: frames the driver dropped)
    int staleFrames = 0;     // frames refused because their exposure began before notBefore
    CameraControls controls; // values the camera reports for this frame
    std::string source;      // where it came from (file name, sensor model), for the journal
};

class Camera {
public:
    virtual ~Camera() = default;
    // Allocates buffers for frames up to the given size. Errors: Invalid, BadFormat, Io,
    // NotFound (no such camera: the next configure() or capture() looks again).
    virtual Error configure(const CameraFormat &fmt) = 0;
    // Captures the first frame whose exposure started at or after req.notBeforeMs, waiting
    // at most req.timeoutMs. Errors: Timeout, BadFormat (a frame of another format),
    // BadStride, TooLarge, Io, Closed (the camera went away), NotFound. Never blocks longer
    // than the timeout.
    virtual Error capture(const CaptureRequest &req, CapturedFrame *out) = 0;
    // The first frame exposed after this call.
    Error capture(int timeoutMs, CapturedFrame *out)
    {
        return capture(CaptureRequest{CaptureRequest::kAtCall, timeoutMs}, out);
    }
    // Words for `status` and the display: model, mode, what it was asked (one line).
    virtual std::string describe() const { return {}; }
};

} // namespace icacam::hal
