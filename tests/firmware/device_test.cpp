// The device loop on the file-backed HAL with a manual clock: errors become words on the
// display and error lines on serial, never a hang or a crash.
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
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;
using test::RecordingSerial;

namespace {

// A display stand-in that records what the device showed.
struct RecordingDisplay final : hal::Display {
    hal::MonoBitmap last;
    hal::Error show(const hal::MonoBitmap &p) override
    {
        last = p;
        return {};
    }
    std::string row(int r) const { return fw::readRow(last, r); }
};

struct Rig {
    std::string dir;
    hal::ManualClock clock;
    hal::FileCamera camera;
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock};
    RecordingDisplay display;
    RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    std::unique_ptr<fw::Device> device;

    explicit Rig(const std::string &frames, uint64_t quota = 0, bool loop = false)
            : dir(makeDir()), camera(clock, {frames.empty() ? dir : frames, 1, loop, 0, {}})
    {
        EXPECT_TRUE(storage.open(dir + "/journal", quota).ok());
        fw::Config cfg;
        cfg.n = 0.2;
        cfg.mmPerPx = 0.0125;
        cfg.cameraMaxWidth = 256;
        cfg.cameraMaxHeight = 256;
        cfg.captureTimeoutMs = 700;
        device = std::make_unique<fw::Device>(fw::DeviceHal{camera, trigger, led, display, serial, storage, clock}, cfg,
                                              model);
    }
    ~Rig() { fs::remove_all(dir); }
    static std::string makeDir()
    {
        char t[] = "/tmp/icacam-dev-test-XXXXXX";
        return ::mkdtemp(t);
    }
};

void writeGrey(const std::string &path, int w, int h, uint8_t v)
{
    std::ofstream f(path, std::ios::binary);
    f << "P5\n" << w << " " << h << "\n255\n" << std::string(size_t(w * h), char(v));
}

} // namespace

TEST(Device, CameraTimeoutIsShownInWordsAndJournaled)
{
    char t[] = "/tmp/icacam-frames-XXXXXX";
    const std::string frames = ::mkdtemp(t);
    {
        std::ofstream(frames + "/list.txt") << "!timeout\n";
    }
    Rig rig(frames + "/list.txt");
    ASSERT_TRUE(rig.device->start().ok());
    EXPECT_NE(rig.serial.out.find("\"type\":\"hello\""), std::string::npos);
    EXPECT_EQ(rig.display.row(0), "icacam  ready");
    rig.serial.in = "trigger\n";
    const int64_t t0 = rig.clock.monotonicMs();
    rig.device->tick();
    EXPECT_LE(rig.clock.monotonicMs() - t0, 700 + 20 + 1); // the watchdog bounds the wait
    EXPECT_NE(rig.serial.out.find("\"code\":\"measurement_failed\""), std::string::npos);
    EXPECT_EQ(rig.display.row(0), "#1 error");
    EXPECT_EQ(rig.display.row(2), "camera timeout: no");
    EXPECT_FALSE(rig.led.isOn());
    EXPECT_EQ(fw::Journal::checkLine(rig.storage.read(fw::Journal::kFile)
                                         .value.substr(0, rig.storage.read(fw::Journal::kFile).value.size() - 1)),
              1);
    fs::remove_all(frames);
}

TEST(Device, NoSpecimenAndFullDiskAreWordsNotCrashes)
{
    Rig rig("", 4000); // a blank frame, and a card too small for its image
    writeGrey(rig.dir + "/blank.pgm", 200, 150, 30);
    ASSERT_TRUE(rig.device->start().ok());
    rig.trigger.feed("press 80\n");
    rig.device->tick();
    rig.clock.advance(100);
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("\"type\":\"result\",\"id\":1"), std::string::npos) << rig.serial.out;
    EXPECT_NE(rig.serial.out.find("\"status\":\"error\""), std::string::npos);
    EXPECT_NE(rig.serial.out.find("\"code\":\"storage\""), std::string::npos);
    EXPECT_EQ(rig.display.row(0), "#1 error");
    EXPECT_FALSE(rig.display.row(2).empty());
    rig.serial.in = "status\n";
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("\"type\":\"status\""), std::string::npos);
}

TEST(Device, SettingsSurviveARestart)
{
    Rig rig("");
    writeGrey(rig.dir + "/a.pgm", 64, 64, 0);
    ASSERT_TRUE(rig.device->start().ok());
    rig.serial.in = "set n 0.37\nset journal.dir /\n{\"cmd\":\"get\",\"key\":\"n\",\"id\":\"g\"}\n";
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("\"code\":\"bad_argument\""), std::string::npos);
    EXPECT_NE(rig.serial.out.find("{\"type\":\"settings\",\"n\":0.37,\"tag\":\"g\"}"), std::string::npos);
    fw::Device again({rig.camera, rig.trigger, rig.led, rig.display, rig.serial, rig.storage, rig.clock}, fw::Config{},
                     rig.model);
    ASSERT_TRUE(again.start().ok());
    EXPECT_DOUBLE_EQ(again.config().n, 0.37);
}

TEST(Device, LongPressAimsASecondShowsSettingsAndBounceDoesNotMeasure)
{
    Rig rig("", 0, true); // the live view takes a picture every 250 ms
    writeGrey(rig.dir + "/a.pgm", 64, 64, 0);
    ASSERT_TRUE(rig.device->start().ok());
    rig.trigger.feed("0 down\n3 up\n6 down\n9 up\n"); // bounce only
    rig.clock.advance(20);
    rig.device->tick();
    EXPECT_EQ(rig.serial.out.find("\"type\":\"result\""), std::string::npos);
    rig.trigger.feed("press 2000\n");
    rig.clock.advance(1);
    rig.device->tick();
    rig.clock.advance(1600);
    rig.device->tick(); // held: aim mode, the ring on and the live picture
    EXPECT_NE(rig.serial.out.find("\"type\":\"aim\",\"state\":\"on\""), std::string::npos) << rig.serial.out;
    EXPECT_TRUE(rig.led.isOn());
    EXPECT_EQ(rig.display.row(0).substr(rig.display.row(0).find('F'), 2), "F0"); // a blank frame: no focus
    rig.clock.advance(1000);
    rig.device->tick(); // released: aiming goes on
    rig.trigger.feed("press 2000\n");
    rig.clock.advance(1);
    rig.device->tick();
    rig.clock.advance(1600);
    rig.device->tick(); // held again: the settings page, aiming over
    EXPECT_EQ(rig.display.row(0), "settings");
    EXPECT_EQ(rig.display.row(2), "n     0.2000");
    EXPECT_FALSE(rig.led.isOn());
    rig.clock.advance(1000);
    rig.device->tick();
    EXPECT_EQ(rig.serial.out.find("\"type\":\"result\""), std::string::npos);
    EXPECT_EQ(rig.led.switchCount(), 2);
}

TEST(Device, FinalHeightIsALiveJournaledKeyCheckedAgainstTheInitialHeight)
{
    // specimen.h_final_mm feeds the reduction-aware model (docs/loop-method.md): settable over
    // serial, kept across restarts, and never above the initial height.
    Rig rig("");
    writeGrey(rig.dir + "/a.pgm", 64, 64, 0);
    ASSERT_TRUE(rig.device->start().ok());
    rig.serial.in = "set h_final_mm 7.3\nset h_final_mm 15\nget h_final_mm\n";
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("{\"type\":\"settings\",\"h_final_mm\":7.3}"), std::string::npos) << rig.serial.out;
    EXPECT_NE(rig.serial.out.find("must be below specimen.h0_mm"), std::string::npos) << rig.serial.out;
    EXPECT_DOUBLE_EQ(rig.device->config().hFinalMm, 7.3); // the bad value changed nothing
    fw::Device again({rig.camera, rig.trigger, rig.led, rig.display, rig.serial, rig.storage, rig.clock}, fw::Config{},
                     rig.model);
    ASSERT_TRUE(again.start().ok());
    EXPECT_DOUBLE_EQ(again.config().hFinalMm, 7.3);
    // A result record names the final height it was measured with and the model.
    rig.serial.out.clear();
    rig.serial.in = "trigger\n";
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("\"h_final_mm\":7.3"), std::string::npos) << rig.serial.out;
    EXPECT_NE(rig.serial.out.find("\"model\":\"paper\""), std::string::npos) << rig.serial.out;
}

// The imaging controls set in the config reach the camera, and what the camera reports for
// the frame is journaled with the result, with the capture's latency.
TEST(Device, ConfiguredImagingControlsAreJournaledWithEachResult)
{
    fw::Config parsed;
    const auto issues = fw::parseConfig("[specimen]\nn = 0.2\n[calibration]\nmm_per_px = 0.0125\n"
                                        "[camera]\nframes = x\nexposure_us = 12000\nanalogue_gain = 2.5\n"
                                        "red_gain = 1.9\nblue_gain = 1.4\nlens_position = 3.5\nsharpness = 0\n"
                                        "noise_reduction = off\n[display]\ndir = d\n[serial]\nlink = l\n"
                                        "[journal]\ndir = j\n",
                                        &parsed);
    ASSERT_TRUE(issues.empty()) << issues.front().message;
    const hal::CameraControls asked = fw::cameraControlsOf(parsed);
    EXPECT_EQ(asked.noiseReduction, 0);
    Rig rig("");
    writeGrey(rig.dir + "/a.pgm", 64, 64, 0);
    hal::FileCamera camera(rig.clock, {rig.dir, 1, false, 0, asked});
    fw::Config cfg = rig.device->config();
    cfg.ledSettleMs = 25;
    fw::Device device({camera, rig.trigger, rig.led, rig.display, rig.serial, rig.storage, rig.clock}, cfg, rig.model);
    ASSERT_TRUE(device.start().ok());
    rig.serial.in = "trigger\n";
    device.tick();
    const reading::FlatObject r = rig.serial.last("result");
    ASSERT_TRUE(r.find("exposure_us")) << rig.serial.out;
    EXPECT_EQ(r.find("exposure_us")->number, 12000);
    EXPECT_EQ(r.find("gain")->number, 2.5);
    EXPECT_EQ(r.find("red_gain")->number, 1.9);
    EXPECT_EQ(r.find("blue_gain")->number, 1.4);
    EXPECT_EQ(r.find("lens_position")->number, 3.5);
    EXPECT_EQ(r.find("latency_us")->number, 0);          // the file camera starts when asked
    EXPECT_EQ(r.find("trigger_latency_ms")->number, 25); // the LED's settle time
    // The journal holds the same line; `status` the controls of the last frame.
    EXPECT_NE(rig.storage.read(fw::Journal::kFile).value.find("\"exposure_us\":12000"), std::string::npos);
    rig.serial.in = "status\n";
    device.tick();
    const reading::FlatObject st = rig.serial.last("status");
    ASSERT_TRUE(st.find("camera_controls"));
    EXPECT_EQ(st.find("camera_controls")->text,
              "exposure_us 12000 gain 2.500 red_gain 1.900 blue_gain 1.400 lens_position 3.500");
    EXPECT_EQ(st.find("camera_latency_us")->number, 0);
}

// A camera missing at start: the device runs, says so on the display, in `hello` and in
// `status`, refuses to measure with a reason, and measures once the camera appears.
TEST(Device, MissingCameraIsShownAndMeasuringStartsWhenItAppears)
{
    Rig rig(""); // the frame folder is empty: the file camera has nothing to open
    ASSERT_TRUE(rig.device->start().ok());
    EXPECT_NE(rig.serial.out.find("\"camera\":\"missing\""), std::string::npos) << rig.serial.out;
    EXPECT_EQ(rig.display.row(0), "icacam: no camera");
    rig.serial.out.clear();
    rig.serial.in = "status\n";
    rig.device->tick();
    const reading::FlatObject st = rig.serial.last("status");
    ASSERT_TRUE(st.find("camera"));
    EXPECT_EQ(st.find("camera")->text, "missing");
    EXPECT_NE(st.find("camera_problem")->text.find("no images"), std::string::npos);
    rig.serial.in = "trigger\n";
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("camera missing"), std::string::npos) << rig.serial.out;
    EXPECT_FALSE(rig.led.isOn());

    writeGrey(rig.dir + "/a.pgm", 64, 64, 0); // the camera appears
    rig.serial.out.clear();
    rig.clock.advance(rig.device->config().cameraRetryMs);
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("\"type\":\"camera\",\"camera\":\"ok\""), std::string::npos) << rig.serial.out;
    EXPECT_EQ(rig.display.row(0), "icacam  ready");
    rig.serial.in = "trigger\n";
    rig.device->tick();
    const reading::FlatObject r = rig.serial.last("result");
    ASSERT_TRUE(r.find("source")) << rig.serial.out;
    EXPECT_EQ(r.find("source")->text, "a.pgm");
}
