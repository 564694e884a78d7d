#pragma once
// Which frame was exposed under the LED ring. A frame is fresh when its first row's exposure
// started at or after the moment the light settled; everything else is refused, however late
// it arrives. The drivers stamp frames at different points:
//  * libcamera's SensorTimestamp (Raspberry Pi: the receiver's frame-start interrupt) is the
//    start of the first row's readout, i.e. the end of its exposure, so the exposure began
//    ExposureTime earlier (picamera2 tests frames the same way). The buffer's own timestamp
//    is useless here: on a Pi 5 the ISP stamps buffers when it has processed them, and
//    requests complete oldest sensor frame first, so a frame exposed in the dark completes
//    after the LED came on.
//  * uvcvideo stamps a buffer when the frame's first USB packet arrives (hardware stamps are
//    off by default): after the exposure, by the camera's readout and (MJPEG) encoding
//    time. The start is therefore at most stamp − exposure, and at least that minus the
//    camera's delay; stampDelayNs is the bound used, so a refused frame is never stale.
// Times are CLOCK_MONOTONIC nanoseconds, the clock the kernel stamps both with.
#include <time.h>

#include <cstdint>

#include "hal/camera.h"
#include "hal/clock.h"

namespace icacam::hal {

struct FrameStamp {
    int64_t stampNs = 0;      // the driver's timestamp of the frame
    int64_t exposureNs = 0;   // the exposure the frame was taken with (or a bound of it)
    int64_t stampDelayNs = 0; // most the stamp can lag the end of the first row's exposure
};

// The earliest the frame's exposure can have started.
inline int64_t exposureStartNs(const FrameStamp &s)
{
    return s.stampNs - s.exposureNs - s.stampDelayNs;
}

inline bool exposedAfter(const FrameStamp &s, int64_t notBeforeNs)
{
    return exposureStartNs(s) >= notBeforeNs;
}

inline int64_t monotonicNowNs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// A time of the HAL's Clock (whole milliseconds, any origin: a test's manual clock) on
// CLOCK_MONOTONIC, never earlier than the true instant: a whole-millisecond age can be up to
// 1 ms too long, so one is taken off. kAtCall is "now".
inline int64_t notBeforeOnMonotonicNs(const Clock &clock, int64_t notBeforeMs)
{
    const int64_t now = monotonicNowNs();
    if (notBeforeMs == CaptureRequest::kAtCall) return now;
    const int64_t ageMs = clock.monotonicMs() - notBeforeMs;
    return ageMs >= 1 ? now - (ageMs - 1) * 1000000 : now - ageMs * 1000000; // a future instant: later
}

// The same instant back on the HAL's Clock.
inline int64_t monotonicNsOnClockMs(const Clock &clock, int64_t ns)
{
    return clock.monotonicMs() - (monotonicNowNs() - ns) / 1000000;
}

} // namespace icacam::hal
