// The device with a camera calibration file and the reference-disc scale check, through the
// file-backed HAL: frames rendered by the host renderer through a tilted, distorting camera
// (host_tools/calibration_renderer), the calibration read from a file like on the device.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "calibration/calibration_file.h"
#include "firmware/device.h"
#include "firmware/device_calibration.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/scripted_light.h"
#include "host_tools/calibration_renderer.h"
#include "host_tools/model_inverse.h"
#include "reading/record_line.h"
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;
using test::RecordingSerial;

namespace {

struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

std::string text(const reading::FlatObject &o, const char *key)
{
    const reading::JsonField *f = o.find(key);
    return f ? f->text : "";
}
double number(const reading::FlatObject &o, const char *key)
{
    const reading::JsonField *f = o.find(key);
    return f && f->type == reading::JsonField::Type::Number ? f->number : NAN;
}

// A folder with frames, a calibration file and a journal; a device on them.
struct Rig {
    fs::path dir;
    hal::ManualClock clock;
    hal::ScriptedLight light{clock}; // the file LED lights the file camera's frames
    std::unique_ptr<hal::FileCamera> camera;
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    NullDisplay display;
    RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    std::unique_ptr<fw::Device> device;
    fw::Config cfg;

    Rig()
    {
        char t[] = "/tmp/icacam-devcal-XXXXXX";
        dir = ::mkdtemp(t);
        fs::create_directories(dir / "frames");
        cfg.n = 0.2;
        cfg.cameraMaxWidth = 1600;
        cfg.cameraMaxHeight = 1200;
        cfg.baseDir = dir.string();
    }
    ~Rig() { fs::remove_all(dir); }
    void frame(const std::string &name, const cv::Mat &img) { cv::imwrite((dir / "frames" / name).string(), img); }
    bool start()
    {
        camera = std::make_unique<hal::FileCamera>(
            clock, hal::FileCameraOptions{(dir / "frames").string(), 1, false, 0, {}, &light});
        EXPECT_TRUE(storage.open((dir / "journal").string()).ok());
        device = std::make_unique<fw::Device>(fw::DeviceHal{*camera, trigger, led, display, serial, storage, clock},
                                              cfg, model);
        return device->start().ok();
    }
    void say(const std::string &line)
    {
        serial.in += line + "\n";
        device->tick();
    }
};

calibration::CalibrationFile fileFor(const host::CameraModel &cam)
{
    calibration::CalibrationFile c;
    c.plane = host::toPlaneCalibration(cam);
    c.imageWidth = cam.width, c.imageHeight = cam.height;
    c.board = "chessboard:9x7:1.4";
    return c;
}

// An untilted, undistorted camera 60 mm above the fixture: 0.015 mm/px on the fixture.
host::CameraModel straightCamera()
{
    return host::CameraModel{};
}

} // namespace

TEST(DeviceCalibration, StartUpNamesWhatIsWrongWithTheFile)
{
    Rig rig;
    fw::DeviceCalibration cal;
    rig.cfg.calibrationFile = "missing.cal";
    EXPECT_NE(
        fw::loadDeviceCalibration(rig.cfg, &cal).find("cannot read calibration '" + (rig.dir / "missing.cal").string()),
        std::string::npos);
    {
        std::ofstream(rig.dir / "other.cal") << "format = something-else-2\n";
    }
    rig.cfg.calibrationFile = "other.cal";
    EXPECT_NE(fw::loadDeviceCalibration(rig.cfg, &cal).find("unknown format 'something-else-2'"), std::string::npos);
    host::CameraModel big = straightCamera();
    big.width = 2028, big.height = 1520;
    ASSERT_EQ(calibration::writeCalibrationFile((rig.dir / "big.cal").string(), fileFor(big)), "");
    rig.cfg.calibrationFile = (rig.dir / "big.cal").string(); // absolute paths are taken as they are
    const std::string e = fw::loadDeviceCalibration(rig.cfg, &cal);
    EXPECT_NE(e.find("is for 2028x1520 images, larger than the camera's largest frame"), std::string::npos) << e;
    EXPECT_FALSE(cal.present);
    // The device refuses to start on it (icacam-fw --check reports it first, exit 78).
    EXPECT_FALSE(rig.start());
}

TEST(DeviceCalibration, MeasuresInTheEndFacePlaneAndJournalsWhichCalibration)
{
    Rig rig;
    const host::CameraModel cam = host::exampleTiltedCamera();
    const host::BoardPhotoRenderer r(cam);
    ASSERT_EQ(calibration::writeCalibrationFile((rig.dir / "cam.cal").string(), fileFor(cam)), "");
    host::EndFaceScene s;
    const double n = 0.2, u = host::uForMu(friction::PaperModel(), 0.15, n);
    s.rOuterMm = 6.85 - 0.95 * u, s.rInnerMm = s.rOuterMm - u;
    s.rMaxMm = 5.0 * std::sqrt(2.0) * (1.008 + 0.034 * u);
    rig.frame("a.png", r.endFace(s, 0.4, -0.3, 7.5, 0.9, 2.0, 5));
    rig.frame("b.png", cv::Mat(600, 800, CV_8U, cv::Scalar(90))); // another camera's size
    rig.cfg.calibrationFile = "cam.cal";                          // no mm_per_px: the calibration scales
    rig.cfg.h0Mm = 15, rig.cfg.hFinalMm = 7.5;                    // end face 7.5 mm above the fixture
    ASSERT_TRUE(rig.start());
    rig.say("{\"cmd\":\"trigger\",\"id\":\"t1\"}"); // the longest record: a value, a calibration, a tag
    const reading::FlatObject a = rig.serial.last("result");
    // No check flag: ok, whatever the tolerance decision (the paper's own 3 % error alone nears it).
    EXPECT_EQ(text(a, "status"), "ok") << rig.serial.out;
    EXPECT_EQ(text(a, "flags"), "") << rig.serial.out;
    EXPECT_FALSE(text(a, "decision").empty()) << rig.serial.out;
    EXPECT_FALSE(text(a, "advice").empty()) << rig.serial.out;
    EXPECT_LE(std::fabs(number(a, "mu") - friction::PaperModel().estimate({s.rOuterEqMm() - s.rInnerEqMm(), n}).mu),
              2 * number(a, "mu_sigma"));
    const double muTrue = friction::PaperModel().estimate({s.rOuterEqMm() - s.rInnerEqMm(), n}).mu;
    EXPECT_NEAR(number(a, "mu"), muTrue, 0.004);
    EXPECT_EQ(text(a, "calibration"), "cam.cal");
    EXPECT_DOUBLE_EQ(number(a, "plane_height_mm"), 7.5);
    rig.say("trigger");
    const reading::FlatObject b = rig.serial.last("result");
    EXPECT_EQ(text(b, "status"), "error");
    EXPECT_EQ(text(b, "message"),
              "calibration 'cam.cal': frame is 800x600 but the calibration is for 1456x1088 images");
    // Both are in the journal with the calibration's name, and recovery can read them back.
    const std::string journal = rig.storage.read(fw::Journal::kFile).value;
    EXPECT_EQ(fw::Journal::checkLine(journal.substr(0, journal.find('\n'))), 1);
    fw::Journal again(rig.storage, 8);
    fw::JournalRecovery rec;
    ASSERT_TRUE(again.recover(&rec).ok());
    EXPECT_EQ(rec.records, 2);
    EXPECT_EQ(rec.cutBytes, 0u);
    EXPECT_NE(journal.find("\"calibration\":\"cam.cal\",\"plane_height_mm\":7.5"), std::string::npos) << journal;
}

TEST(DeviceCalibration, SetOverSerialIsCheckedAndSurvivesARestart)
{
    Rig rig;
    ASSERT_EQ(calibration::writeCalibrationFile((rig.dir / "cam.cal").string(), fileFor(straightCamera())), "");
    rig.frame("a.png", cv::Mat(64, 64, CV_8U, cv::Scalar(0)));
    rig.cfg.mmPerPx = 0.015;
    ASSERT_TRUE(rig.start());
    rig.say("set calibration_file nowhere.cal");
    EXPECT_NE(rig.serial.out.find("\"code\":\"bad_argument\",\"message\":\"calibration.file: cannot read calibration"),
              std::string::npos)
        << rig.serial.out;
    rig.say("set calibration_file cam.cal");
    EXPECT_NE(rig.serial.out.find("{\"type\":\"settings\",\"calibration_file\":\"cam.cal\"}"), std::string::npos)
        << rig.serial.out;
    rig.say("get calibration.file");
    EXPECT_NE(rig.serial.out.rfind("{\"type\":\"settings\",\"calibration_file\":\"cam.cal\"}"),
              rig.serial.out.find("cam.cal\"}"));
    fw::Device again({*rig.camera, rig.trigger, rig.led, rig.display, rig.serial, rig.storage, rig.clock}, rig.cfg,
                     rig.model);
    ASSERT_TRUE(again.start().ok());
    EXPECT_EQ(again.config().calibrationFile, "cam.cal");
    rig.say("set calibration_file none");
    EXPECT_NE(rig.serial.out.find("{\"type\":\"settings\",\"calibration_file\":\"\"}"), std::string::npos)
        << rig.serial.out;
}

TEST(ScaleCheck, ReferenceDiscPassesAtTheRightScaleAndFailsAtAWrongOne)
{
    // Through the tilted, distorting camera with its calibration: a 12 mm dark disc.
    {
        Rig rig;
        const host::CameraModel cam = host::exampleTiltedCamera();
        const host::BoardPhotoRenderer r(cam);
        ASSERT_EQ(calibration::writeCalibrationFile((rig.dir / "cam.cal").string(), fileFor(cam)), "");
        // The same calibration from a camera that sat 2 % farther: every length 2 % off.
        host::CameraModel moved = cam;
        moved.fixtureTvec *= 1.02;
        ASSERT_EQ(calibration::writeCalibrationFile((rig.dir / "moved.cal").string(), fileFor(moved)), "");
        for (int i = 0; i < 3; ++i)
            rig.frame("disc" + std::to_string(i) + ".png", r.disc(12, 0.5, -0.4, 0, 40, 200, 0.9, 2.0, uint32_t(i)));
        rig.cfg.calibrationFile = "cam.cal";
        ASSERT_TRUE(rig.start());
        rig.say("scalecheck 12");
        const reading::FlatObject a = rig.serial.last("scalecheck");
        EXPECT_EQ(text(a, "status"), "pass") << rig.serial.out;
        std::printf("scale check, calibrated: ratio %.7f\n", number(a, "ratio"));
        EXPECT_NEAR(number(a, "ratio"), 1, 0.002);
        EXPECT_EQ(text(a, "calibration"), "cam.cal");
        rig.say("set calibration_file moved.cal");
        rig.say("{\"cmd\":\"scalecheck\",\"diameter_mm\":12,\"tolerance_pct\":0.5,\"id\":\"s2\"}");
        const reading::FlatObject b = rig.serial.last("scalecheck");
        EXPECT_EQ(text(b, "status"), "fail");
        EXPECT_EQ(text(b, "tag"), "s2");
        std::printf("scale check, calibration 2 %% off: ratio %.7f: %s\n", number(b, "ratio"),
                    text(b, "message").c_str());
        EXPECT_NE(text(b, "message").find("scale off by +2.0"), std::string::npos) << text(b, "message");
        EXPECT_NE(text(b, "message").find("check the calibration"), std::string::npos);
        // Journaled like a measurement, and `results` gives it back.
        const std::string journal = rig.storage.read(fw::Journal::kFile).value;
        EXPECT_NE(journal.find("\"type\":\"scalecheck\",\"id\":2"), std::string::npos) << journal;
        rig.say("results 2");
        EXPECT_NE(rig.serial.out.rfind("{\"type\":\"scalecheck\",\"id\":2"), std::string::npos);
        // A frame with no disc: a clear error, not a ratio.
        rig.frame("disc2.png", cv::Mat(cam.height, cam.width, CV_8U, cv::Scalar(200)));
        rig.say("scalecheck 12");
        const reading::FlatObject c = rig.serial.last("scalecheck");
        EXPECT_EQ(text(c, "status"), "error");
        EXPECT_FALSE(c.find("ratio"));
        EXPECT_NE(text(c, "message").find("no reference disc in view"), std::string::npos) << text(c, "message");
    }
    // A 1 mm thick disc: its edge is in its top face, 1 mm nearer the camera. Declared, it
    // passes; measured as if it lay in the fixture's plane, it reads 1.6 % large.
    {
        Rig rig;
        const host::CameraModel cam = host::exampleTiltedCamera();
        const host::BoardPhotoRenderer r(cam);
        ASSERT_EQ(calibration::writeCalibrationFile((rig.dir / "cam.cal").string(), fileFor(cam)), "");
        for (int i = 0; i < 2; ++i)
            rig.frame("thick" + std::to_string(i) + ".png",
                      r.disc(10, -0.6, 0.3, 1.0, 45, 190, 0.9, 2.0, uint32_t(20 + i)));
        rig.cfg.calibrationFile = "cam.cal";
        ASSERT_TRUE(rig.start());
        rig.say("scalecheck 10 0.5 1");
        const reading::FlatObject a = rig.serial.last("scalecheck");
        EXPECT_EQ(text(a, "status"), "pass") << rig.serial.out;
        rig.say("scalecheck 10 0.5");
        const reading::FlatObject b = rig.serial.last("scalecheck");
        std::printf("scale check, 1 mm disc: ratio %.7f with its thickness, %.7f without\n", number(a, "ratio"),
                    number(b, "ratio"));
        EXPECT_EQ(text(b, "status"), "fail");
        EXPECT_NE(text(b, "message").find("scale off by +1."), std::string::npos) << text(b, "message");
    }
    // Without a calibration: mm_per_px right, then 2 % wrong; a bright disc this time.
    {
        Rig rig;
        const host::BoardPhotoRenderer r(straightCamera()); // 0.015 mm/px on the fixture
        for (int i = 0; i < 2; ++i)
            rig.frame("disc" + std::to_string(i) + ".png", r.disc(10, -1, 0.5, 0, 210, 60, 1.0, 2.0, uint32_t(i)));
        rig.cfg.mmPerPx = 0.015;
        ASSERT_TRUE(rig.start());
        rig.say("scalecheck 10 0.5");
        const reading::FlatObject a = rig.serial.last("scalecheck");
        EXPECT_EQ(text(a, "status"), "pass") << rig.serial.out;
        EXPECT_NEAR(number(a, "ratio"), 1, 0.002);
        rig.say("set mm_per_px 0.0153");
        rig.say("scalecheck 10 0.5");
        const reading::FlatObject b = rig.serial.last("scalecheck");
        EXPECT_EQ(text(b, "status"), "fail");
        EXPECT_NE(text(b, "message").find("scale off by +2.0"), std::string::npos) << text(b, "message");
        EXPECT_NE(text(b, "message").find("check the mm_per_px setting"), std::string::npos);
    }
}
