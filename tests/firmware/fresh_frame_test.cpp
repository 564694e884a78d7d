// The frame measured is the first one exposed after the LED ring settled, whatever the
// driver has queued. A simulated free-running sensor delivers frames the way the real
// pipelines do (stale frames completed in the dark and waiting in the queue, frames in
// flight when the light settled that complete after it, then fresh ones), stamped the way
// each driver stamps them; the double picks frames with the production rule
// (hal/fresh_frame.h) on those stamps only. The device is driven over serial on a manual
// clock; the test knows every frame's true exposure start and checks each result.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <filesystem>
#include <random>
#include <vector>

#include "firmware/device.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/fresh_frame.h"
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

// How a driver stamps and completes a frame, relative to the start of its first row's
// exposure (µs). All frames complete in the order they were exposed.
struct DriverModel {
    const char *name;
    int64_t periodUs, exposureUs;
    int64_t stampAfterStartUs;       // the timestamp the rule reads
    int64_t completeAfterStartUs;    // when the application gets the buffer
    int64_t bufferStampAfterStartUs; // the buffer's own timestamp (what a naive rule reads)
    int64_t declaredDelayUs;         // the stamp's delay bound the backend is told
    int buffers;
};

// Pi 5 (PiSP): SensorTimestamp at readout start; the ISP stamps the buffer when it is done,
// one and a half frames later. Pi 4 (Unicam): the same sensor stamp, completion after the
// frame and the ISP. UVC: stamped at the first USB packet (the stamp the backend reads is
// the buffer's own), uncompressed soon after readout starts, MJPEG after encoding.
const DriverModel kPiSp{"pisp", 33333, 10000, 10000, 10000 + 50000, 10000 + 50000, 0, 4};
const DriverModel kUnicam{"unicam", 33333, 20000, 20000, 20000 + 33333 + 5000, 20000 + 33333 + 5000, 0, 4};
const DriverModel kUvcYuyv{"uvc-yuyv", 33333, 8000, 8000 + 1000, 8000 + 33333, 8000 + 1000, 1000, 4};
const DriverModel kUvcMjpeg{"uvc-mjpeg", 33333, 15000, 15000 + 9000, 15000 + 33333 + 9000, 15000 + 9000, 9000, 3};

// A free-running sensor behind a request queue, on the test's manual clock (µs = ms × 1000).
class SimulatedSensor final : public hal::Camera {
public:
    SimulatedSensor(hal::ManualClock &clock, DriverModel m, int64_t phaseUs) : clock_(clock), m_(m), phase_(phaseUs)
    {
        pixels_.assign(64 * 48, 0);
    }
    hal::Error configure(const hal::CameraFormat &) override
    {
        free_ = m_.buffers;
        next_ = firstStartingAfter(nowUs());
        inflight_.clear();
        done_.clear();
        held_ = -1;
        return {};
    }
    using hal::Camera::capture;
    hal::Error capture(const hal::CaptureRequest &req, hal::CapturedFrame *out) override
    {
        advance();
        if (held_ >= 0) ++free_, held_ = -1; // requeued: usable by frames starting from now
        const int64_t notBeforeNs =
            (req.notBeforeMs == hal::CaptureRequest::kAtCall ? clock_.monotonicMs() : req.notBeforeMs) * 1000000;
        const int64_t deadline = clock_.monotonicMs() + req.timeoutMs;
        int stale = 0;
        for (;;) {
            while (!done_.empty()) {
                const int64_t k = done_.front();
                done_.pop_front();
                hal::FrameStamp st;
                st.stampNs = (start(k) + m_.stampAfterStartUs) * 1000;
                st.exposureNs = m_.exposureUs * 1000;
                st.stampDelayNs = m_.declaredDelayUs * 1000;
                if (!hal::exposedAfter(st, notBeforeNs)) {
                    ++stale;
                    ++free_;
                    continue;
                }
                held_ = k;
                std::fill(pixels_.begin(), pixels_.end(), uint8_t(k % 256));
                out->view = {hal::PixelFormat::Grey8, pixels_.data(), 64, 48, 64, pixels_.size()};
                out->timestampMs = hal::exposureStartNs(st) / 1000000;
                out->latencyUs = (hal::exposureStartNs(st) - notBeforeNs) / 1000;
                out->exposureUs = m_.exposureUs;
                out->sequence = uint32_t(k);
                out->staleFrames = stale;
                out->controls = {int(m_.exposureUs), 2.0, 1.5, 1.7, -1, -1, -1};
                out->source = std::string("sim-") + m_.name;
                return {};
            }
            if (clock_.monotonicMs() >= deadline)
                return hal::Error::make(hal::Errc::Timeout, "simulated sensor: nothing fresh");
            clock_.advance(1);
            advance();
        }
    }

    int64_t start(int64_t k) const { return phase_ + k * m_.periodUs; }
    int64_t firstStartingAfter(int64_t tUs) const // first k with start(k) >= tUs
    {
        return tUs <= phase_ ? 0 : (tUs - phase_ + m_.periodUs - 1) / m_.periodUs;
    }
    // The frame whose buffer timestamp is the first at or after tUs (what a rule on the
    // buffer timestamp would measure).
    int64_t firstBufferStampedAfter(int64_t tUs) const { return firstStartingAfter(tUs - m_.bufferStampAfterStartUs); }

private:
    int64_t nowUs() const { return clock_.monotonicMs() * 1000; }
    // Runs the sensor up to now: a frame gets a request if one is free when it starts
    // (else the pipeline drops it); completed ones join the done queue in order.
    void advance()
    {
        const int64_t now = nowUs();
        for (; start(next_) <= now; ++next_)
            if (free_ > 0) --free_, inflight_.push_back(next_);
        while (!inflight_.empty() && start(inflight_.front()) + m_.completeAfterStartUs <= now) {
            done_.push_back(inflight_.front());
            inflight_.pop_front();
        }
    }

    hal::ManualClock &clock_;
    DriverModel m_;
    int64_t phase_;
    int free_ = 0;
    int64_t next_ = 0, held_ = -1;
    std::deque<int64_t> inflight_, done_;
    std::vector<uint8_t> pixels_;
};

struct QuietTrigger final : hal::TriggerButton {
    hal::Result<size_t> readEdges(hal::ButtonEdge *, size_t) override { return {}; }
};
// Records when the ring was switched on.
struct TimedLed final : hal::LedRing {
    explicit TimedLed(hal::ManualClock &c) : clock(c) {}
    hal::ManualClock &clock;
    bool on = false;
    int64_t onAtMs = -1;
    hal::Error set(bool v) override
    {
        if (v && !on) onAtMs = clock.monotonicMs();
        on = v;
        return {};
    }
    bool isOn() const override { return on; }
};
struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

struct Outcome {
    int measured = 0, naiveWouldDiffer = 0;
};

// Triggers `shots` measurements at irregular times; each result must carry the first frame
// whose exposure started at or after the settle instant, and its latency.
Outcome runModel(const DriverModel &m, int shots, uint32_t seed)
{
    Outcome o;
    char t[] = "/tmp/icacam-fresh-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    hal::ManualClock clock(10000);
    std::mt19937 rng(seed);
    SimulatedSensor cam(clock, m, 1000 + int64_t(rng() % 30000));
    QuietTrigger trigger;
    TimedLed led(clock);
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    EXPECT_TRUE(storage.open(dir, 0).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 64;
    cfg.cameraMaxHeight = 48;
    cfg.journalImages = "none";
    cfg.ledSettleMs = 20;
    cfg.captureTimeoutMs = 1000;
    friction::PaperModel model;
    fw::Device device({cam, trigger, led, display, serial, storage, clock}, cfg, model);
    EXPECT_TRUE(device.start().ok());
    for (int i = 0; i < shots; ++i) {
        clock.advance(50 + int64_t(rng() % 400)); // the technician's pace: any phase
        serial.out.clear();
        serial.in = "trigger\n";
        device.tick();
        const reading::FlatObject r = serial.last("result");
        const reading::JsonField *seq = r.find("frame_seq"), *lat = r.find("latency_us");
        if (!seq || !lat) {
            ADD_FAILURE() << m.name << ": no capture fields in " << serial.out;
            break;
        }
        const int64_t litUs = (led.onAtMs + cfg.ledSettleMs) * 1000;
        const int64_t want = cam.firstStartingAfter(litUs);
        EXPECT_EQ(int64_t(seq->number), want) << m.name << " shot " << i;
        EXPECT_EQ(int64_t(lat->number), cam.start(want) - litUs) << m.name << " shot " << i;
        EXPECT_GE(int64_t(lat->number), 0);
        if (cam.firstBufferStampedAfter(litUs) != want) ++o.naiveWouldDiffer;
        ++o.measured;
    }
    std::printf("%s: %d shots, each the first frame exposed after the light; a rule on the buffer timestamp would "
                "have measured another frame in %d\n",
                m.name, o.measured, o.naiveWouldDiffer);
    fs::remove_all(dir);
    return o;
}

TEST(FreshFrame, Pi5IspCompletionOrderMeasuresTheFirstFrameExposedAfterTheLight)
{
    const Outcome o = runModel(kPiSp, 60, 1);
    EXPECT_EQ(o.measured, 60);
    // The case the rule is for: a frame exposed (partly) in the dark but stamped by the ISP
    // after the light settled was in the queue in most shots.
    EXPECT_GT(o.naiveWouldDiffer, 30);
}

TEST(FreshFrame, Pi4UnicamMeasuresTheFirstFrameExposedAfterTheLight)
{
    EXPECT_EQ(runModel(kUnicam, 60, 2).measured, 60);
}

TEST(FreshFrame, UvcStampsAtFirstPacketMeasureTheFirstFrameExposedAfterTheLight)
{
    const Outcome yuyv = runModel(kUvcYuyv, 60, 3);
    EXPECT_EQ(yuyv.measured, 60);
    const Outcome mjpeg = runModel(kUvcMjpeg, 60, 4);
    EXPECT_EQ(mjpeg.measured, 60);
    EXPECT_GT(mjpeg.naiveWouldDiffer, 10);
}

} // namespace
