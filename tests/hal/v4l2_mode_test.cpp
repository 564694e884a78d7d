// The V4L2 backend's two policies without a device: which mode to stream (by frame rate,
// then area, then format), and how far a buffer's timestamp is believed.
#include <gtest/gtest.h>

#include <linux/videodev2.h>

#include <vector>

#include "hal/v4l2/buffer_stamp.h"
#include "hal/v4l2/stream_mode.h"
#include "tests/hal/c920_modes.h"

namespace {

using namespace icacam;
using hal::V4l2Mode;

constexpr uint32_t kYuyv = V4L2_PIX_FMT_YUYV, kMjpeg = V4L2_PIX_FMT_MJPEG, kGrey = V4L2_PIX_FMT_GREY;

TEST(V4l2Mode, AWebcamStreamsMjpegAtThirtyRatherThanItsSlowLargestYuyv)
{
    const std::vector<V4l2Mode> modes = test::c920Modes();
    // Largest area alone would be YUYV 2304x1536 at 2 fps.
    auto c = hal::chooseV4l2Mode(modes, 4096, 3072, 0, 0, kYuyv);
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.mode.fourcc, kMjpeg);
    EXPECT_EQ(c.mode.width, 1920);
    EXPECT_EQ(c.mode.height, 1080);
    EXPECT_DOUBLE_EQ(c.mode.fps(), 30);
    // Within 1280x720 MJPEG still wins: YUYV 1280x720 runs 10 fps.
    c = hal::chooseV4l2Mode(modes, 1280, 720, 0, 0, kYuyv);
    EXPECT_EQ(c.mode.fourcc, kMjpeg);
    EXPECT_EQ(c.mode.width, 1280);
    // At 960x720 YUYV reaches 15 fps: in place beats decoded at the same size.
    c = hal::chooseV4l2Mode(modes, 960, 720, 0, 0, kYuyv);
    EXPECT_EQ(c.mode.fourcc, kYuyv);
    EXPECT_EQ(c.mode.width, 960);
}

TEST(V4l2Mode, NothingReachesFifteenThenTheFastestAreTheCandidates)
{
    const std::vector<V4l2Mode> slow{{kYuyv, 1920, 1080, 1, 5}, {kYuyv, 1280, 720, 1, 10}, {kYuyv, 640, 480, 1, 10}};
    const auto c = hal::chooseV4l2Mode(slow, 4096, 3072, 0, 0, kYuyv);
    EXPECT_EQ(c.mode.width, 1280); // 10 fps is the best there is: the largest at 10
}

TEST(V4l2Mode, UnlistedIntervalsFallBackToTheLargestAreaAndInPlaceFormats)
{
    const std::vector<V4l2Mode> modes{{kMjpeg, 1280, 720}, {kYuyv, 1280, 720}, {kGrey, 640, 480}};
    auto c = hal::chooseV4l2Mode(modes, 4096, 3072, 0, 0, kGrey);
    EXPECT_EQ(c.mode.fourcc, kYuyv);
    EXPECT_EQ(c.mode.width, 1280);
    c = hal::chooseV4l2Mode(modes, 800, 600, 0, 0, kGrey);
    EXPECT_EQ(c.mode.fourcc, kGrey);
}

TEST(V4l2Mode, AConfiguredSizeIsTakenInItsBestFormat)
{
    const std::vector<V4l2Mode> modes = test::c920Modes();
    auto c = hal::chooseV4l2Mode(modes, 4096, 3072, 1920, 1080, kYuyv);
    EXPECT_EQ(c.mode.fourcc, kMjpeg); // 30 fps against YUYV's 5
    c = hal::chooseV4l2Mode(modes, 4096, 3072, 640, 480, kYuyv);
    EXPECT_EQ(c.mode.fourcc, kYuyv); // both 30: in place
    EXPECT_FALSE(hal::chooseV4l2Mode(modes, 4096, 3072, 1000, 1000, kYuyv).found);
}

// Buffer timestamps: L is the instant the LED settled; exposures are 10 ms, frames 33 ms.
constexpr int64_t kMs = 1000000;
constexpr int64_t L = 5000 * kMs;

hal::BufferTiming timing(int64_t stampNs, int64_t nowNs)
{
    hal::BufferTiming t;
    t.stampNs = stampNs;
    t.nowNs = nowNs;
    t.exposureNs = 10 * kMs;
    t.frameIntervalNs = 33 * kMs;
    t.pollSliceNs = 20 * kMs;
    return t;
}

bool fresh(const hal::BufferStampModel &m, const hal::BufferTiming &t)
{
    hal::FrameStamp s;
    return hal::boundExposureStart(m, t, &s) && hal::exposedAfter(s, L);
}

TEST(BufferStamp, UvcvideosStartOfExposureFlagIsNotBelieved)
{
    const uint32_t flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE;
    const auto uvc = hal::bufferStampModel(flags, "uvcvideo");
    EXPECT_TRUE(uvc.monotonic);
    EXPECT_TRUE(uvc.firstPacket);
    // First packet 15 ms after L: with a 10 ms exposure and up to 33 ms of readout and
    // encoding before it, the exposure may have begun 28 ms before L. Refused.
    EXPECT_FALSE(fresh(uvc, timing(L + 15 * kMs, L + 40 * kMs)));
    EXPECT_TRUE(fresh(uvc, timing(L + 44 * kMs, L + 60 * kMs)));
    // The same stamp from a driver whose SOE is the specification's: the exposure began then.
    const auto soe = hal::bufferStampModel(flags, "some-csi-receiver");
    EXPECT_FALSE(soe.firstPacket);
    EXPECT_TRUE(fresh(soe, timing(L + 1 * kMs, L + 40 * kMs)));
    EXPECT_FALSE(fresh(soe, timing(L - 1 * kMs, L + 40 * kMs)));
}

TEST(BufferStamp, AnEndOfFrameStampAllowsTheWholeReadoutWhateverWasConfigured)
{
    const auto eof = hal::bufferStampModel(V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_EOF, "csi");
    auto t = timing(L + 30 * kMs, L + 40 * kMs);
    t.configuredDelayNs = 2 * kMs; // a first-packet delay, too short for a whole frame's readout
    EXPECT_FALSE(fresh(eof, t));   // the first row may have started 13 ms before L
    t.stampNs = L + 44 * kMs;
    EXPECT_TRUE(fresh(eof, t));
}

TEST(BufferStamp, StampsOnAnotherClockFallBackToTheDequeueTime)
{
    // uvcvideo loaded with clock=realtime: the MONOTONIC flag stays, the stamps are wall time.
    const auto uvc =
        hal::bufferStampModel(V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE, "uvcvideo");
    const int64_t wall = int64_t(1767225600) * 1000000000; // 2026-01-01 in CLOCK_REALTIME
    auto t = timing(wall, L + 200 * kMs);
    t.waitingAtCall = true; // already in the queue when capture() was called: no bound
    EXPECT_FALSE(fresh(uvc, t));
    t.waitingAtCall = false; // arrived while polling: 10 + 33 + 33 + 20 ms before it at most
    EXPECT_TRUE(fresh(uvc, t));
    t.nowNs = L + 90 * kMs;
    EXPECT_FALSE(fresh(uvc, t));
    // No clock in the flags at all (COPY): the same.
    const auto copy = hal::bufferStampModel(V4L2_BUF_FLAG_TIMESTAMP_COPY, "vivid");
    EXPECT_FALSE(copy.monotonic);
    auto c = timing(L + 500 * kMs, L + 40 * kMs); // a stamp that would pass if believed
    c.waitingAtCall = true;
    EXPECT_FALSE(fresh(copy, c));
}

} // namespace
