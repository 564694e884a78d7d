// Hardware in the loop: the real camera on the board (docs/hil-checklist.md). Every frame
// must have started its exposure at or after the instant it was asked for, with the
// controls the camera reports; a CSI camera must deliver the luma at the sensor mode the
// backend's choice names (its full resolution for the sensors the product names) with the
// fixed tone curve; exits 77 (skipped) where there is no camera, as on the build machines.
//   ICACAM_HIL_CAMERA=libcamera            a CSI camera (the default when libcamera has one)
//   ICACAM_HIL_CAMERA=/dev/icacam-camera   a V4L2 node
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "hal/file/clocks.h"
#ifdef ICACAM_HAVE_LIBCAMERA
#include "hal/libcamera/libcamera_camera.h"
#endif
#ifdef ICACAM_HAVE_V4L2
#include "hal/v4l2/v4l2_camera.h"
#endif

namespace {

using namespace icacam;

// The largest frame the test accepts: the shipped maximum (deploy/device.conf).
constexpr int kMaxWidth = 4608, kMaxHeight = 3040;

std::unique_ptr<hal::Camera> gCamera;
bool gLibcamera = false;
hal::SystemClock gClock;
#ifdef ICACAM_HAVE_LIBCAMERA
hal::LibcameraCamera *gCsi = nullptr;

// The full-resolution mode of each sensor the product names (their drivers' mode tables,
// tests/hal/sensor_mode_test.cpp).
struct KnownSensor {
    const char *model;
    int width, height;
};
constexpr KnownSensor kKnown[] = {
    {"imx708", 4608, 2592}, {"imx477", 4056, 3040}, {"imx219", 3280, 2464}, {"ov5647", 2592, 1944}};

TEST(HilCamera, TheLumaIsTheSensorModeTheChoiceNamesWithTheToneCurveFixed)
{
    if (!gCsi) GTEST_SKIP() << "not a libcamera camera";
    const hal::LibcameraMode &m = gCsi->mode();
    std::printf("sensor %s, %zu raw modes:", m.model.c_str(), m.sensorModes.size());
    for (const hal::SensorMode &s : m.sensorModes) std::printf(" %dx%d/%d", s.width, s.height, s.bitDepth);
    std::printf("\nnamed by %s; stream %dx%d %s; %s\n", m.namedBy.c_str(), m.width, m.height, m.pixelFormat.c_str(),
                m.tuning.c_str());
    ASSERT_FALSE(m.sensorModes.empty()) << "the camera lists no raw modes: not a Raspberry Pi pipeline?";
    const hal::SensorModeChoice want = hal::chooseSensorMode(m.sensorModes, kMaxWidth, kMaxHeight);
    ASSERT_TRUE(want.found);
    EXPECT_EQ(m.choice.mode.width, want.mode.width);
    EXPECT_EQ(m.choice.mode.height, want.mode.height);
    EXPECT_EQ(m.width, want.outWidth);
    EXPECT_EQ(m.height, want.outHeight);
    for (const KnownSensor &k : kKnown)
        if (m.model.rfind(k.model, 0) == 0) {
            EXPECT_EQ(want.outWidth, k.width) << k.model << ": not its full resolution";
            EXPECT_EQ(want.outHeight, k.height) << k.model << ": not its full resolution";
            EXPECT_NE(m.tuning.find("adaptive contrast off"), std::string::npos) << m.tuning;
        }
    hal::CapturedFrame f;
    const hal::Error e = gCamera->capture(3000, &f);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(f.view.width, want.outWidth);
    EXPECT_EQ(f.view.height, want.outHeight);
    EXPECT_NE(f.source.find(std::to_string(want.mode.width) + "x" + std::to_string(want.mode.height)),
              std::string::npos)
        << f.source;
}
#endif

TEST(HilCamera, EveryFrameIsExposedAfterItWasAskedForWithItsControls)
{
    ASSERT_TRUE(gCamera);
    std::printf("camera: %s\n", gCamera->describe().c_str());
    uint32_t lastSeq = 0;
    for (int i = 0; i < 10; ++i) {
        const int64_t notBefore = gClock.monotonicMs() + 50;
        hal::CapturedFrame f;
        const hal::Error e = gCamera->capture({notBefore, 3000}, &f);
        ASSERT_TRUE(e.ok()) << e.message;
        std::printf(
            "frame %u: latency %lld us, stale %d, exposure %d us, gain %.3f, colour gains %.3f %.3f, lens %.3f\n",
            f.sequence, static_cast<long long>(f.latencyUs), f.staleFrames, f.controls.exposureUs,
            f.controls.analogueGain, f.controls.redGain, f.controls.blueGain, f.controls.lensPosition);
        EXPECT_GE(f.latencyUs, 0);
        EXPECT_GE(f.timestampMs, notBefore);
        EXPECT_LT(f.latencyUs, 200000) << "more than 200 ms after the instant: frames lost?";
        if (i > 0) { EXPECT_GT(f.sequence, lastSeq); }
        lastSeq = f.sequence;
        if (gLibcamera) { EXPECT_NEAR(f.controls.exposureUs, 8000, 800); }
        EXPECT_GT(f.view.width, 0);
    }
}

} // namespace

int main(int argc, char **argv)
{
    setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);
    const char *want = std::getenv("ICACAM_HIL_CAMERA");
    const std::string which = want ? want : "libcamera";
    hal::CameraControls controls{8000, 1.0, -1, -1, -1, -1, -1};
    if (which == "libcamera") {
#ifdef ICACAM_HAVE_LIBCAMERA
        hal::LibcameraOptions o;
        o.controls.exposureUs = 8000;
        o.controls.analogueGain = 1.0;
        auto csi = std::make_unique<hal::LibcameraCamera>(gClock, o);
        gCsi = csi.get();
        gCamera = std::move(csi);
        gLibcamera = true;
#endif
    } else {
#ifdef ICACAM_HAVE_V4L2
        struct stat st {};
        if (::stat(which.c_str(), &st) == 0) {
            hal::V4l2Options o;
            o.device = which;
            o.controls = controls;
            gCamera = std::make_unique<hal::V4l2Camera>(gClock, o);
        }
#endif
    }
    if (!gCamera) {
        std::fprintf(stderr, "hil_camera_test: no %s camera backend here: skipped\n", which.c_str());
        return 77;
    }
    if (const hal::Error e = gCamera->configure({vision::PixelFormat::Grey8, kMaxWidth, kMaxHeight}); !e.ok()) {
        if (e.code == hal::Errc::NotFound) {
            std::fprintf(stderr, "hil_camera_test: %s: skipped\n", e.message.c_str());
            return 77;
        }
        std::fprintf(stderr, "hil_camera_test: %s\n", e.message.c_str());
        return 1;
    }
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
