#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fcntl.h>

#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_trigger.h"
#include "hal/file/image_decoder.h"
#include "hal/file/png_display.h"
#include "hal/file/pty_serial.h"
#include "hal/file/scripted_light.h"
#include "tests/support/temp_dir.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

using test::TempDir;

void writePgm(const std::string &path, int w, int h)
{
    std::ofstream f(path, std::ios::binary);
    f << "P5\n# test\n" << w << " " << h << "\n255\n";
    for (int i = 0; i < w * h; ++i) f.put(char(i % 251));
}

} // namespace

TEST(FileCamera, DeliversFramesWithPaddedStrideThenTimesOut)
{
    TempDir dir;
    writePgm(dir.path + "/a.pgm", 30, 20);
    std::vector<uint8_t> rgb(size_t(8 * 8 * 3), 100);
    ASSERT_TRUE(hal::writePng(dir.path + "/b.png", rgb.data(), 8, 8, 3, 24).ok());
    {
        std::ofstream list(dir.path + "/frames.txt");
        list << "# frames\na.pgm\n!timeout\nb.png\n";
    }
    hal::ManualClock clock;
    hal::FileCamera cam(clock, {dir.path + "/frames.txt", 64, false, 0, {}});
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    hal::CapturedFrame f;
    ASSERT_TRUE(cam.capture(500, &f).ok());
    EXPECT_EQ(f.view.width, 30);
    EXPECT_EQ(f.view.stride, 64);
    EXPECT_EQ(f.source, "a.pgm");
    EXPECT_EQ(f.view.data[64 * 19 + 29], uint8_t((19 * 30 + 29) % 251)); // rows re-laid correctly
    const int64_t t0 = clock.monotonicMs();
    EXPECT_EQ(cam.capture(500, &f).code, hal::Errc::Timeout);
    EXPECT_EQ(clock.monotonicMs() - t0, 500);
    EXPECT_EQ(cam.capture(500, &f).code, hal::Errc::BadFormat); // RGB file, grey camera
    EXPECT_EQ(cam.capture(500, &f).code, hal::Errc::Timeout);   // list exhausted
}

TEST(FileCamera, RefusesFramesLargerThanConfigured)
{
    TempDir dir;
    writePgm(dir.path + "/big.pgm", 100, 10);
    hal::ManualClock clock;
    hal::FileCamera cam(clock, {dir.path, 1, true, 0, {}});
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    hal::CapturedFrame f;
    EXPECT_EQ(cam.capture(100, &f).code, hal::Errc::TooLarge);
    hal::FileCamera none(clock, {dir.path + "/missing", 1, false, 0, {}});
    EXPECT_EQ(none.configure({hal::PixelFormat::Grey8, 64, 64}).code, hal::Errc::NotFound);
}

TEST(FileTrigger, ScriptEdgesArriveInTimeOrder)
{
    hal::ManualClock clock(1000);
    hal::FileTrigger t(clock);
    t.feed("press 80\nwait 500\npress\n# comment\n2000 down\n2050 up\nnonsense\n");
    EXPECT_FALSE(t.lastError().empty());
    hal::ButtonEdge e[8];
    EXPECT_EQ(t.readEdges(e, 8).value, 1u); // the first down is due now
    EXPECT_TRUE(e[0].pressed);
    EXPECT_EQ(e[0].timeMs, 1000);
    clock.advance(80);
    ASSERT_EQ(t.readEdges(e, 8).value, 1u);
    EXPECT_FALSE(e[0].pressed);
    clock.advance(2000);
    const size_t n = t.readEdges(e, 8).value;
    ASSERT_EQ(n, 4u);
    EXPECT_EQ(e[0].timeMs, 1580);
    EXPECT_EQ(e[1].timeMs, 1680);
    // "2000 down" is relative to the start (1000) but in the past of the cursor: kept in order.
    for (size_t i = 1; i < n; ++i) EXPECT_GE(e[i].timeMs, e[i - 1].timeMs);
}

TEST(PngDisplay, WritesPicturesOfTheScreen)
{
    TempDir dir;
    hal::PngDisplay d;
    ASSERT_TRUE(d.open(dir.path + "/screen", 2).ok());
    hal::MonoBitmap b;
    b.set(3, 4, true);
    ASSERT_TRUE(d.show(b).ok());
    ASSERT_TRUE(d.show(b).ok()); // unchanged: no new picture
    EXPECT_EQ(d.pictureCount(), 1);
    std::vector<uint8_t> px(256 * 128);
    hal::DecodedImage img;
    ASSERT_TRUE(hal::decodeImage(dir.path + "/screen/screen-000001.png", px.data(), px.size(), 256, 128, 0, &img).ok());
    EXPECT_EQ(img.width, 256);
    EXPECT_EQ(px[size_t(8 * 256 + 6)], 255);
    EXPECT_EQ(px[size_t(8 * 256 + 8)], 0);
}

TEST(PtySerial, BytesBothWaysAndNoStallWithoutReader)
{
    TempDir dir;
    hal::PtySerial s;
    ASSERT_TRUE(s.open(dir.path + "/tty", 50).ok());
    hal::UniqueFd host(::open((dir.path + "/tty").c_str(), O_RDWR | O_NOCTTY));
    ASSERT_TRUE(host.valid());
    ASSERT_EQ(::write(host.get(), "ping\n", 5), 5);
    char buf[16];
    size_t got = 0;
    for (int i = 0; i < 100 && got < 5; ++i) {
        got += s.read(buf + got, sizeof buf - got).value;
        ::usleep(1000);
    }
    EXPECT_EQ(std::string(buf, got), "ping\n");
    ASSERT_TRUE(s.write("pong\n").ok());
    ASSERT_EQ(::read(host.get(), buf, 5), 5);
    EXPECT_EQ(std::string(buf, 5), "pong\n");
    // Nobody reads: output is dropped after the write timeout instead of blocking forever.
    hal::Error e;
    const std::string chunk(4096, 'x');
    for (int i = 0; i < 1000 && e.ok(); ++i) e = s.write(chunk);
    EXPECT_EQ(e.code, hal::Errc::Full);
    // Further lines are dropped at once, not after another timeout each.
    hal::SystemClock clock;
    const int64_t t0 = clock.monotonicMs();
    for (int i = 0; i < 20; ++i) EXPECT_EQ(s.write(chunk).code, hal::Errc::Full);
    EXPECT_LT(clock.monotonicMs() - t0, 200);
    // The far end reads again: output flows again.
    char drain[65536];
    ::fcntl(host.get(), F_SETFL, O_NONBLOCK);
    while (::read(host.get(), drain, sizeof drain) > 0) {}
    EXPECT_TRUE(s.write("back\n").ok());
}

// The file camera lit by a scripted ring: rows exposed while the ring was dark are dimmed to the
// ambient level, a rolling shutter's rows one after the other; the image is used up only by a
// frame lit top to bottom.
TEST(FileCamera, ScriptedLightLightsTheRowsItReachesAndKeepsTheSceneUntilLit)
{
    char t[] = "/tmp/icacam-light-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    for (const char *name : {"a.pgm", "b.pgm"}) {
        std::ofstream f(dir + "/" + name, std::ios::binary);
        f << "P5\n8 10\n255\n" << std::string(80, char(200));
    }
    hal::ManualClock clock;
    hal::ScriptedLight light(clock);
    ASSERT_TRUE(light.feed("late 5 # the ring lights 5 ms late\n").ok());
    EXPECT_FALSE(light.feed("blink 3\n").ok());
    hal::FileCameraOptions o(dir, 1, false, 0, {}, &light);
    o.readoutMs = 10;
    o.ambient = 0.1;
    hal::FileCamera cam(clock, o);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    hal::CapturedFrame f;
    ASSERT_TRUE(cam.capture(100, &f).ok()); // the ring off: the scene dim, not used up
    EXPECT_EQ(f.source, "a.pgm");
    EXPECT_EQ(f.view.data[0], 20);
    light.switched(true);
    const int64_t on = clock.monotonicMs();
    ASSERT_TRUE(cam.capture({on, 100}, &f).ok()); // rows 0-4 before the light, 5-9 after
    EXPECT_EQ(f.source, "a.pgm");
    EXPECT_EQ(f.view.data[0], 20);
    EXPECT_EQ(f.view.data[size_t(f.view.stride) * 4], 20);
    EXPECT_EQ(f.view.data[size_t(f.view.stride) * 5], 200);
    ASSERT_TRUE(cam.capture({on, 100}, &f).ok()); // lit top to bottom: a.pgm seen
    EXPECT_EQ(f.source, "a.pgm");
    EXPECT_EQ(f.view.data[0], 200);
    ASSERT_TRUE(cam.capture({on, 100}, &f).ok());
    EXPECT_EQ(f.source, "b.pgm");
    light.switched(false);
    EXPECT_EQ(light.litFraction(double(clock.monotonicMs()), double(clock.monotonicMs()) + 1), 0.0);
    std::filesystem::remove_all(dir);
}

TEST(FileCamera, ControlsChangeOnTheRunWithoutStartingTheImagesOver)
{
    TempDir dir;
    writePgm(dir.path + "/a.pgm", 8, 8);
    writePgm(dir.path + "/b.pgm", 8, 8);
    writePgm(dir.path + "/c.pgm", 8, 8);
    hal::ManualClock clock;
    hal::CameraControls made;
    made.exposureUs = 5000;
    made.analogueGain = 1;
    hal::FileCamera cam(clock, {dir.path, 1, false, 0, made});
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 64, 64}).ok());
    hal::CapturedFrame f;
    ASSERT_TRUE(cam.capture(500, &f).ok());
    EXPECT_EQ(f.source, "a.pgm");
    EXPECT_EQ(f.controls.exposureUs, 5000);
    hal::CameraControls asked;
    asked.exposureUs = 12000;
    asked.lensPosition = 2.5;
    const hal::Result<hal::CameraControls> took = cam.setControls(asked);
    ASSERT_TRUE(took.ok()) << took.error.message;
    EXPECT_EQ(took.value.exposureUs, 12000);
    EXPECT_EQ(took.value.lensPosition, 2.5);
    EXPECT_LT(took.value.analogueGain, 0); // not asked
    ASSERT_TRUE(cam.capture(500, &f).ok());
    EXPECT_EQ(f.source, "b.pgm"); // the list goes on
    EXPECT_EQ(f.controls.exposureUs, 12000);
    EXPECT_EQ(f.exposureUs, 12000);
    EXPECT_EQ(f.controls.analogueGain, 1); // kept
    EXPECT_EQ(f.controls.lensPosition, 2.5);
}
