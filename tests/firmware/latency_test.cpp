// `measure-latency` on a simulated webcam whose timestamps lag its exposures by a delay the
// test knows and the device does not: the ring is stepped, the first frame lit top to bottom
// found, and the bound saved is never below the true delay, and above it by less than a frame
// interval and an exposure.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "firmware/device.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/folder_storage.h"
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

struct QuietTrigger final : hal::TriggerButton {
    hal::Result<size_t> readEdges(hal::ButtonEdge *, size_t) override { return {}; }
};
struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};
// When the ring was on, in µs of the manual clock.
struct TimedLed final : hal::LedRing {
    hal::ManualClock &clock;
    std::vector<std::pair<int64_t, int64_t>> lit; // [on, off)
    explicit TimedLed(hal::ManualClock &c) : clock(c) {}
    hal::Error set(bool v) override
    {
        const int64_t now = clock.monotonicMs() * 1000;
        if (v && !isOn()) lit.push_back({now, INT64_MAX});
        if (!v && isOn()) lit.back().second = now;
        return {};
    }
    bool isOn() const override { return !lit.empty() && lit.back().second == INT64_MAX; }
    double litPart(int64_t from, int64_t to) const
    {
        int64_t on = 0;
        for (const auto &[a, b] : lit) on += std::max<int64_t>(0, std::min(b, to) - std::max(a, from));
        return double(on) / double(to - from);
    }
};

// A free-running webcam: frame k exposed from phase + k·period for exposureUs, stamped
// trueDelayUs after its exposure ended; four buffers, so older frames are dropped. It refuses,
// as the V4L2 backend does, frames whose start computed with its delay bound is before the
// request's instant. Rows are exposed top to bottom over the period (a rolling shutter).
struct DelayedWebcam final : hal::Camera {
    hal::ManualClock &clock;
    const TimedLed &led;
    int64_t periodUs = 33333, exposureUs = 10000, trueDelayUs, boundUs, phaseUs;
    int64_t k = 0;
    uint8_t pixels[32 * 32] = {};
    DelayedWebcam(hal::ManualClock &c, const TimedLed &l, int64_t delayUs, int64_t phase)
            : clock(c), led(l), trueDelayUs(delayUs), boundUs(periodUs), phaseUs(phase)
    {}
    int64_t start(int64_t i) const { return phaseUs + i * periodUs; }
    int64_t stamp(int64_t i) const { return start(i) + exposureUs + trueDelayUs; }
    hal::Error configure(const hal::CameraFormat &) override { return {}; }
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override
    {
        const int64_t notBeforeUs =
            (req.notBeforeMs == hal::CaptureRequest::kAtCall ? clock.monotonicMs() : req.notBeforeMs) * 1000;
        const int64_t deadlineMs = clock.monotonicMs() + req.timeoutMs;
        const int64_t nowUs = clock.monotonicMs() * 1000;
        const int64_t newestDone = (nowUs - phaseUs - exposureUs - trueDelayUs) / periodUs;
        k = std::max(k, newestDone - 3);
        for (;; ++k) {
            if (stamp(k) > clock.monotonicMs() * 1000) clock.advance((stamp(k) + 999) / 1000 - clock.monotonicMs());
            if (clock.monotonicMs() > deadlineMs) return hal::Error::make(hal::Errc::Timeout, "no frame");
            const int64_t believedStart = stamp(k) - exposureUs - boundUs;
            if (believedStart < notBeforeUs) continue;
            for (int y = 0; y < 32; ++y) {
                const int64_t rowStart = start(k) + periodUs * y / 32;
                const double part = led.litPart(rowStart, rowStart + exposureUs);
                std::fill(pixels + y * 32, pixels + y * 32 + 32, uint8_t(20 + 160 * part));
            }
            out->view = {hal::PixelFormat::Grey8, pixels, 32, 32, 32, sizeof pixels};
            out->timestampMs = believedStart / 1000;
            out->latencyUs = believedStart - notBeforeUs;
            out->exposureUs = exposureUs;
            out->stampDelayUs = boundUs;
            out->sequence = uint32_t(k++);
            out->source = "sim-uvc";
            return {};
        }
    }
    hal::Error setStampDelayUs(int us) override
    {
        boundUs = us;
        return {};
    }
};

struct Outcome {
    int64_t saved = -1;
    std::string settings;
};

Outcome measure(int64_t trueDelayUs, int64_t phaseUs)
{
    char t[] = "/tmp/icacam-latency-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    hal::ManualClock clock(5000);
    TimedLed led(clock);
    DelayedWebcam cam(clock, led, trueDelayUs, phaseUs);
    QuietTrigger trigger;
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    EXPECT_TRUE(storage.open(dir, 0).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 64;
    cfg.cameraMaxHeight = 64;
    cfg.journalImages = "none";
    friction::PaperModel model;
    fw::Device device({cam, trigger, led, display, serial, storage, clock}, cfg, model);
    EXPECT_TRUE(device.start().ok());
    clock.advance(1000);
    serial.in = "measure-latency\n";
    device.tick();
    Outcome o;
    const reading::FlatObject r = serial.last("latency");
    if (!r.find("stamp_delay_us")) {
        ADD_FAILURE() << serial.out;
    } else {
        o.saved = int64_t(r.find("stamp_delay_us")->number);
        EXPECT_EQ(cam.boundUs, o.saved); // in use at once
        EXPECT_EQ(device.config().stampDelayUs, o.saved);
    }
    o.settings = storage.read("settings.conf").value;
    EXPECT_FALSE(led.isOn());
    fs::remove_all(dir);
    return o;
}

} // namespace

TEST(MeasureLatency, TheSavedDelayCoversTheCamerasOwnAndIsUnderAFrameAndAnExposureAbove)
{
    for (const int64_t delay : {2000, 9000, 25000, 48000})
        for (const int64_t phase : {0, 11111, 29000}) {
            const Outcome o = measure(delay, phase);
            EXPECT_GE(o.saved, delay) << delay << " phase " << phase; // never lets a stale frame in
            EXPECT_LE(o.saved, delay + 33333 + 10000) << delay << " phase " << phase;
            EXPECT_NE(o.settings.find("stamp_delay_us = " + std::to_string(o.saved)), std::string::npos) << o.settings;
        }
}

TEST(MeasureLatency, ACameraWithSensorStampsHasNothingToMeasure)
{
    // The default Camera answers setStampDelayUs with Invalid: the device says so, saves nothing.
    struct SensorStamped final : hal::Camera {
        uint8_t px[16 * 16] = {};
        hal::ManualClock *clock = nullptr;
        const hal::LedRing *led = nullptr;
        hal::Error configure(const hal::CameraFormat &) override { return {}; }
        using hal::Camera::capture;
        hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override
        {
            clock->advance(33);
            std::fill(std::begin(px), std::end(px), uint8_t(led->isOn() ? 180 : 20));
            out->view = {hal::PixelFormat::Grey8, px, 16, 16, 16, sizeof px};
            out->timestampMs = clock->monotonicMs() - 20;
            const int64_t nb = req.notBeforeMs == hal::CaptureRequest::kAtCall ? clock->monotonicMs() : req.notBeforeMs;
            out->latencyUs = (out->timestampMs - nb) * 1000;
            return {};
        }
    };
    char t[] = "/tmp/icacam-latency-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    hal::ManualClock clock(5000);
    TimedLed led(clock);
    SensorStamped cam;
    cam.clock = &clock;
    cam.led = &led;
    QuietTrigger trigger;
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir, 0).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 64;
    cfg.cameraMaxHeight = 64;
    friction::PaperModel model;
    fw::Device device({cam, trigger, led, display, serial, storage, clock}, cfg, model);
    ASSERT_TRUE(device.start().ok());
    serial.in = "measure-latency\n";
    device.tick();
    const reading::FlatObject e = serial.last("error");
    ASSERT_TRUE(e.find("code")) << serial.out;
    EXPECT_EQ(e.find("code")->text, "latency_failed");
    EXPECT_NE(e.find("message")->text.find("sensor's own"), std::string::npos) << e.find("message")->text;
    EXPECT_EQ(device.config().stampDelayUs, -1);
    fs::remove_all(dir);
}
