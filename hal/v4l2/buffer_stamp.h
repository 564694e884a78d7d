#pragma once
// What a V4L2 buffer's timestamp says about when its frame was exposed, read from the
// buffer's flags and the driver, believed only as far as the driver's source supports it.
//
//  * The flags: V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC says the stamp is on CLOCK_MONOTONIC
//    (COPY and UNKNOWN: no clock at all); TSTAMP_SRC_SOE says it was taken at the start of
//    the exposure, TSTAMP_SRC_EOF when the last pixel was received.
//  * uvcvideo sets MONOTONIC | SOE once for its queue, whatever happens (uvc_queue_init,
//    drivers/media/usb/uvc/uvc_queue.c), and stamps a buffer with the system time when the
//    frame's first USB packet arrives (uvc_video_decode_start, uvc_video.c): after the
//    exposure, by the camera's readout and, for MJPEG, encoding. Its clock is the module's
//    `clock` parameter, CLOCK_MONOTONIC by default but realtime if set, under the same
//    MONOTONIC flag. So for uvcvideo the SOE flag is not believed, and a stamp far from
//    CLOCK_MONOTONIC's now is taken for what it is: another clock.
//  * Another driver's SOE stamp is its exposure start (the V4L2 specification); an EOF
//    stamp follows the whole frame's readout, at most one frame interval after the first
//    row's exposure ended.
//  * A stamp that cannot be believed is replaced by the time the buffer was dequeued, with
//    the bound widened by a frame interval (the transfer after the first packet) and the
//    poll slice; a buffer that was already waiting when capture() began has no bound at all
//    and is refused.
#include <cstdint>
#include <string>
#include <string_view>

#include "hal/fresh_frame.h"

namespace icacam::hal {

struct BufferStampModel {
    bool monotonic = false;       // the flags name CLOCK_MONOTONIC
    bool startOfExposure = false; // the flags say SOE
    bool firstPacket = false;     // uvcvideo: the first packet's arrival, whatever the flags say
};

BufferStampModel bufferStampModel(uint32_t bufferFlags, std::string_view driver);

// Words for `status`: "first USB packet (uvcvideo; its MONOTONIC+SOE flags are fixed)".
std::string describeStampModel(const BufferStampModel &model);

struct BufferTiming {
    int64_t stampNs = 0;            // the buffer's timestamp
    int64_t nowNs = 0;              // CLOCK_MONOTONIC when it was dequeued
    int64_t exposureNs = 0;         // the exposure (or a bound of it)
    int64_t frameIntervalNs = 0;    // the stream's frame interval
    int64_t configuredDelayNs = -1; // camera.stamp_delay_us: most the stamp lags the exposure's end; -1 unset
    int64_t pollSliceNs = 0;        // most a buffer waits in the driver's queue while capture() polls
    bool waitingAtCall = false;     // dequeued before capture() first waited: done before the call
};

// The stamp model turned into fresh_frame's FrameStamp for this buffer: exposureStartNs() of
// the result is never later than the frame's true exposure start. False: no such bound
// exists (a buffer without a believable stamp that was already waiting): refuse it.
bool boundExposureStart(const BufferStampModel &model, const BufferTiming &t, FrameStamp *out);

} // namespace icacam::hal
