#include "hal/v4l2/stream_mode.h"

#include <linux/videodev2.h>

namespace icacam::hal {

namespace {

// Lower is better: the formats vision views in place before the decoded one.
int formatRank(uint32_t cc, uint32_t preferred)
{
    if (cc == preferred && cc != V4L2_PIX_FMT_MJPEG) return 0;
    switch (cc) {
    case V4L2_PIX_FMT_GREY: return 1;
    case V4L2_PIX_FMT_NV12: return 2;
    case V4L2_PIX_FMT_YUYV: return 3;
    case V4L2_PIX_FMT_MJPEG: return 4;
    default: return 5;
    }
}

} // namespace

V4l2ModeChoice chooseV4l2Mode(std::span<const V4l2Mode> modes, int maxWidth, int maxHeight, int width, int height,
                              uint32_t preferred, double minFps)
{
    const bool sized = width > 0 && height > 0;
    auto candidate = [&](const V4l2Mode &m) {
        if (m.width <= 0 || m.height <= 0 || formatRank(m.fourcc, preferred) > 4) return false;
        if (sized) return m.width == width && m.height == height;
        return m.width <= maxWidth && m.height <= maxHeight;
    };
    // The rate to reach: minFps, or the best any candidate has when none reaches it.
    double best = 0;
    bool anyUnknown = false;
    for (const V4l2Mode &m : modes) {
        if (!candidate(m)) continue;
        if (m.fps() == 0) anyUnknown = true;
        if (m.fps() > best) best = m.fps();
    }
    const double goal = anyUnknown || best >= minFps ? minFps : best;
    const double tolerance = 1e-6 * goal; // 30000/1001 against 30/1 and the like stay distinct
    V4l2ModeChoice c;
    for (const V4l2Mode &m : modes) {
        if (!candidate(m)) continue;
        const double fps = m.fps() == 0 ? goal : m.fps();
        if (fps + tolerance < goal) continue;
        if (c.found) {
            const int64_t area = int64_t(m.width) * m.height, bestArea = int64_t(c.mode.width) * c.mode.height;
            if (area < bestArea) continue;
            if (area == bestArea) {
                const int rank = formatRank(m.fourcc, preferred), bestRank = formatRank(c.mode.fourcc, preferred);
                if (rank > bestRank) continue;
                if (rank == bestRank && fps <= (c.mode.fps() == 0 ? goal : c.mode.fps())) continue;
            }
        }
        c.found = true;
        c.mode = m;
    }
    return c;
}

} // namespace icacam::hal
