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

// True when any field of c is set.
inline bool anyControlSet(const CameraControls &c)
{
    return c.exposureUs >= 0 || c.analogueGain >= 0 || c.redGain >= 0 || c.blueGain >= 0 || c.lensPosition >= 0 ||
           c.sharpness >= 0 || c.noiseReduction >= 0;
}

// The fields set in `changes` over `into`.
inline void mergeControls(CameraControls *into, const CameraControls &changes)
{
    if (changes.exposureUs >= 0) into->exposureUs = changes.exposureUs;
    if (changes.analogueGain >= 0) into->analogueGain = changes.analogueGain;
    if (changes.redGain >= 0) into->redGain = changes.redGain;
    if (changes.blueGain >= 0) into->blueGain = changes.blueGain;
    if (changes.lensPosition >= 0) into->lensPosition = changes.lensPosition;
    if (changes.sharpness >= 0) into->sharpness = changes.sharpness;
    if (changes.noiseReduction >= 0) into->noiseReduction = changes.noiseReduction;
}

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
    // How late the driver's stamp may be after the exposure, as the start was computed with
    // (V4L2: camera.stamp_delay_us, or a bound from the frame interval); 0: the stamp is the
    // sensor's own, nothing added.
    int64_t stampDelayUs = 0;
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
    // Imaging controls changed on the running camera, without a reconfigure: each field of
    // `asked` that is set (>= 0) takes effect, the others stay as they are; all kept across
    // configure(). Exposure and gain set turn their automatic control off; a lens position holds
    // the lens of a camera with a focus motor (Camera Module 3, a UVC camera with
    // focus_absolute), autofocus off. A capture() after it hands out only frames exposed with
    // the new values: a camera that reports per frame what it used (libcamera) waits for the
    // first frame that reports them, one that does not (V4L2) for the first exposed after the
    // change. Returns the values the camera took, in CameraControls' units after its own
    // limits and steps (-1: not set or not read back). Errors: Invalid (a control this camera
    // does not have, or a value < 0 where one is needed: nothing changed), Io, Closed.
    virtual Result<CameraControls> setControls(const CameraControls & /*asked*/)
    {
        return Result<CameraControls>::fail(Errc::Invalid, "this camera's controls are fixed");
    }
    // The most a buffer's timestamp lags the end of its exposure, measured (`measure-latency`):
    // used from the next capture on. Errors: Invalid (a camera whose stamps are the sensor's
    // own, or < 0).
    virtual Error setStampDelayUs(int /*us*/)
    {
        return Error::make(Errc::Invalid, "this camera's timestamps are the sensor's own: no delay to set");
    }
    // One autofocus sweep on what the camera sees now, then the lens held where it ended, as
    // setControls() holds it: the position. Errors: Invalid (no autofocus), Timeout (no focus within
    // timeoutMs, the lens left as it was), Io, Closed.
    virtual Result<double> focusOnce(int /*timeoutMs*/)
    {
        return Result<double>::fail(Errc::Invalid, "this camera has no autofocus");
    }
};

} // namespace icacam::hal
