// The device with a part missing, on the file-backed HAL and a manual clock: without its
// display it measures and says so on serial, in the journal and in the log; without its serial
// line it measures and says so on the display; a part that comes later is found by the retry.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "firmware/device.h"
#include "firmware/font5x7.h"
#include "firmware/parts.h"
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
    int shown = 0;
    hal::Error show(const hal::MonoBitmap &p) override
    {
        last = p;
        ++shown;
        return {};
    }
};

// A part's factory that fails as a missing device does (NotFound) until `there` is set, and then
// hands out the backend given once.
template <typename Interface, typename Backend> struct Socket {
    bool there = false;
    Backend *handedOut = nullptr;
    int opens = 0;
    std::string missingWords;
    explicit Socket(std::string words) : missingWords(std::move(words)) {}
    hal::Result<std::unique_ptr<Interface>> operator()()
    {
        ++opens;
        if (!there) return hal::Result<std::unique_ptr<Interface>>::fail(hal::Errc::NotFound, missingWords);
        auto b = std::make_unique<Backend>();
        handedOut = b.get();
        return {std::move(b), {}};
    }
};

struct Rig {
    std::string dir = makeDir();
    hal::ManualClock clock;
    hal::ScriptedLight light{clock};
    hal::FileCamera camera{clock, {dir + "/frames", 1, true, 0, {}, &light}};
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    hal::FolderStorage storage;
    friction::PaperModel model;
    Socket<hal::Display, RecordingDisplay> displaySocket{"/dev/i2c-1: No such file or directory"};
    Socket<hal::SerialPort, RecordingSerial> serialSocket{"serial /dev/serial0: No such file or directory"};
    fw::DisplayPart display{[this] { return displaySocket(); }};
    fw::SerialPart serial{[this] { return serialSocket(); }};
    fw::TriggerPart button{[this]() -> hal::Result<std::unique_ptr<hal::TriggerButton>> {
        return {std::unique_ptr<hal::TriggerButton>(new Forward(trigger)), {}};
    }};
    fw::LedPart ring{[this]() -> hal::Result<std::unique_ptr<hal::LedRing>> {
        return {std::unique_ptr<hal::LedRing>(new ForwardLed(led)), {}};
    }};
    fw::Parts parts{display, serial, button, ring, clock, 2000};
    std::vector<std::string> log;
    std::unique_ptr<fw::Device> device;

    // The button and ring as the tests' own file backends, which the rig keeps to script them.
    struct Forward final : hal::TriggerButton {
        hal::TriggerButton &to;
        explicit Forward(hal::TriggerButton &t) : to(t) {}
        hal::Result<size_t> readEdges(hal::ButtonEdge *out, size_t cap) override { return to.readEdges(out, cap); }
    };
    struct ForwardLed final : hal::LedRing {
        hal::LedRing &to;
        explicit ForwardLed(hal::LedRing &l) : to(l) {}
        hal::Error set(bool on) override { return to.set(on); }
        bool isOn() const override { return to.isOn(); }
    };

    Rig(bool displayThere, bool serialThere)
    {
        fs::create_directories(dir + "/frames");
        writeGrey(dir + "/frames/a.pgm", 64, 64, 120);
        EXPECT_TRUE(storage.open(dir + "/journal", 0).ok());
        displaySocket.there = displayThere;
        serialSocket.there = serialThere;
        parts.setLog([this](std::string_view l) { log.emplace_back(l); });
        parts.openAll();
        fw::Config cfg;
        cfg.n = 0.2;
        cfg.mmPerPx = 0.0125;
        cfg.cameraMaxWidth = 256;
        cfg.cameraMaxHeight = 256;
        device = std::make_unique<fw::Device>(
            fw::DeviceHal{camera, button, ring, display, serial, storage, clock, &parts}, cfg, model);
    }
    ~Rig() { fs::remove_all(dir); }
    static std::string makeDir()
    {
        char t[] = "/tmp/icacam-parts-test-XXXXXX";
        return ::mkdtemp(t);
    }
    static void writeGrey(const std::string &path, int w, int h, uint8_t v)
    {
        std::ofstream f(path, std::ios::binary);
        f << "P5\n" << w << " " << h << "\n255\n" << std::string(size_t(w * h), char(v));
    }
    std::string journal() { return storage.read(fw::Journal::kFile).value; }
    void press()
    {
        trigger.feed("press 80\n");
        device->tick();
        clock.advance(100);
        device->tick();
    }
};

bool logSays(const std::vector<std::string> &log, const std::string &words)
{
    for (const std::string &l : log)
        if (l.find(words) != std::string::npos) return true;
    return false;
}

} // namespace

TEST(Parts, NoDisplayTheDeviceMeasuresAndSaysSoOnSerialInTheJournalAndTheLog)
{
    Rig rig(false, true);
    ASSERT_TRUE(rig.device->start().ok());
    RecordingSerial &serial = *rig.serialSocket.handedOut;
    const reading::FlatObject hello = serial.last("hello");
    ASSERT_TRUE(hello.find("parts_missing")) << serial.out;
    EXPECT_EQ(hello.find("parts_missing")->text, "display");
    EXPECT_NE(hello.find("display_problem")->text.find("/dev/i2c-1"), std::string::npos);
    const reading::FlatObject part = serial.last("part");
    ASSERT_TRUE(part.find("part")) << serial.out;
    EXPECT_EQ(part.find("part")->text, "display");
    EXPECT_EQ(part.find("state")->text, "missing");
    EXPECT_NE(rig.journal().find("\"type\":\"part\",\"id\":0,\"part\":\"display\",\"state\":\"missing\""),
              std::string::npos)
        << rig.journal();
    EXPECT_TRUE(logSays(rig.log, "display missing: /dev/i2c-1: No such file or directory - trying again every 2 s"));

    rig.press();
    const reading::FlatObject r = serial.last("result");
    ASSERT_TRUE(r.find("id")) << serial.out;
    EXPECT_EQ(r.find("id")->number, 1); // a part event takes no id
    EXPECT_EQ(r.find("source")->text, "a.pgm");
    EXPECT_NE(rig.journal().find("\"type\":\"result\",\"id\":1"), std::string::npos);
    // No error line per picture the missing display could not show: the part said it once.
    EXPECT_EQ(serial.out.find("display_failed"), std::string::npos) << serial.out;
}

TEST(Parts, NoSerialTheDeviceMeasuresAndSaysSoOnTheDisplay)
{
    Rig rig(true, false);
    ASSERT_TRUE(rig.device->start().ok());
    RecordingDisplay &display = *rig.displaySocket.handedOut;
    EXPECT_EQ(fw::readRow(display.last, 7), "no serial");
    EXPECT_TRUE(logSays(rig.log, "serial missing: serial /dev/serial0: No such file or directory"));
    EXPECT_NE(rig.journal().find("\"part\":\"serial\",\"state\":\"missing\""), std::string::npos);

    rig.press();
    EXPECT_EQ(fw::readRow(display.last, 0).substr(0, 2), "#1") << fw::readRow(display.last, 0);
    EXPECT_NE(rig.journal().find("\"type\":\"result\",\"id\":1"), std::string::npos) << rig.journal();
}

TEST(Parts, AMissingPartIsLookedForAgainAndItsReturnReported)
{
    Rig rig(true, false);
    ASSERT_TRUE(rig.device->start().ok());
    const int opens = rig.serialSocket.opens;
    rig.clock.advance(1000);
    rig.device->tick();
    EXPECT_EQ(rig.serialSocket.opens, opens); // not before the retry interval
    rig.serialSocket.there = true;            // the UART is enabled, the link appears
    rig.clock.advance(1000);
    rig.device->tick();
    EXPECT_EQ(rig.serialSocket.opens, opens + 1);
    ASSERT_NE(rig.serialSocket.handedOut, nullptr);
    const reading::FlatObject part = rig.serialSocket.handedOut->last("part");
    ASSERT_TRUE(part.find("state")) << rig.serialSocket.handedOut->out;
    EXPECT_EQ(part.find("part")->text, "serial");
    EXPECT_EQ(part.find("state")->text, "ok");
    EXPECT_TRUE(logSays(rig.log, "serial ok"));
    EXPECT_EQ(fw::readRow(rig.displaySocket.handedOut->last, 7), "");
    // The serial line now answers commands.
    rig.serialSocket.handedOut->in = "status\n";
    rig.device->tick();
    const reading::FlatObject st = rig.serialSocket.handedOut->last("status");
    ASSERT_TRUE(st.find("parts_missing"));
    EXPECT_EQ(st.find("parts_missing")->text, "");
}

TEST(Parts, NeitherDisplayNorSerialStillJournalsEveryMeasurement)
{
    Rig rig(false, false);
    ASSERT_TRUE(rig.device->start().ok());
    rig.press();
    rig.clock.advance(500);
    rig.press();
    const std::string j = rig.journal();
    EXPECT_NE(j.find("\"type\":\"result\",\"id\":1"), std::string::npos) << j;
    EXPECT_NE(j.find("\"type\":\"result\",\"id\":2"), std::string::npos) << j;
    EXPECT_TRUE(logSays(rig.log, "display missing"));
    EXPECT_TRUE(logSays(rig.log, "serial missing"));
}

TEST(Parts, AMissingLedRingIsAReasonOnEveryMeasurementNotAStop)
{
    hal::ManualClock clock;
    fw::LedPart ring([]() -> hal::Result<std::unique_ptr<hal::LedRing>> {
        return hal::Result<std::unique_ptr<hal::LedRing>>::fail(hal::Errc::NotFound,
                                                                "LED chip /dev/gpiochip0: No such file or directory");
    });
    EXPECT_FALSE(ring.open().ok());
    EXPECT_EQ(ring.state(), fw::Part::State::Missing);
    const hal::Error e = ring.set(true);
    EXPECT_EQ(e.code, hal::Errc::NotFound);
    EXPECT_EQ(e.message, "LED ring missing: LED chip /dev/gpiochip0: No such file or directory");
    EXPECT_FALSE(ring.isOn());
}
