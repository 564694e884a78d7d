// Every frame measured is proven lit (firmware/device_capture.cpp): on the file HAL, a scripted
// LED ring (hal/file/scripted_light.h) that lights late, not at all or only for part of a frame
// lights the file camera's rows as a rolling shutter sees it; the device refuses such a frame,
// captures again, and says "LED ring not lit" when no frame is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
using test::RecordingSerial;

namespace {

struct RecordingDisplay final : hal::Display {
    hal::MonoBitmap last;
    hal::Error show(const hal::MonoBitmap &p) override
    {
        last = p;
        return {};
    }
};

// The camera reads its rows out over 30 ms; the ring settles for 20 ms before the capture.
struct Rig {
    std::string dir = makeDir();
    hal::ManualClock clock;
    hal::ScriptedLight light{clock};
    hal::FileCamera camera{clock, options(dir, &light)};
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    RecordingDisplay display;
    RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    std::unique_ptr<fw::Device> device;

    explicit Rig(const std::string &script, int attempts = 3)
    {
        std::ofstream f(dir + "/a.pgm", std::ios::binary);
        f << "P5\n64 64\n255\n" << std::string(64 * 64, char(140));
        f.close();
        EXPECT_TRUE(light.feed(script).ok());
        EXPECT_TRUE(storage.open(dir + "/journal", 0).ok());
        fw::Config cfg;
        cfg.n = 0.2;
        cfg.mmPerPx = 0.0125;
        cfg.cameraMaxWidth = 256;
        cfg.cameraMaxHeight = 256;
        cfg.ledSettleMs = 20;
        cfg.litAttempts = attempts;
        device = std::make_unique<fw::Device>(fw::DeviceHal{camera, trigger, led, display, serial, storage, clock}, cfg,
                                              model);
    }
    ~Rig() { fs::remove_all(dir); }
    static hal::FileCameraOptions options(const std::string &dir, const hal::ScriptedLight *light)
    {
        hal::FileCameraOptions o(dir, 1, true, 0, {}, light);
        o.readoutMs = 30;
        return o;
    }
    static std::string makeDir()
    {
        char t[] = "/tmp/icacam-lit-test-XXXXXX";
        return ::mkdtemp(t);
    }
    reading::FlatObject trigger1()
    {
        EXPECT_TRUE(device->start().ok());
        serial.in = "trigger\n";
        device->tick();
        return serial.last("result");
    }
};

} // namespace

TEST(LitCapture, ARingThatLightsAtOnceIsMeasuredFirstTime)
{
    Rig rig("ok\n");
    const reading::FlatObject r = rig.trigger1();
    ASSERT_TRUE(r.find("lit")) << rig.serial.out;
    EXPECT_EQ(r.find("lit")->text, "lit");
    EXPECT_EQ(r.find("unlit_frames")->number, 0);
    EXPECT_EQ(rig.serial.out.find("LED ring not lit"), std::string::npos) << rig.serial.out;
    EXPECT_FALSE(rig.led.isOn());
}

// The ring lights 25 ms after being switched on: the first frame, started 20 ms after, has its
// top rows dark. It is refused; the next one is lit top to bottom and measured.
TEST(LitCapture, ARingThatLightsLateIsRefusedUntilAFrameIsLitTopToBottom)
{
    Rig rig("late 25\n");
    const reading::FlatObject r = rig.trigger1();
    ASSERT_TRUE(r.find("lit")) << rig.serial.out;
    EXPECT_EQ(r.find("lit")->text, "lit");
    EXPECT_EQ(r.find("unlit_frames")->number, 1);
    EXPECT_EQ(r.find("source")->text, "a.pgm");
    EXPECT_EQ(rig.serial.out.find("LED ring not lit"), std::string::npos) << rig.serial.out;
}

// With one attempt, the late ring's frame is refused with the reason: lit at the bottom only.
TEST(LitCapture, AFrameLitAtTheBottomOnlyIsNeverMeasured)
{
    Rig rig("late 25\n", 1);
    const reading::FlatObject r = rig.trigger1();
    ASSERT_TRUE(r.find("status")) << rig.serial.out;
    EXPECT_EQ(r.find("status")->text, "error");
    EXPECT_EQ(r.find("lit")->text, "partly_lit");
    const reading::FlatObject e = rig.serial.last("error");
    ASSERT_TRUE(e.find("message")) << rig.serial.out;
    EXPECT_EQ(e.find("message")->text.rfind("LED ring not lit: lit at the bottom only", 0), 0u)
        << e.find("message")->text;
    EXPECT_EQ(fw::readRow(rig.display.last, 0), "#1 error");
}

// The ring flashes for 35 ms and goes dark: the first frame is lit at the top only, the
// others not at all. After led.lit_attempts frames: the error, and no image journaled.
TEST(LitCapture, ARingThatGoesDarkDuringTheFrameEndsInLedRingNotLit)
{
    Rig rig("flash 35\n");
    const reading::FlatObject r = rig.trigger1();
    ASSERT_TRUE(r.find("unlit_frames")) << rig.serial.out;
    EXPECT_EQ(r.find("unlit_frames")->number, 3);
    EXPECT_EQ(r.find("status")->text, "error");
    EXPECT_EQ(r.find("image")->text, "");
    const reading::FlatObject e = rig.serial.last("error");
    ASSERT_TRUE(e.find("message"));
    EXPECT_EQ(e.find("message")->text.rfind("LED ring not lit: not lit", 0), 0u) << e.find("message")->text;
    EXPECT_NE(e.find("message")->text.find("3 frames refused"), std::string::npos);
}

// The ring goes dark 49 ms after being switched on, as the last two of 64 rows start their
// exposure: every band but the last is lit throughout and the last keeps half its light, so
// only its strips see it. Refused, with one attempt an error.
TEST(LitCapture, ARingThatLightsAllButTheLastRowsIsRefused)
{
    Rig rig("flash 49\n", 1);
    const reading::FlatObject r = rig.trigger1();
    ASSERT_TRUE(r.find("lit")) << rig.serial.out;
    EXPECT_EQ(r.find("lit")->text, "partly_lit");
    EXPECT_EQ(r.find("status")->text, "error");
    const reading::FlatObject e = rig.serial.last("error");
    ASSERT_TRUE(e.find("message")) << rig.serial.out;
    EXPECT_EQ(e.find("message")->text.rfind("LED ring not lit: lit at the top only", 0), 0u) << e.find("message")->text;
}

TEST(LitCapture, ADeadRingIsReportedNotMeasured)
{
    Rig rig("dead\n");
    const reading::FlatObject r = rig.trigger1();
    ASSERT_TRUE(r.find("lit")) << rig.serial.out;
    EXPECT_EQ(r.find("lit")->text, "not_lit");
    EXPECT_NE(rig.serial.out.find("LED ring not lit"), std::string::npos);
    // The next press, the ring working again, is measured: nothing sticks.
    rig.serial.in = "trigger\n";
    rig.device->tick();
    EXPECT_EQ(rig.serial.last("result").find("lit")->text, "lit") << rig.serial.out;
}
