// Hardware in the loop: the real camera on the board (docs/hil-checklist.md). Every frame
// must have started its exposure at or after the instant it was asked for, with the
// controls the camera reports; exits 77 (skipped) where there is no camera, as on the
// build machines.
//   ICACAM_HIL_CAMERA=libcamera            a CSI camera (the default when libcamera has one)
//   ICACAM_HIL_CAMERA=/dev/icacam-camera   a V4L2 node
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <sys/stat.h>

#include "hal/file/clocks.h"
#ifdef ICACAM_HAVE_LIBCAMERA
#include "hal/libcamera/libcamera_camera.h"
#endif
#ifdef ICACAM_HAVE_V4L2
#include "hal/v4l2/v4l2_camera.h"
#endif

namespace {

using namespace icacam;

std::unique_ptr<hal::Camera> gCamera;
bool gLibcamera = false;
hal::SystemClock gClock;

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
        gCamera = std::make_unique<hal::LibcameraCamera>(gClock, o);
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
    if (const hal::Error e = gCamera->configure({hal::PixelFormat::Grey8, 4608, 3040}); !e.ok()) {
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
