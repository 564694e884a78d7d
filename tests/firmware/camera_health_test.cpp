// The camera's health between presses: an idle probe finds a camera that went away before
// anyone presses the button, and a camera that was lost is ok again only once it delivers a
// frame, however often it configures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "firmware/camera_health.h"
#include "firmware/device.h"
#include "firmware/font5x7.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/scripted_light.h"
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

struct RecordingDisplay final : hal::Display {
    hal::MonoBitmap last;
    hal::Error show(const hal::MonoBitmap &p) override
    {
        last = p;
        return {};
    }
};

// A sensor that answers on its bus (configure() succeeds) and streams nothing: a CSI ribbon
// that lost its data lanes.
struct SilentSensor final : hal::Camera {
    hal::ManualClock &clock;
    int configures = 0, captures = 0;
    bool streams = true;
    explicit SilentSensor(hal::ManualClock &c) : clock(c) {}
    hal::Error configure(const hal::CameraFormat &) override
    {
        ++configures;
        return {};
    }
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override
    {
        ++captures;
        if (!streams) {
            clock.advance(req.timeoutMs);
            return hal::Error::make(hal::Errc::Timeout, "no frame within " + std::to_string(req.timeoutMs) + " ms");
        }
        static uint8_t pixels[16 * 16] = {};
        out->view = {hal::PixelFormat::Grey8, pixels, 16, 16, 16, sizeof pixels};
        out->timestampMs = clock.monotonicMs();
        out->latencyUs = 0;
        return {};
    }
};

} // namespace

TEST(CameraHealth, AnIdleProbeFindsACameraLostBetweenPresses)
{
    char t[] = "/tmp/icacam-health-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    fs::create_directories(dir + "/frames");
    {
        std::ofstream f(dir + "/frames/a.pgm", std::ios::binary);
        f << "P5\n32 32\n255\n" << std::string(32 * 32, char(100));
    }
    hal::ManualClock clock;
    hal::ScriptedLight light(clock);
    hal::FileCamera camera(clock, {dir + "/frames", 1, true, 0, {}, &light});
    hal::FileTrigger trigger(clock);
    hal::FileLed led(clock, &light);
    RecordingDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir + "/journal", 0).ok());
    friction::PaperModel model;
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 64;
    cfg.cameraMaxHeight = 64;
    cfg.cameraProbeMs = 5000;
    cfg.cameraRetryMs = 2000;
    fw::Device device({camera, trigger, led, display, serial, storage, clock}, cfg, model);
    ASSERT_TRUE(device.start().ok());
    EXPECT_EQ(device.camera().state(), fw::CameraHealth::State::Ok);

    fs::remove_all(dir + "/frames"); // the camera goes away while nobody measures
    clock.advance(4000);
    device.tick();
    EXPECT_EQ(device.camera().state(), fw::CameraHealth::State::Ok); // not probed yet
    clock.advance(1000);
    device.tick();
    EXPECT_EQ(device.camera().state(), fw::CameraHealth::State::Lost);
    const reading::FlatObject lost = serial.last("camera");
    ASSERT_TRUE(lost.find("camera")) << serial.out;
    EXPECT_EQ(lost.find("camera")->text, "lost");
    EXPECT_EQ(fw::readRow(display.last, 0), "icacam: no camera");

    fs::create_directories(dir + "/frames"); // back
    {
        std::ofstream f(dir + "/frames/a.pgm", std::ios::binary);
        f << "P5\n32 32\n255\n" << std::string(32 * 32, char(100));
    }
    clock.advance(2000);
    device.tick();
    EXPECT_EQ(serial.last("camera").find("camera")->text, "ok") << serial.out;
    EXPECT_EQ(fw::readRow(display.last, 0), "icacam  ready");
    fs::remove_all(dir);
}

TEST(CameraHealth, ALostCameraThatConfiguresButStreamsNothingStaysLost)
{
    hal::ManualClock clock;
    SilentSensor sensor(clock);
    fw::CameraHealth health(sensor, clock, {hal::PixelFormat::Grey8, 64, 64}, 2000, 5000, 500);
    ASSERT_TRUE(health.open());
    sensor.streams = false;
    clock.advance(5000);
    EXPECT_FALSE(health.poll()); // one probe timed out: not lost yet
    EXPECT_TRUE(health.poll());  // the second, at once, decides
    EXPECT_EQ(health.state(), fw::CameraHealth::State::Lost);
    // Retried many times: it configures every time, and is never reported ok.
    int changes = 0;
    for (int i = 0; i < 10; ++i) {
        clock.advance(2000);
        changes += health.poll() ? 1 : 0;
        EXPECT_EQ(health.state(), fw::CameraHealth::State::Lost) << i;
        EXPECT_FALSE(health.ready()) << i;
    }
    EXPECT_EQ(changes, 0);
    EXPECT_GE(sensor.configures, 10);
    EXPECT_NE(health.problem().find("configures but delivers no frame"), std::string::npos) << health.problem();
    sensor.streams = true; // the ribbon reseated
    clock.advance(2000);
    EXPECT_TRUE(health.poll());
    EXPECT_TRUE(health.ok());
}

TEST(CameraHealth, NoProbeWhileFramesFlow)
{
    hal::ManualClock clock;
    SilentSensor sensor(clock);
    fw::CameraHealth health(sensor, clock, {hal::PixelFormat::Grey8, 64, 64}, 2000, 5000, 500);
    ASSERT_TRUE(health.open());
    for (int i = 0; i < 10; ++i) {
        clock.advance(3000);
        hal::CapturedFrame f;
        health.onCapture(sensor.capture(500, &f), &f); // a measurement every 3 s
        health.poll();
    }
    EXPECT_EQ(sensor.captures, 10);
}
