// The file-backed LED ring lit in segments: FileLed's log and refusals, ScriptedLight's light
// per segment (apart from the whole ring's), and the file camera's frames lit by one segment:
// taken from the entry's segment images, or the scene at one segment's share of the light,
// without using the scene up.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/scripted_light.h"
#include "tests/support/temp_dir.h"

using namespace icacam;

namespace {

using test::TempDir;

// A grey PGM of one value, so a frame shows which file it came from and how it was lit.
void writeFlatPgm(const std::string &path, int w, int h, int value)
{
    std::ofstream f(path, std::ios::binary);
    f << "P5\n" << w << " " << h << "\n255\n" << std::string(size_t(w * h), char(value));
}

std::string readFile(const std::string &path)
{
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A pixel of value v in a row lit for `lit` of its exposure at `share` of the ring's light,
// as FileCamera dims it.
int dimmed(int v, double ambient, double lit, double share)
{
    const auto gain = unsigned(std::lround((ambient + (1 - ambient) * lit * share) * 256));
    return gain >= 256 ? v : int((unsigned(v) * gain + 128) >> 8);
}

// A scene a.pgm (200) with segment images s0…s3 (40, 80, 120, 160), then b.pgm (100)
// without; all 8×10.
struct SegmentScenes {
    TempDir dir{"icacam-segments"};
    std::string list = dir.path + "/frames.txt";
    explicit SegmentScenes(const std::string &lines)
    {
        writeFlatPgm(dir.path + "/a.pgm", 8, 10, 200);
        writeFlatPgm(dir.path + "/b.pgm", 8, 10, 100);
        for (int k = 0; k < 4; ++k) writeFlatPgm(dir.path + "/s" + std::to_string(k) + ".pgm", 8, 10, 40 * (k + 1));
        writeFlatPgm(dir.path + "/big.pgm", 9, 10, 60);
        std::ofstream(list) << lines;
    }
};

} // namespace

TEST(ScriptedLight, SegmentsAreLitApartFromTheWholeRing)
{
    hal::ManualClock clock(1000);
    hal::ScriptedLight light(clock);
    ASSERT_TRUE(light.setSegments(4).ok());
    ASSERT_TRUE(light.feed("ok\nlate 5\ndead\nflash 3\nok\n").ok());
    light.switched(true); // ok: the whole ring from 1000
    clock.advance(10);
    light.switchedSegment(1); // late 5: the ring ends at 1010, segment 1 lights at 1015
    EXPECT_EQ(light.litFraction(1000, 1010), 1.0);
    EXPECT_EQ(light.litFraction(1010, 1020), 0.0); // the whole ring: nothing while a segment is lit
    EXPECT_EQ(light.litFraction(1000, 1010, 1), 0.0);
    EXPECT_DOUBLE_EQ(light.litFraction(1010, 1020, 1), 0.5);
    EXPECT_EQ(light.litFraction(1010, 1020, 0), 0.0);
    EXPECT_EQ(light.litFraction(1012, 1012, 1), 0.0);
    EXPECT_EQ(light.litFraction(1016, 1016, 1), 1.0);
    clock.advance(10);
    light.switchedSegment(2); // dead: segment 1 ends at 1020, segment 2 gives no light
    EXPECT_EQ(light.litFraction(1020, 1030, 2), 0.0);
    EXPECT_EQ(light.litFraction(1020, 1030, 1), 0.0);
    EXPECT_DOUBLE_EQ(light.litFraction(1010, 1020, 1), 0.5);
    clock.advance(5);
    light.switchedSegment(2); // lit already: no switch, no script line taken
    clock.advance(5);
    light.switchedSegment(3); // flash 3: 1030 to 1033
    EXPECT_DOUBLE_EQ(light.litFraction(1030, 1040, 3), 0.3);
    clock.advance(10);
    light.switched(true); // ok: the whole ring from 1040
    EXPECT_EQ(light.litFraction(1040, 1050), 1.0);
    EXPECT_EQ(light.litFraction(1040, 1050, 3), 0.0);
    clock.advance(10);
    light.switchedSegment(0); // the script used up: lights at once
    clock.advance(10);
    light.switched(false);
    EXPECT_EQ(light.litFraction(1050, 1060), 0.0);
    EXPECT_EQ(light.litFraction(1050, 1060, 0), 1.0);
    EXPECT_EQ(light.litFraction(1060, 1070, 0), 0.0); // switched off ends the segment too
    EXPECT_EQ(light.litFraction(1040, 1060), 0.5);
}

TEST(ScriptedLight, SegmentSwitchedOffBeforeItsLateLightNeverLights)
{
    hal::ManualClock clock(0);
    hal::ScriptedLight light(clock);
    ASSERT_TRUE(light.feed("late 20\n").ok());
    light.switchedSegment(0);
    clock.advance(10);
    light.switched(false);
    EXPECT_EQ(light.litFraction(0, 100, 0), 0.0);
    EXPECT_EQ(light.segments(), 1);
    EXPECT_EQ(light.setSegments(0).code, hal::Errc::Invalid);
    EXPECT_EQ(light.segments(), 1); // kept
}

TEST(FileLed, LogsSegmentsBesideOnAndOffAndCountsEveryChange)
{
    TempDir dir;
    hal::ManualClock clock(500);
    hal::ScriptedLight light(clock);
    hal::FileLed led(clock, &light, 4);
    EXPECT_EQ(light.segments(), 4); // the light knows the ring's share of a segment
    EXPECT_EQ(led.segments(), 4);
    ASSERT_TRUE(led.open(dir.path + "/led.log").ok());
    ASSERT_TRUE(led.set(true).ok());
    clock.advance(5);
    ASSERT_TRUE(led.lightSegment(2).ok());
    EXPECT_TRUE(led.isOn());
    ASSERT_TRUE(led.lightSegment(2).ok()); // lit already: logged, not a change
    EXPECT_EQ(led.switchCount(), 2);
    // No such segment: refused, nothing logged or changed.
    EXPECT_EQ(led.lightSegment(4).code, hal::Errc::Invalid);
    EXPECT_EQ(led.lightSegment(-1).code, hal::Errc::Invalid);
    EXPECT_EQ(led.switchCount(), 2);
    clock.advance(5);
    ASSERT_TRUE(led.lightSegment(0).ok());
    clock.advance(5);
    ASSERT_TRUE(led.set(true).ok()); // from a segment to the whole ring
    clock.advance(5);
    ASSERT_TRUE(led.set(false).ok());
    EXPECT_FALSE(led.isOn());
    EXPECT_EQ(led.switchCount(), 5);
    EXPECT_EQ(readFile(dir.path + "/led.log"),
              "500 on\n505 segment 2\n505 segment 2\n510 segment 0\n515 on\n520 off\n");
    // The light was told: segment 2 from 505, segment 0 from 510, the whole ring from 515.
    EXPECT_EQ(light.litFraction(505, 510, 2), 1.0);
    EXPECT_EQ(light.litFraction(505, 510), 0.0);
    EXPECT_EQ(light.litFraction(510, 515, 0), 1.0);
    EXPECT_EQ(light.litFraction(515, 520), 1.0);
}

TEST(FileLed, OneLineRingHasNoSegmentAndNoneIsNoRing)
{
    hal::ManualClock clock;
    hal::FileLed one(clock);
    EXPECT_EQ(one.segments(), 1);
    EXPECT_EQ(one.lightSegment(0).code, hal::Errc::Invalid);
    EXPECT_FALSE(one.isOn());
    EXPECT_EQ(one.switchCount(), 0);
    hal::ScriptedLight light(clock);
    hal::FileLed none(clock, &light, 0);
    EXPECT_EQ(none.open("").code, hal::Errc::Invalid);
    EXPECT_EQ(light.segments(), 1); // not told a count it cannot have
}

// The segment frames of a specimen before its whole-ring frame: each from its own image, the
// scene left for the whole ring, which then uses it up.
TEST(FileCamera, SegmentFramesComeFromTheSegmentImagesAndLeaveTheScene)
{
    SegmentScenes set("# a scene and its segment images\na.pgm|s0.pgm |  s1.pgm\t| s2.pgm | s3.pgm \nb.pgm\n");
    hal::ManualClock clock;
    hal::ScriptedLight light(clock);
    hal::FileLed led(clock, &light, 4);
    hal::FileCameraOptions o(set.list, 1, false, 0, {}, &light);
    o.ambient = 0.1;
    hal::FileCamera cam(clock, o);
    const hal::Error ce = cam.configure({hal::PixelFormat::Grey8, 64, 64});
    ASSERT_TRUE(ce.ok()) << ce.message;
    hal::CapturedFrame f;
    for (int k : {2, 0, 3}) {
        ASSERT_TRUE(led.lightSegment(k).ok());
        const hal::Error e = cam.capture(100, &f);
        ASSERT_TRUE(e.ok()) << e.message;
        EXPECT_EQ(f.source, "s" + std::to_string(k) + ".pgm");
        EXPECT_EQ(f.view.data[0], 40 * (k + 1));
        EXPECT_EQ(f.view.data[size_t(f.view.stride) * 9 + 7], 40 * (k + 1));
    }
    ASSERT_TRUE(led.set(true).ok());
    ASSERT_TRUE(cam.capture(100, &f).ok());
    EXPECT_EQ(f.source, "a.pgm"); // still there after three segment frames
    EXPECT_EQ(f.view.data[0], 200);
    // Used up by the whole ring: b.pgm, which has no segment images, is next. A segment lights
    // it at a quarter of the ring's light and leaves it there.
    ASSERT_TRUE(led.lightSegment(1).ok());
    ASSERT_TRUE(cam.capture(100, &f).ok());
    EXPECT_EQ(f.source, "b.pgm");
    EXPECT_EQ(f.view.data[0], dimmed(100, 0.1, 1.0, 0.25));
    EXPECT_EQ(f.view.data[0], 32);
    ASSERT_TRUE(led.set(false).ok());
    ASSERT_TRUE(cam.capture(100, &f).ok()); // dark: the scene stays too
    EXPECT_EQ(f.source, "b.pgm");
    EXPECT_EQ(f.view.data[0], dimmed(100, 0.1, 0.0, 1.0));
    ASSERT_TRUE(led.set(true).ok());
    ASSERT_TRUE(cam.capture(100, &f).ok());
    EXPECT_EQ(f.source, "b.pgm");
    EXPECT_EQ(f.view.data[0], 100);
    EXPECT_EQ(cam.capture(100, &f).code, hal::Errc::Timeout); // both scenes used up
}

// A segment that lights late: the rows exposed before it are at the ambient level, as the
// whole ring's are.
TEST(FileCamera, SegmentFrameRowsAreDimmedForThePartTheSegmentWasDark)
{
    SegmentScenes set("a.pgm | s0.pgm | s1.pgm | s2.pgm\n");
    hal::ManualClock clock;
    hal::ScriptedLight light(clock);
    ASSERT_TRUE(light.feed("late 5\n").ok());
    hal::FileLed led(clock, &light, 3);
    hal::FileCameraOptions o(set.list, 1, false, 0, {}, &light);
    o.readoutMs = 10;
    o.ambient = 0.1;
    hal::FileCamera cam(clock, o);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    ASSERT_TRUE(led.lightSegment(1).ok());
    hal::CapturedFrame f;
    ASSERT_TRUE(cam.capture(100, &f).ok()); // rows 0-4 before the light, 5-9 after
    EXPECT_EQ(f.source, "s1.pgm");
    EXPECT_EQ(f.view.data[0], dimmed(80, 0.1, 0.0, 1.0));
    EXPECT_EQ(f.view.data[size_t(f.view.stride) * 4], dimmed(80, 0.1, 0.0, 1.0));
    EXPECT_EQ(f.view.data[size_t(f.view.stride) * 5], 80);
    EXPECT_EQ(f.view.data[size_t(f.view.stride) * 9], 80);
}

TEST(FileCamera, SegmentImagesOfAnotherCountOrSizeAreRefused)
{
    SegmentScenes set("a.pgm | s0.pgm | s1.pgm | s2.pgm\nb.pgm | s0.pgm | big.pgm | s2.pgm\n");
    hal::ManualClock clock;
    hal::ScriptedLight light(clock);
    hal::FileLed four(clock, &light, 4);
    hal::FileCameraOptions o(set.list, 1, false, 0, {}, &light);
    hal::FileCamera cam(clock, o);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    hal::CapturedFrame f;
    ASSERT_TRUE(four.lightSegment(3).ok());
    hal::Error e = cam.capture(100, &f);
    EXPECT_EQ(e.code, hal::Errc::Invalid);
    EXPECT_NE(e.message.find("'a.pgm' has 3 segment images"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("4 segments"), std::string::npos) << e.message;
    ASSERT_TRUE(four.set(true).ok());
    ASSERT_TRUE(cam.capture(100, &f).ok()); // the scene was not used up by the refusal
    EXPECT_EQ(f.source, "a.pgm");
    ASSERT_TRUE(four.set(false).ok());

    hal::FileLed three(clock, &light, 3);
    ASSERT_TRUE(three.lightSegment(1).ok());
    e = cam.capture(100, &f);
    EXPECT_EQ(e.code, hal::Errc::BadFormat);
    EXPECT_NE(e.message.find("'big.pgm' is 9x10"), std::string::npos) << e.message;
    ASSERT_TRUE(three.lightSegment(2).ok());
    ASSERT_TRUE(cam.capture(100, &f).ok());
    EXPECT_EQ(f.source, "s2.pgm");
    EXPECT_EQ(f.view.data[0], 120);
}

TEST(FileCamera, ListLinesNamingSegmentImagesAreChecked)
{
    hal::ManualClock clock;
    for (const char *bad : {"a.pgm | s0.pgm | s1.pgm\n",                            // 2: too few
                            "a.pgm | s0 | s1 | s2 | s3 | s0 | s1 | s2 | s3 | s0\n", // 9: too many
                            "a.pgm | s0.pgm | | s2.pgm\n",                          // an empty one
                            " | s0.pgm | s1.pgm | s2.pgm\n",                        // no scene
                            "!timeout | s0.pgm | s1.pgm | s2.pgm\n"}) {
        SegmentScenes set(std::string("b.pgm\n") + bad);
        hal::FileCamera cam(clock, {set.list, 1, false, 0, {}});
        const hal::Error e = cam.configure({hal::PixelFormat::Grey8, 64, 64});
        EXPECT_EQ(e.code, hal::Errc::Invalid) << bad;
        EXPECT_NE(e.message.find("line 2"), std::string::npos) << e.message;
    }
    SegmentScenes eight("a.pgm | s0 | s1 | s2 | s3 | s0 | s1 | s2 | s3\n");
    hal::FileCamera most(clock, {eight.list, 1, false, 0, {}});
    EXPECT_TRUE(most.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    // Without a light, segment images are never used: the scene, once.
    SegmentScenes set("a.pgm | s0.pgm | s1.pgm | s2.pgm\n");
    hal::FileCamera cam(clock, {set.list, 1, false, 0, {}});
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    hal::CapturedFrame f;
    ASSERT_TRUE(cam.capture(100, &f).ok());
    EXPECT_EQ(f.source, "a.pgm");
    EXPECT_EQ(cam.capture(100, &f).code, hal::Errc::Timeout);
}
