// The ring lit in turn on the device (firmware/device_segments.cpp): a segmented LED ring on
// the file HAL lights one segment at a time; the file camera shows a rendered record's
// segment frames (tests/data/photo/segments) under it. The device takes them at one fixed
// exposure before the whole ring's frame, proves each lit, reads the tilt from them as
// `icacam measure` does from the same files, journals them so the loop re-measures the
// journal the same way, and falls back on the whole ring's frame alone, saying why, when a
// segment does not light.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "firmware/device.h"
#include "friction/friction_models.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/scripted_light.h"
#include "host_tools/loop/journal_records.h"
#include "tests/support/recording_serial.h"
#include "tests/support/same_reading.h"

using namespace icacam;
using test::expectSameReading;
namespace fs = std::filesystem;

namespace {

const std::string kSegments = std::string(ICACAM_SOURCE_DIR) + "/tests/data/photo/segments";

struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

// The camera as the device drives it: every exposure it was asked for, in order.
struct ExposureLog final : hal::Camera {
    hal::Camera &camera;
    std::vector<int> asked;
    explicit ExposureLog(hal::Camera &c) : camera(c) {}
    hal::Error configure(const hal::CameraFormat &f) override { return camera.configure(f); }
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &r, hal::CapturedFrame *out) override
    {
        return camera.capture(r, out);
    }
    hal::Result<hal::CameraControls> setControls(const hal::CameraControls &c) override
    {
        if (c.exposureUs >= 0) asked.push_back(c.exposureUs);
        return camera.setControls(c);
    }
};

// The record straight-0021 (640 × 480, R_o read 2.6 px out on the barrel by the frame alone)
// with its four segment frames, listed for the file camera in the order `order` gives.
struct Rig {
    fs::path dir = makeDir();
    hal::ManualClock clock;
    hal::ScriptedLight light{clock};
    std::unique_ptr<hal::FileCamera> files;
    std::unique_ptr<ExposureLog> camera;
    hal::FileTrigger trigger{clock};
    std::unique_ptr<hal::FileLed> led;
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    const friction::FrictionModel *model = friction::frictionModel(friction::kDefaultModel);
    fw::Config cfg;
    std::unique_ptr<fw::Device> device;

    explicit Rig(int segments, const std::string &script = "", std::vector<int> order = {0, 1, 2, 3})
    {
        fs::create_directories(dir / "frames");
        std::ofstream list(dir / "frames" / "list.txt");
        list << "straight-0021.png";
        fs::copy_file(kSegments + "/images/straight-0021.png", dir / "frames" / "straight-0021.png");
        for (int k = 0; k < 4; ++k) {
            const std::string name = "straight-0021-s" + std::to_string(k) + ".png";
            fs::copy_file(kSegments + "/images/" + name, dir / "frames" / name);
        }
        if (segments > 1)
            for (int k : order) list << " | straight-0021-s" << k << ".png";
        list << "\n";
        list.close();
        EXPECT_TRUE(light.feed(script).ok());
        hal::FileCameraOptions o((dir / "frames" / "list.txt").string(), 1, true, 0, {}, &light);
        files = std::make_unique<hal::FileCamera>(clock, o);
        camera = std::make_unique<ExposureLog>(*files);
        led = std::make_unique<hal::FileLed>(clock, &light, segments);
        EXPECT_TRUE(led->open((dir / "led.log").string()).ok());
        EXPECT_TRUE(storage.open((dir / "journal").string()).ok());
        cfg.n = 0.2107, cfg.kMpa = 1201, cfg.mmPerPx = 0.0407012;
        cfg.cameraMaxWidth = 640, cfg.cameraMaxHeight = 480;
        cfg.exposureUs = 1000;
        cfg.ledSegments = segments;
        cfg.baseDir = dir.string();
    }
    ~Rig() { fs::remove_all(dir); }
    static fs::path makeDir()
    {
        char t[] = "/tmp/icacam-segments-XXXXXX";
        return ::mkdtemp(t);
    }
    reading::FlatObject measure()
    {
        device = std::make_unique<fw::Device>(fw::DeviceHal{*camera, trigger, *led, display, serial, storage, clock},
                                              cfg, *model);
        EXPECT_TRUE(device->start().ok());
        serial.in = "trigger\n";
        device->tick();
        return serial.last("result");
    }
    std::string ledLog() const
    {
        std::ifstream in(dir / "led.log");
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

reading::FlatObject hostResult(const std::string &manifestText, const friction::FrictionModel &model)
{
    return test::hostResult(manifestText, kSegments, model);
}

const char *const kRow = "id,image,n,k_mpa,mm_per_px,segment_images\n"
                         "a,images/straight-0021.png,0.2107,1201,0.0407012,"
                         "images/straight-0021-s0.png;images/straight-0021-s1.png;images/straight-0021-s2.png;"
                         "images/straight-0021-s3.png\n";
// The same frames as a ring mounted a quarter turn on: its segment 0 is the rendered segment 1.
const char *const kRowTurned = "id,image,n,k_mpa,mm_per_px,segment_images,segment0_deg\n"
                               "a,images/straight-0021.png,0.2107,1201,0.0407012,"
                               "images/straight-0021-s1.png;images/straight-0021-s2.png;images/straight-0021-s3.png;"
                               "images/straight-0021-s0.png,90\n";
const char *const kRowAlone = "id,image,n,k_mpa,mm_per_px\n"
                              "a,images/straight-0021.png,0.2107,1201,0.0407012\n";

} // namespace

TEST(SegmentCapture, TheDeviceReadsTheTiltAsMeasureDoesFromTheSameFrames)
{
    Rig rig(4);
    const reading::FlatObject r = rig.measure();
    ASSERT_TRUE(r.find("segment_frames")) << rig.serial.out;
    EXPECT_EQ(r.find("segment_frames")->number, 4) << rig.serial.out;
    EXPECT_EQ(r.find("segment_problem"), nullptr);
    ASSERT_TRUE(r.find("tilt_knee_px"));
    EXPECT_EQ(r.find("tilt_knee_px")->type, reading::JsonField::Type::Number) << "the tilt was read";
    test::expectSameReading(r, hostResult(kRow, *rig.model));
    // The tilt moved the contact edge: the whole ring's frame alone reads another μ.
    EXPECT_NE(r.find("mu")->text, hostResult(kRowAlone, *rig.model).find("mu")->text);
    EXPECT_EQ(rig.serial.out.find("\"segments\""), std::string::npos) << rig.serial.out;

    // Each segment lit alone, in order, then the whole ring, then dark; the segment frames at
    // four times the recipe's exposure, the whole ring's back at the recipe's.
    std::istringstream log(rig.ledLog());
    std::vector<std::string> words;
    for (std::string ms, what; log >> ms >> what;) {
        if (what == "segment") log >> what, what = "s" + what;
        words.push_back(what);
    }
    EXPECT_EQ(words, (std::vector<std::string>{"off", "s0", "s1", "s2", "s3", "off", "on", "off"})) << rig.ledLog();
    ASSERT_GE(rig.camera->asked.size(), 2u);
    EXPECT_EQ(rig.camera->asked[rig.camera->asked.size() - 2], 4000);
    EXPECT_EQ(rig.camera->asked.back(), 1000);
    EXPECT_FALSE(rig.led->isOn());

    // The journal holds the segment frames beside the image; the loop's manifest of it
    // re-measures the record with them, to the same reading.
    ASSERT_TRUE(r.find("segment_images"));
    EXPECT_EQ(r.find("segment_images")->text,
              "img-000001-s0.pgm;img-000001-s1.pgm;img-000001-s2.pgm;img-000001-s3.pgm");
    host::Manifest journal;
    host::loop::JournalJoin join;
    std::string error;
    std::ofstream(rig.dir / "ref.csv") << "id,mu_ref\n1,0.2\n";
    ASSERT_TRUE(host::loop::readJournalManifest((rig.dir / "journal").string(), (rig.dir / "ref.csv").string(),
                                                &journal, &join, &error))
        << error;
    ASSERT_EQ(journal.rows.size(), 1u);
    test::expectSameReading(r, test::hostResult(journal, *rig.model));
}

// The ring mounted turned: segment 0 where the rendered segment 1 lit from, the config saying
// so. The tilt is the same, read from the same light.
TEST(SegmentCapture, SegmentZeroIsWhereTheConfigSaysItIs)
{
    Rig rig(4, "", {1, 2, 3, 0});
    rig.cfg.ledSegment0Deg = 90;
    const reading::FlatObject r = rig.measure();
    ASSERT_TRUE(r.find("segment_frames")) << rig.serial.out;
    EXPECT_EQ(r.find("segment_frames")->number, 4);
    EXPECT_EQ(r.find("segment0_deg")->number, 90);
    test::expectSameReading(r, hostResult(kRowTurned, *rig.model));
    EXPECT_EQ(r.find("mu")->text, hostResult(kRow, *rig.model).find("mu")->text);

    // The same ring, the config not told: the frames say where segment 0 is, no tilt is read
    // from them (the whole ring's frame's reading), and the record and serial say what to set.
    Rig wrong(4, "", {1, 2, 3, 0});
    const reading::FlatObject w = wrong.measure();
    ASSERT_TRUE(w.find("segment_problem")) << wrong.serial.out;
    EXPECT_NE(w.find("segment_problem")->text.find("segment 0 lights the specimen from 89 deg"), std::string::npos)
        << w.find("segment_problem")->text;
    EXPECT_NEAR(w.find("segment0_seen_deg")->number, 90, 5);
    EXPECT_EQ(w.find("tilt_knee_px")->type, reading::JsonField::Type::Null);
    EXPECT_EQ(w.find("mu")->text, hostResult(kRowAlone, *rig.model).find("mu")->text);
    EXPECT_EQ(wrong.serial.last("error").find("code")->text, "segments");
    // Set over serial as the problem says, kept for the next start; the next press reads the tilt.
    wrong.serial.in = "set segment0_deg 90\ntrigger\n";
    wrong.device->tick();
    wrong.device->tick();
    const reading::FlatObject again = wrong.serial.last("result");
    ASSERT_TRUE(again.find("segment_frames")) << wrong.serial.out;
    EXPECT_EQ(again.find("segment_problem"), nullptr) << again.find("segment_problem")->text;
    EXPECT_EQ(again.find("mu")->text, r.find("mu")->text);
    std::ifstream saved(wrong.dir / "journal" / "settings.conf");
    std::stringstream text;
    text << saved.rdbuf();
    EXPECT_NE(text.str().find("segment0_deg = 90"), std::string::npos) << text.str();

    // Its lines listed the other way round.
    Rig reversed(4, "", {0, 3, 2, 1});
    const reading::FlatObject v = reversed.measure();
    ASSERT_TRUE(v.find("segment_problem")) << reversed.serial.out;
    EXPECT_NE(v.find("segment_problem")->text.find("other way round"), std::string::npos);
    EXPECT_EQ(v.find("segment_way")->number, -1);
}

// Segment 1's LED is dead: its frames are refused, the reading is the whole ring's frame's
// alone (never a tilt from a dark segment), and the record, serial and screen say why.
TEST(SegmentCapture, ADeadSegmentLeavesTheWholeRingsFrameAlone)
{
    Rig rig(4, "ok\ndead\nok\n");
    const reading::FlatObject r = rig.measure();
    ASSERT_TRUE(r.find("segment_frames")) << rig.serial.out;
    EXPECT_EQ(r.find("segment_frames")->number, 0);
    ASSERT_TRUE(r.find("segment_problem"));
    EXPECT_NE(r.find("segment_problem")->text.find("segment 1 not lit"), std::string::npos)
        << r.find("segment_problem")->text;
    EXPECT_EQ(r.find("segment_images"), nullptr);
    test::expectSameReading(r, hostResult(kRowAlone, *rig.model));
    const reading::FlatObject e = rig.serial.last("error");
    ASSERT_TRUE(e.find("code")) << rig.serial.out;
    EXPECT_EQ(e.find("code")->text, "segments");
    // Back at the recipe's exposure for the whole ring's frame all the same.
    EXPECT_EQ(rig.camera->asked.back(), 1000);
}

// A ring of one line told it has segments: said, and measured with the whole ring.
TEST(SegmentCapture, ARingWithoutTheSegmentsTheConfigNamesIsSaidSo)
{
    Rig rig(1);
    rig.cfg.ledSegments = 4;
    const reading::FlatObject r = rig.measure();
    ASSERT_TRUE(r.find("segment_problem")) << rig.serial.out;
    EXPECT_NE(r.find("segment_problem")->text.find("switches 1 segment"), std::string::npos);
    test::expectSameReading(r, hostResult(kRowAlone, *rig.model));
    rig.serial.in = "status\n";
    rig.device->tick();
    const reading::FlatObject st = rig.serial.last("status");
    ASSERT_TRUE(st.find("led_segments")) << rig.serial.out;
    EXPECT_EQ(st.find("led_segments")->number, 4);
    EXPECT_EQ(st.find("led_switches")->number, 1);
}

TEST(SegmentCapture, TheConfigTiesSegmentsToLinesAndAFixedExposure)
{
    fw::Config c;
    EXPECT_EQ(fw::ledSegmentIssue(c), "");
    c.ledSegments = 2;
    EXPECT_NE(fw::ledSegmentIssue(c).find("3-8"), std::string::npos);
    c.ledSegments = 4;
    EXPECT_NE(fw::ledSegmentIssue(c).find("camera.exposure_us"), std::string::npos);
    c.exposureUs = 2000;
    EXPECT_EQ(fw::ledSegmentIssue(c), "");
    EXPECT_EQ(fw::segmentExposureUs(c), 8000);
    c.ledSegmentExposureUs = 5000;
    EXPECT_EQ(fw::segmentExposureUs(c), 5000);
    c.ledBackend = "gpiod";
    c.ledLine = "GPIO5, GPIO6,GPIO13";
    EXPECT_NE(fw::ledSegmentIssue(c).find("3 line(s) for led.segments = 4"), std::string::npos);
    c.ledLine = "GPIO5, GPIO6,GPIO13 ,GPIO19";
    EXPECT_EQ(fw::ledSegmentIssue(c), "");
    EXPECT_EQ(fw::ledLines(c), (std::vector<std::string>{"GPIO5", "GPIO6", "GPIO13", "GPIO19"}));
    c.ledSegments = 1;
    EXPECT_NE(fw::ledSegmentIssue(c).find("set led.segments"), std::string::npos);

    fw::Config parsed;
    const auto issues = fw::parseConfig("[specimen]\nn = 0.2\n[calibration]\nmm_per_px = 0.03\n[journal]\n"
                                        "dir = /tmp/j\n[led]\nsegments = 4\nsegment0_deg = 45\n",
                                        &parsed);
    int exposureIssues = 0;
    for (const fw::ConfigIssue &i : issues) exposureIssues += i.message.find("camera.exposure_us") != std::string::npos;
    EXPECT_EQ(exposureIssues, 1);
    EXPECT_EQ(parsed.ledSegment0Deg, 45);
}
