// Setting the camera up over serial: `lens` and `focus` hold the lens and save it, `fetch`
// brings a snapshot to the PC over the line, aim mode asks for the newest picture.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "firmware/device.h"
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

struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

// The file camera with a focus motor: what it was told, whether the ring was lit while it
// focused, and the requests it had.
struct LensCamera final : hal::Camera {
    hal::FileCamera frames;
    const hal::LedRing &ring;
    double lens = -1;
    int lensCalls = 0;
    bool litWhileFocusing = false;
    std::vector<int64_t> notBefore;
    LensCamera(hal::ManualClock &clock, const std::string &dir, const hal::ScriptedLight *light,
               const hal::LedRing &led)
            : frames(clock, {dir, 1, true, 0, {}, light}), ring(led)
    {}
    hal::Error configure(const hal::CameraFormat &f) override { return frames.configure(f); }
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override
    {
        notBefore.push_back(req.notBeforeMs);
        return frames.capture(req, out);
    }
    hal::Result<hal::CameraControls> setControls(const hal::CameraControls &c) override
    {
        if (c.lensPosition >= 0) {
            lens = c.lensPosition;
            ++lensCalls;
        }
        return frames.setControls(c);
    }
    hal::Result<double> focusOnce(int) override
    {
        litWhileFocusing = ring.isOn();
        lens = 4.25;
        return {4.25, {}};
    }
};

struct Rig {
    std::string dir = makeDir();
    hal::ManualClock clock{1000};
    hal::ScriptedLight light{clock};
    hal::FileLed led{clock, &light};
    LensCamera camera{clock, dir + "/frames", &light, led};
    hal::FileTrigger trigger{clock};
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    fw::Config cfg;
    std::unique_ptr<fw::Device> device;

    Rig()
    {
        fs::create_directories(dir + "/frames");
        std::ofstream f(dir + "/frames/a.pgm", std::ios::binary);
        f << "P5\n48 40\n255\n" << std::string(48 * 40, char(150));
        f.close();
        EXPECT_TRUE(storage.open(dir + "/journal", 0).ok());
        cfg.n = 0.2;
        cfg.mmPerPx = 0.0125;
        cfg.cameraMaxWidth = 128;
        cfg.cameraMaxHeight = 128;
        device = std::make_unique<fw::Device>(fw::DeviceHal{camera, trigger, led, display, serial, storage, clock}, cfg,
                                              model);
        EXPECT_TRUE(device->start().ok());
    }
    ~Rig() { fs::remove_all(dir); }
    static std::string makeDir()
    {
        char t[] = "/tmp/icacam-setup-XXXXXX";
        return ::mkdtemp(t);
    }
    void say(const std::string &line)
    {
        serial.in = line + "\n";
        device->tick();
    }
};

std::string fromBase64(const std::string &s)
{
    const std::string a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    uint32_t acc = 0;
    int bits = 0;
    for (char c : s) {
        if (c == '=') break;
        acc = acc << 6 | uint32_t(a.find(c));
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(char((acc >> bits) & 0xff));
        }
    }
    return out;
}

} // namespace

TEST(SetupCommands, LensIsHeldSavedAndHeldAgainAfterARestart)
{
    Rig rig;
    rig.say("lens 6.7");
    const reading::FlatObject r = rig.serial.last("lens");
    ASSERT_TRUE(r.find("lens_position")) << rig.serial.out;
    EXPECT_EQ(r.find("lens_position")->number, 6.7);
    EXPECT_EQ(r.find("by")->text, "set");
    EXPECT_EQ(rig.camera.lens, 6.7);
    EXPECT_NE(rig.storage.read("settings.conf").value.find("lens_position = 6.7"), std::string::npos);
    rig.say("get lens_position");
    EXPECT_EQ(rig.serial.last("settings").find("lens_position")->number, 6.7);

    rig.camera.lens = -1;
    fw::Device again({rig.camera, rig.trigger, rig.led, rig.display, rig.serial, rig.storage, rig.clock}, rig.cfg,
                     rig.model);
    ASSERT_TRUE(again.start().ok());
    EXPECT_EQ(rig.camera.lens, 6.7); // the saved lens, held again
    rig.say("lens -1");
    EXPECT_EQ(rig.serial.last("error").find("code")->text, "bad_argument");
}

TEST(SetupCommands, FocusRunsUnderTheRingAndSavesWhereItEnded)
{
    Rig rig;
    rig.say("{\"cmd\":\"focus\",\"id\":\"f1\"}");
    const reading::FlatObject r = rig.serial.last("lens");
    ASSERT_TRUE(r.find("lens_position")) << rig.serial.out;
    EXPECT_EQ(r.find("lens_position")->number, 4.25);
    EXPECT_EQ(r.find("by")->text, "autofocus");
    EXPECT_EQ(r.find("tag")->text, "f1");
    EXPECT_TRUE(rig.camera.litWhileFocusing);
    EXPECT_FALSE(rig.led.isOn());
    EXPECT_NE(rig.storage.read("settings.conf").value.find("lens_position = 4.25"), std::string::npos);
}

TEST(SetupCommands, ACameraWithoutALensSaysSo)
{
    char t[] = "/tmp/icacam-nolens-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    {
        std::ofstream f(dir + "/a.pgm", std::ios::binary);
        f << "P5\n8 8\n255\n" << std::string(64, char(90));
    }
    hal::ManualClock clock;
    hal::FileCameraOptions fixed{dir, 1, true};
    fixed.fixedFocus = true;
    hal::FileCamera camera(clock, fixed);
    hal::FileTrigger trigger(clock);
    hal::FileLed led(clock);
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir + "/journal", 0).ok());
    friction::PaperModel model;
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 64;
    cfg.cameraMaxHeight = 64;
    fw::Device device({camera, trigger, led, display, serial, storage, clock}, cfg, model);
    ASSERT_TRUE(device.start().ok());
    serial.in = "lens 3\nfocus\n";
    device.tick();
    EXPECT_NE(serial.out.find("\"code\":\"lens_failed\",\"message\":\"this camera has no lens control"),
              std::string::npos)
        << serial.out;
    EXPECT_NE(serial.out.find("\"code\":\"focus_failed\",\"message\":\"this camera has no autofocus"),
              std::string::npos)
        << serial.out;
    EXPECT_FALSE(led.isOn());
    fs::remove_all(dir);
}

TEST(SetupCommands, ASnapshotIsFetchedOverSerialByteForByte)
{
    Rig rig;
    rig.clock.advance(100);
    rig.say("snapshot");
    const reading::FlatObject snap = rig.serial.last("snapshot");
    ASSERT_TRUE(snap.find("image")) << rig.serial.out;
    const std::string name = snap.find("image")->text;
    rig.serial.out.clear();
    rig.say("fetch " + name);
    std::string bytes;
    size_t at = 0;
    int lines = 0;
    while (at < rig.serial.out.size()) {
        const size_t nl = rig.serial.out.find('\n', at);
        reading::FlatObject o;
        ASSERT_TRUE(reading::parseFlatObject(rig.serial.out.substr(at, nl - at), &o).empty());
        at = nl + 1;
        if (o.find("type")->text == "data") {
            EXPECT_EQ(o.find("i")->number, lines++);
            bytes += fromBase64(o.find("b64")->text);
        }
    }
    EXPECT_GT(lines, 1);
    EXPECT_EQ(rig.serial.last("file").find("bytes")->number, double(bytes.size()));
    EXPECT_EQ(bytes, rig.storage.read(name).value);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    rig.say("fetch ../journal.jsonl");
    EXPECT_EQ(rig.serial.last("error").find("code")->text, "bad_argument");
    rig.say("fetch snap-999999-1.png");
    EXPECT_EQ(rig.serial.last("error").find("code")->text, "fetch_failed");
}

TEST(SetupCommands, AimAsksForThePictureExposedNowNotTheOldestQueued)
{
    Rig rig;
    rig.say("aim 5");
    rig.camera.notBefore.clear();
    for (int i = 0; i < 4; ++i) {
        rig.clock.advance(300);
        const int64_t now = rig.clock.monotonicMs();
        rig.device->tick();
        ASSERT_EQ(rig.camera.notBefore.size(), size_t(i + 1)) << rig.serial.out;
        EXPECT_GE(rig.camera.notBefore.back(), now) << i;
    }
    rig.say("aim off");
}
