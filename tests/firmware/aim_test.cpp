// Aim mode and snapshots on the file-backed HAL with the bundled sample frame: the live
// picture on the display with the end face, a focus score and a hint; the score printed on
// serial; a PNG of the full frame with the fitted boundaries in the journal folder.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "firmware/aim_view.h"
#include "firmware/device.h"
#include "firmware/font5x7.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/image_decoder.h"
#include "reading/instrument.h"
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

const std::string kSample = std::string(ICACAM_SOURCE_DIR) + "/tests/data/sample/images/synth-0002.jpg";

struct RecordingDisplay final : hal::Display {
    hal::MonoBitmap last;
    int shown = 0;
    hal::Error show(const hal::MonoBitmap &p) override
    {
        last = p;
        ++shown;
        return {};
    }
};

// A trigger whose level can be read, and whose event queue can lose edges.
struct LevelTrigger final : hal::TriggerButton {
    std::vector<hal::ButtonEdge> edges;
    bool level = false;
    hal::Result<size_t> readEdges(hal::ButtonEdge *out, size_t cap) override
    {
        const size_t n = std::min(cap, edges.size());
        std::copy(edges.begin(), edges.begin() + long(n), out);
        edges.erase(edges.begin(), edges.begin() + long(n));
        return {n, {}};
    }
    hal::Result<bool> pressed() override { return {level, {}}; }
};

struct AimRig {
    std::string dir;
    hal::ManualClock clock{50000};
    std::unique_ptr<hal::FileCamera> camera;
    LevelTrigger trigger;
    hal::FileLed led{clock};
    RecordingDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    std::unique_ptr<fw::Device> device;

    AimRig()
    {
        char t[] = "/tmp/icacam-aim-XXXXXX";
        dir = ::mkdtemp(t);
        std::ofstream(dir + "/frames.txt") << kSample << "\n";
        camera = std::make_unique<hal::FileCamera>(clock, hal::FileCameraOptions{dir + "/frames.txt", 1, true, 0, {}});
        EXPECT_TRUE(storage.open(dir + "/journal", 0).ok());
        fw::Config cfg;
        cfg.n = 0.1742;
        cfg.kMpa = 647;
        cfg.mmPerPx = 0.0153924;
        cfg.cameraMaxWidth = 1456;
        cfg.cameraMaxHeight = 1088;
        device = std::make_unique<fw::Device>(fw::DeviceHal{*camera, trigger, led, display, serial, storage, clock},
                                              cfg, model);
    }
    ~AimRig() { fs::remove_all(dir); }
    // All `aim` picture lines so far.
    std::vector<reading::FlatObject> pictures() const
    {
        std::vector<reading::FlatObject> out;
        size_t at = 0;
        while (at < serial.out.size()) {
            const size_t nl = serial.out.find('\n', at);
            reading::FlatObject o;
            if (reading::parseFlatObject(serial.out.substr(at, nl - at), &o).empty() && o.find("picture"))
                out.push_back(o);
            at = nl == std::string::npos ? serial.out.size() : nl + 1;
        }
        return out;
    }
};

bool sampleHere()
{
    return fs::exists(kSample);
}

TEST(Aim, LivePictureWithTheEndFaceFocusScoreAndHintUntilTimeRunsOut)
{
    if (!sampleHere()) GTEST_SKIP() << "no sample frame";
    AimRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    rig.serial.in = "aim 2\n";
    rig.device->tick();
    EXPECT_TRUE(rig.led.isOn()); // lit as for a measurement, all the time it aims
    for (int i = 0; i < 6; ++i) {
        rig.clock.advance(250);
        rig.device->tick();
    }
    const auto pics = rig.pictures();
    ASSERT_GE(pics.size(), 4u) << rig.serial.out;
    const reading::FlatObject &p = pics.front();
    EXPECT_TRUE(p.find("found")->boolean);
    EXPECT_GT(p.find("focus")->number, 1.0);
    EXPECT_EQ(p.find("hint")->text, "ok") << rig.serial.out; // the sample is centred and sharp
    // The centre and the outer radius of the sample (reference-measurements.txt: 709.9, 566.6).
    EXPECT_NEAR(p.find("x")->number, 709.9, 2);
    EXPECT_NEAR(p.find("y")->number, 566.6, 2);
    // The display: picture on the left (both colours present), the score on the right.
    const std::string row0 = fw::readRow(rig.display.last, 0);
    EXPECT_NE(row0.find("F" + std::to_string(int(p.find("focus")->number))), std::string::npos) << row0;
    EXPECT_NE(fw::readRow(rig.display.last, 3).find("ok"), std::string::npos);
    int on = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 80; ++x) on += rig.display.last.get(x, y);
    EXPECT_GT(on, 300);
    EXPECT_LT(on, 80 * 64 - 300);
    // Time runs out: the ring goes off and the idle page comes back.
    for (int i = 0; i < 4; ++i) {
        rig.clock.advance(250);
        rig.device->tick();
    }
    EXPECT_FALSE(rig.led.isOn());
    EXPECT_NE(rig.serial.out.find("\"state\":\"off\",\"by\":\"time\""), std::string::npos) << rig.serial.out;
    EXPECT_EQ(fw::readRow(rig.display.last, 0), "icacam  ready");
}

TEST(Aim, LongPressAimsAndAShortPressEndsItWithoutMeasuring)
{
    if (!sampleHere()) GTEST_SKIP() << "no sample frame";
    AimRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    const int64_t t = rig.clock.monotonicMs();
    rig.trigger.edges = {{t, true}};
    rig.trigger.level = true;
    rig.device->tick();
    rig.clock.advance(1600);
    rig.device->tick(); // held 1.6 s: aim mode
    EXPECT_TRUE(rig.led.isOn());
    rig.trigger.edges = {{rig.clock.monotonicMs(), false}};
    rig.trigger.level = false;
    rig.device->tick();
    ASSERT_FALSE(rig.pictures().empty());
    rig.trigger.edges = {{rig.clock.monotonicMs() + 10, true}, {rig.clock.monotonicMs() + 110, false}};
    rig.clock.advance(200);
    rig.device->tick();
    EXPECT_FALSE(rig.led.isOn());
    EXPECT_NE(rig.serial.out.find("\"by\":\"button\""), std::string::npos);
    EXPECT_EQ(rig.serial.out.find("\"type\":\"result\""), std::string::npos); // not measured
}

TEST(Aim, ButtonLevelReadAfterAMeasurementUndoesALostRelease)
{
    if (!sampleHere()) GTEST_SKIP() << "no sample frame";
    AimRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    const int64_t t = rig.clock.monotonicMs();
    // A press, then bounce whose last edge (the release) the full event queue dropped.
    rig.trigger.edges = {{t, true}, {t + 100, false}, {t + 140, true}};
    rig.trigger.level = false; // the button is up
    rig.clock.advance(200);
    rig.device->tick();
    EXPECT_NE(rig.serial.out.find("\"type\":\"result\""), std::string::npos);
    rig.serial.out.clear();
    rig.device->tick();      // the level is read: the button is up
    rig.clock.advance(3000); // would have been a long press (aim mode) without the re-read
    rig.device->tick();
    EXPECT_TRUE(rig.pictures().empty()) << rig.serial.out;
    EXPECT_EQ(rig.serial.out.find("\"type\":\"aim\""), std::string::npos) << rig.serial.out;
}

TEST(Snapshot, FullFramePngWithTheFittedBoundariesInTheJournal)
{
    if (!sampleHere()) GTEST_SKIP() << "no sample frame";
    AimRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    rig.serial.in = "{\"cmd\":\"snapshot\",\"id\":\"s1\"}\n";
    rig.device->tick();
    const reading::FlatObject s = rig.serial.last("snapshot");
    ASSERT_TRUE(s.find("image")) << rig.serial.out;
    EXPECT_EQ(s.find("tag")->text, "s1");
    EXPECT_TRUE(s.find("found")->boolean);
    const std::string path = rig.dir + "/journal/" + s.find("image")->text;
    ASSERT_TRUE(fs::exists(path)) << path;
    EXPECT_FALSE(rig.led.isOn());
    // Read it back: full size, and the drawn boundaries where the pipeline put them.
    std::vector<uint8_t> rgb(1456u * 1088u * 3u);
    hal::DecodedImage img;
    ASSERT_TRUE(hal::decodeImage(path, rgb.data(), rgb.size(), 1456, 1088, 0, &img).ok());
    ASSERT_EQ(img.width, 1456);
    ASSERT_EQ(img.height, 1088);
    ASSERT_EQ(img.channels, 3);
    // The same frame through the analyzer: the drawn curves lie at its radii.
    std::vector<uint8_t> grey(1456u * 1088u);
    hal::DecodedImage g;
    ASSERT_TRUE(hal::decodeImage(kSample, grey.data(), grey.size(), 1456, 1088, 0, &g).ok());
    friction::PaperModel model;
    reading::Instrument analyzer;
    ASSERT_EQ(analyzer.configure(1456, 1088, model), vision::ErrorCode::None);
    const reading::Reading m =
        analyzer.read({grey.data(), 1456, 1088, g.stride, 1}, reading::SpecimenSpec{0.1742, 647, 10, 15, 0.0153924, 0});
    ASSERT_TRUE(m.hasValue());
    auto meanRadius = [&](uint8_t r, uint8_t gr, uint8_t b, long *count) {
        double sum = 0;
        *count = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const uint8_t *p = &rgb[(size_t(y) * size_t(img.stride)) + size_t(x) * 3];
                if (p[0] == r && p[1] == gr && p[2] == b)
                    sum += std::hypot(x - m.geometry.centreX, y - m.geometry.centreY), ++*count;
            }
        return *count ? sum / double(*count) : 0;
    };
    long green = 0, red = 0;
    EXPECT_NEAR(meanRadius(40, 255, 40, &green), m.geometry.outer.rEqPx, 2.0);
    EXPECT_NEAR(meanRadius(255, 40, 40, &red), m.geometry.inner.rEqPx, 2.0);
    EXPECT_GT(green, 1000);
    EXPECT_GT(red, 1000);
}

// The focus score falls as the picture blurs, and the hint names the way to the centre.
TEST(AimView, FocusScoreFallsWithBlurAndHintPointsToTheCentre)
{
    if (!sampleHere()) GTEST_SKIP() << "no sample frame";
    std::vector<uint8_t> grey(1456u * 1088u), blurred(grey.size());
    hal::DecodedImage g;
    ASSERT_TRUE(hal::decodeImage(kSample, grey.data(), grey.size(), 1456, 1088, 0, &g).ok());
    for (int y = 0; y < 1088; ++y) // a 9 × 9 box blur: a lens a few turns out of focus
        for (int x = 0; x < 1456; ++x) {
            int sum = 0, n = 0;
            for (int dy = -4; dy <= 4; ++dy)
                for (int dx = -4; dx <= 4; ++dx) {
                    const int xx = std::clamp(x + dx, 0, 1455), yy = std::clamp(y + dy, 0, 1087);
                    sum += grey[size_t(yy) * 1456 + size_t(xx)], ++n;
                }
            blurred[size_t(y) * 1456 + size_t(x)] = uint8_t(sum / n);
        }
    friction::PaperModel model;
    reading::Instrument analyzer;
    ASSERT_EQ(analyzer.configure(1456, 1088, model), vision::ErrorCode::None);
    const vision::LumaView sharp{grey.data(), 1456, 1088, 1456, 1}, soft{blurred.data(), 1456, 1088, 1456, 1};
    const reading::Reading m = analyzer.read(sharp, reading::SpecimenSpec{0.1742, 647, 10, 15, 0.0153924, 0});
    const double fs1 = fw::focusScore(sharp, m), fs2 = fw::focusScore(soft, m);
    std::printf("focus score: sharp %.2f, 9 x 9 box blur %.2f\n", fs1, fs2);
    EXPECT_LT(fs2, 0.6 * fs1) << fs1 << " vs " << fs2;
    reading::Reading left = m;
    left.geometry.centreX = 200; // the specimen far left in the frame
    EXPECT_STREQ(fw::aimReading(sharp, left).hint, "move right");
    reading::Reading low = m;
    low.geometry.centreY = 1000;
    EXPECT_STREQ(fw::aimReading(sharp, low).hint, "move up");
    reading::Reading small = m;
    small.geometry.rMaxPx = 80, small.geometry.outer.rEqPx = 70;
    EXPECT_STREQ(fw::aimReading(sharp, small).hint, "closer");
    reading::Reading none;
    EXPECT_STREQ(fw::aimReading(sharp, none).hint, "no specimen: centre it");
}

} // namespace
