// Hardware in the loop: the real camera on the board (docs/hil-checklist.md). Every frame
// must have started its exposure at or after the instant it was asked for, with the
// controls the camera reports; a CSI camera must deliver the luma at the sensor mode the
// backend's choice names (its full resolution for the sensors the product names) with the
// fixed tone curve; with the LED ring's line named (ICACAM_HIL_LED=GPIO27), the frames taken
// after the LED settled must be lit top to bottom by the photometric check
// (firmware/lit_frame.h), and a CSI camera's frames whose first rows were exposed before the
// LED came on must not pass it; exits 77 (skipped) where there is no camera, as on the
// build machines.
//   ICACAM_HIL_CAMERA=libcamera            a CSI camera (the default when libcamera has one)
//   ICACAM_HIL_CAMERA=/dev/icacam-camera   a V4L2 node
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "firmware/frame_luma.h"
#include "firmware/lit_frame.h"
#include "hal/file/clocks.h"
#ifdef ICACAM_HAVE_GPIOD
#include "hal/gpiod/gpiod_lines.h"
#endif
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
            EXPECT_NE(m.tuning.find("tone curve"), std::string::npos) << m.tuning;
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

#ifdef ICACAM_HAVE_GPIOD
bool lumaPlane(const hal::CapturedFrame &f, fw::LumaPlane *out)
{
    vision::LumaView v;
    if (fw::frameLuma(f.view, nullptr, 0, &v) != vision::ErrorCode::None) return false;
    *out = {v.data, v.width, v.height, v.stride, v.pixelStep};
    return true;
}

void printBands(const char *what, const fw::LitCheckResult &r)
{
    std::printf("%s: %s (%s); rise per band:", what, fw::litVerdictName(r.verdict), r.reason);
    for (int b = 0; b < r.bands; ++b) std::printf(" %.1f", double(r.rise[b]));
    std::printf("\n");
}

// The LED ring driven for real: the lit-frame check against the real sensor and light.
//   ICACAM_HIL_LED=GPIO27 (a line name or offset), ICACAM_HIL_LED_ACTIVE_LOW=1 when the
//   driver lights the ring on a low level, ICACAM_HIL_LED_SETTLE_MS (default 20).
TEST(HilCamera, FramesExposedUnderTheLedAreLitAndFramesAcrossItsEdgeAreNot)
{
    const char *line = std::getenv("ICACAM_HIL_LED");
    if (!line) GTEST_SKIP() << "set ICACAM_HIL_LED=GPIO27 (the LED ring's line) to drive the LED";
    hal::GpioLineSpec spec;
    hal::parseGpioLine(line, &spec);
    spec.activeLow = std::getenv("ICACAM_HIL_LED_ACTIVE_LOW") != nullptr;
    const char *settleText = std::getenv("ICACAM_HIL_LED_SETTLE_MS");
    const int settleMs = settleText ? std::atoi(settleText) : 20;
    hal::GpiodLed led;
    const hal::Error opened = led.open(spec, "icacam-hil");
    ASSERT_TRUE(opened.ok()) << opened.message;
    fw::LitFrameCheck check;
    hal::CapturedFrame f;
    fw::LumaPlane plane;

    // The LED-off reference.
    ASSERT_TRUE(led.set(false).ok());
    gClock.sleepMs(300);
    ASSERT_TRUE(gCamera->capture({gClock.monotonicMs(), 3000}, &f).ok());
    ASSERT_TRUE(lumaPlane(f, &plane));
    ASSERT_TRUE(check.setDarkReference(plane));

    // Frames exposed after the light settled: lit top to bottom, against the LED-off
    // reference alone and then with the first of them as the LED-on reference.
    ASSERT_TRUE(led.set(true).ok());
    const int64_t on = gClock.monotonicMs();
    for (int i = 0; i < 3; ++i) {
        hal::Error e = gCamera->capture({on + settleMs, 3000}, &f);
        ASSERT_TRUE(e.ok()) << e.message;
        ASSERT_TRUE(lumaPlane(f, &plane));
        const fw::LitCheckResult r = check.check(plane);
        printBands("lit", r);
        EXPECT_EQ(r.verdict, fw::LitVerdict::Lit) << r.reason << ": the LED ring does not light the view?";
        if (i == 0) { ASSERT_TRUE(check.setLitReference(plane)); }
    }

    // Across the LED's edge: ask for the first frame exposed after `ask`, switch the LED on
    // `lead` ms later. A frame whose first row's exposure ended before the LED came on has
    // dark rows at its top: the check must not call it lit. Only for a CSI camera, whose
    // exposure start is exact (a UVC camera's is a lower bound).
    for (int lead : {5, 15, 30, 60}) {
        ASSERT_TRUE(led.set(false).ok());
        gClock.sleepMs(300);
        const int64_t ask = gClock.monotonicMs();
        gClock.sleepMs(lead);
        ASSERT_TRUE(led.set(true).ok());
        const int64_t litAt = gClock.monotonicMs();
        ASSERT_TRUE(gCamera->capture({ask, 3000}, &f).ok());
        ASSERT_TRUE(lumaPlane(f, &plane));
        const fw::LitCheckResult r = check.check(plane);
        const int64_t firstRowEndMs = f.timestampMs + (f.exposureUs + 999) / 1000;
        std::printf("LED on %d ms after the ask; exposure start %+lld ms, first row's end %+lld ms from it: ", lead,
                    static_cast<long long>(f.timestampMs - litAt), static_cast<long long>(firstRowEndMs - litAt));
        printBands("edge", r);
        if (!gLibcamera) continue;
        if (firstRowEndMs + 1 < litAt) {
            EXPECT_NE(r.verdict, fw::LitVerdict::Lit) << "the top rows were exposed in the dark";
        } else if (f.timestampMs > litAt + settleMs) {
            EXPECT_EQ(r.verdict, fw::LitVerdict::Lit) << r.reason;
        }
    }
    EXPECT_TRUE(led.set(false).ok());
}
#endif

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
    if (const hal::Error e = gCamera->configure({hal::PixelFormat::Grey8, kMaxWidth, kMaxHeight}); !e.ok()) {
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
