// The libcamera backend where there is no camera (the build machines have no media
// devices): configure() answers NotFound with a clear message, capture() does not hang, and
// the program keeps running. With a camera attached (the board), it captures one frame.
#include <gtest/gtest.h>

#include <cstdlib>

#include "hal/file/clocks.h"
#include "hal/libcamera/libcamera_camera.h"

namespace {

using namespace icacam;

TEST(LibcameraCamera, NoCameraIsNotFoundOrCapturesOnTheBoard)
{
    setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);
    hal::SystemClock clock;
    hal::LibcameraCamera cam(clock, {});
    hal::Error e = cam.configure({hal::PixelFormat::Grey8, 4056, 3040});
    hal::CapturedFrame frame;
    if (e.code == hal::Errc::NotFound) {
        EXPECT_NE(e.message.find("no camera"), std::string::npos) << e.message;
        EXPECT_EQ(cam.capture(100, &frame).code, hal::Errc::NotFound); // tries again, no hang
        return;
    }
    ASSERT_TRUE(e.ok()) << e.message;
    e = cam.capture(3000, &frame);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_GT(frame.view.width, 0);
    EXPECT_NE(frame.view.data, nullptr);
}

TEST(LibcameraCamera, CaptureBeforeConfigureIsInvalid)
{
    hal::SystemClock clock;
    hal::LibcameraCamera cam(clock, {});
    hal::CapturedFrame frame;
    EXPECT_EQ(cam.capture(10, &frame).code, hal::Errc::Invalid);
}

} // namespace
