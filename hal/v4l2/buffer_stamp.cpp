#include "hal/v4l2/buffer_stamp.h"

#include <linux/videodev2.h>

namespace icacam::hal {

namespace {

// A CLOCK_MONOTONIC stamp is within a frame or two of now; CLOCK_REALTIME is decades away
// and CLOCK_BOOTTIME only differs after a suspend. An hour tells them apart.
constexpr int64_t kPlausibleNs = int64_t(3600) * 1000000000;

} // namespace

BufferStampModel bufferStampModel(uint32_t flags, std::string_view driver)
{
    BufferStampModel m;
    m.monotonic = (flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
    m.startOfExposure = (flags & V4L2_BUF_FLAG_TSTAMP_SRC_MASK) == V4L2_BUF_FLAG_TSTAMP_SRC_SOE;
    m.firstPacket = driver == "uvcvideo";
    return m;
}

std::string describeStampModel(const BufferStampModel &m)
{
    if (!m.monotonic) return "no clock in the buffer timestamps: dequeue time";
    if (m.firstPacket) return "first USB packet (uvcvideo; its MONOTONIC+SOE flags are fixed)";
    return m.startOfExposure ? "start of exposure" : "end of frame";
}

bool boundExposureStart(const BufferStampModel &m, const BufferTiming &t, FrameStamp *out)
{
    const int64_t configured = t.configuredDelayNs;
    const int64_t skew = t.stampNs - t.nowNs;
    const bool believable = m.monotonic && skew < kPlausibleNs && skew > -kPlausibleNs;
    if (believable) {
        out->stampNs = t.stampNs;
        if (m.firstPacket) { // after the exposure's end by readout and encoding: configured or one interval
            out->exposureNs = t.exposureNs;
            out->stampDelayNs = configured >= 0 ? configured : t.frameIntervalNs;
        } else if (m.startOfExposure) { // the specification's meaning
            out->exposureNs = 0;
            out->stampDelayNs = configured >= 0 ? configured : 0;
        } else { // end of frame: the whole readout, up to one interval, came first
            out->exposureNs = t.exposureNs;
            out->stampDelayNs = configured > t.frameIntervalNs ? configured : t.frameIntervalNs;
        }
        return true;
    }
    if (t.waitingAtCall) return false;
    // The dequeue time: after the first packet by the rest of the transfer (one interval) and
    // by how long the buffer may have waited while capture() polled.
    out->stampNs = t.nowNs;
    out->exposureNs = t.exposureNs;
    out->stampDelayNs = (configured >= 0 ? configured : t.frameIntervalNs) + t.frameIntervalNs + t.pollSliceNs;
    return true;
}

} // namespace icacam::hal
