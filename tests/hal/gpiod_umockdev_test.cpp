// The libgpiod backends against a mocked /dev/gpiochip0 (umockdev, PLATFORM.md "Testing
// device code without devices"): the real libgpiod opens the chip, requests the lines and
// sets values through the real ioctls, which this test answers as the kernel's GPIO
// character device would. Edge events come through the event fd the line request hands out:
// here the read end of a pipe, into which the test writes the kernel's gpioevent_data.
//
// Needs the umockdev preload library (ctest sets LD_PRELOAD); without it the program exits
// 77 (skipped), like the other tests that need a device.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <linux/gpio.h>
#include <umockdev.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "hal/file/clocks.h"
#include "hal/gpiod/gpiod_lines.h"
#include "tests/support/umockdev_mock.h"

namespace {

using namespace icacam;

constexpr int kLines = 32;

// The kernel's side of the chip: line names/flags, who requested what, values set.
struct FakeChip {
    std::mutex m;
    bool busy[kLines] = {};
    uint32_t requestFlags[kLines] = {};
    std::vector<int> setValues;          // every GPIOHANDLE_SET_LINE_VALUES, first value
    std::vector<unsigned long> requests; // ioctl request codes seen, in order
    int handleFd = -1;                   // handed out by GPIO_GET_LINEHANDLE_IOCTL
    int eventFd = -1;                    // handed out by GPIO_GET_LINEEVENT_IOCTL
    uint32_t eventFlags = 0;
};

// The ioctl's argument is a pointer into the caller: resolve() fetches the struct it points
// at; changes to it are copied back when the call completes.
gboolean onIoctl(UMockdevIoctlBase *, UMockdevIoctlClient *client, gpointer user)
{
    auto *chip = static_cast<FakeChip *>(user);
    std::lock_guard<std::mutex> lock(chip->m);
    const unsigned long req = umockdev_ioctl_client_get_request(client);
    chip->requests.push_back(req);
    auto fail = [&](int err) {
        umockdev_ioctl_client_complete(client, -1, err);
        return TRUE;
    };
    switch (req) {
    case GPIO_GET_CHIPINFO_IOCTL: {
        auto *info = test::ioctlArg<gpiochip_info>(client);
        if (!info) return fail(EFAULT);
        std::snprintf(info->name, sizeof info->name, "gpiochip0");
        std::snprintf(info->label, sizeof info->label, "icacam-mock");
        info->lines = kLines;
        break;
    }
    case GPIO_GET_LINEINFO_IOCTL: {
        auto *info = test::ioctlArg<gpioline_info>(client);
        if (!info || info->line_offset >= kLines) return fail(EINVAL);
        const uint32_t off = info->line_offset;
        std::snprintf(info->name, sizeof info->name, "GPIO%u", off);
        info->flags = chip->busy[off] ? GPIOLINE_FLAG_KERNEL : 0;
        break;
    }
    case GPIO_GET_LINEHANDLE_IOCTL: {
        auto *r = test::ioctlArg<gpiohandle_request>(client);
        if (!r || r->lines != 1 || r->lineoffsets[0] >= kLines) return fail(EINVAL);
        if (chip->busy[r->lineoffsets[0]] || chip->handleFd < 0) return fail(EBUSY);
        chip->busy[r->lineoffsets[0]] = true;
        chip->requestFlags[r->lineoffsets[0]] = r->flags;
        chip->setValues.push_back(r->default_values[0]);
        r->fd = std::exchange(chip->handleFd, -1);
        break;
    }
    case GPIO_GET_LINEEVENT_IOCTL: {
        auto *r = test::ioctlArg<gpioevent_request>(client);
        if (!r || r->lineoffset >= kLines) return fail(EINVAL);
        if (chip->busy[r->lineoffset] || chip->eventFd < 0) return fail(EBUSY);
        chip->busy[r->lineoffset] = true;
        chip->requestFlags[r->lineoffset] = r->handleflags;
        chip->eventFlags = r->eventflags;
        r->fd = std::exchange(chip->eventFd, -1);
        break;
    }
    case GPIOHANDLE_SET_LINE_VALUES_IOCTL: {
        auto *v = test::ioctlArg<gpiohandle_data>(client);
        if (!v) return fail(EFAULT);
        chip->setValues.push_back(v->values[0]);
        break;
    }
    default: return fail(ENOTTY);
    }
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
}

class GpiodMock : public ::testing::Test {
protected:
    void SetUp() override
    {
        bed_ = umockdev_testbed_new();
        std::string why;
        ASSERT_TRUE(test::addGpioChip0(bed_, &why)) << why;
        GError *err = nullptr;
        handler_ = umockdev_ioctl_base_new();
        g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(onIoctl), &chip_);
        ASSERT_TRUE(umockdev_testbed_attach_ioctl(bed_, "/dev/gpiochip0", handler_, &err)) << (err ? err->message : "");
    }
    void TearDown() override
    {
        if (eventWrite_ >= 0) ::close(eventWrite_);
        if (handler_) g_object_unref(handler_);
        if (bed_) g_object_unref(bed_);
    }
    // The fds the chip hands out for the next line requests.
    void prepareEventFd()
    {
        int p[2];
        ASSERT_EQ(pipe2(p, O_CLOEXEC), 0);
        chip_.eventFd = p[0];
        eventWrite_ = p[1];
    }
    void prepareHandleFd()
    {
        // Another open of the mocked chip: its ioctls come to the same handler.
        chip_.handleFd = ::open("/dev/gpiochip0", O_RDWR | O_CLOEXEC);
        ASSERT_GE(chip_.handleFd, 0) << std::strerror(errno);
    }
    void sendEdge(bool rising, uint64_t ns)
    {
        gpioevent_data e{};
        e.timestamp = ns;
        e.id = rising ? GPIOEVENT_EVENT_RISING_EDGE : GPIOEVENT_EVENT_FALLING_EDGE;
        ASSERT_EQ(::write(eventWrite_, &e, sizeof e), ssize_t(sizeof e));
    }
    static uint64_t nowNs()
    {
        timespec ts{};
        clock_gettime(CLOCK_MONOTONIC, &ts);
        return uint64_t(ts.tv_sec) * 1000000000u + uint64_t(ts.tv_nsec);
    }

    UMockdevTestbed *bed_ = nullptr;
    UMockdevIoctlBase *handler_ = nullptr;
    FakeChip chip_;
    int eventWrite_ = -1;
};

TEST_F(GpiodMock, TriggerRequestsBothEdgesWithPullUpAndReportsPressesInOrder)
{
    prepareEventFd();
    hal::ManualClock clock(100000);
    hal::GpiodTrigger trigger(clock);
    hal::GpioLineSpec spec{"/dev/gpiochip0", 17, true, true};
    hal::Error e = trigger.open(spec);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(chip_.eventFlags, uint32_t(GPIOEVENT_REQUEST_BOTH_EDGES));
    EXPECT_TRUE(chip_.requestFlags[17] & GPIOHANDLE_REQUEST_BIAS_PULL_UP);
    EXPECT_FALSE(chip_.requestFlags[17] & GPIOHANDLE_REQUEST_ACTIVE_LOW); // raw edges

    hal::ButtonEdge edges[8];
    auto none = trigger.readEdges(edges, 8);
    ASSERT_TRUE(none.ok()) << none.error.message;
    EXPECT_EQ(none.value, 0u); // nothing yet, and it did not block

    const uint64_t t = nowNs();
    sendEdge(false, t - 50000000); // pressed (active low) 50 ms ago
    sendEdge(true, t - 20000000);  // released 20 ms ago
    auto r = trigger.readEdges(edges, 8);
    ASSERT_TRUE(r.ok()) << r.error.message;
    ASSERT_EQ(r.value, 2u);
    EXPECT_TRUE(edges[0].pressed);
    EXPECT_FALSE(edges[1].pressed);
    // Kernel timestamps placed on the HAL clock by their age (a few ms of slack for qemu).
    EXPECT_NEAR(double(edges[0].timeMs), 100000.0 - 50, 5);
    EXPECT_NEAR(double(edges[1].timeMs - edges[0].timeMs), 30, 2);
}

TEST_F(GpiodMock, TriggerReportsAClosedEventStream)
{
    prepareEventFd();
    hal::SystemClock clock;
    hal::GpiodTrigger trigger(clock);
    ASSERT_TRUE(trigger.open({"/dev/gpiochip0", 17, true, true}).ok());
    ::close(std::exchange(eventWrite_, -1)); // the chip went away
    hal::ButtonEdge edges[4];
    auto r = trigger.readEdges(edges, 4);
    EXPECT_EQ(r.error.code, hal::Errc::Closed) << r.error.message;
}

TEST_F(GpiodMock, BusyLineIsAClearError)
{
    chip_.busy[17] = true;
    prepareEventFd();
    hal::SystemClock clock;
    hal::GpiodTrigger trigger(clock);
    hal::Error e = trigger.open({"/dev/gpiochip0", 17, true, true});
    EXPECT_EQ(e.code, hal::Errc::Io);
    EXPECT_NE(e.message.find("gpiochip0:17"), std::string::npos) << e.message;
}

TEST_F(GpiodMock, MissingChipIsNotFound)
{
    hal::SystemClock clock;
    hal::GpiodTrigger trigger(clock);
    hal::Error e = trigger.open({"/dev/gpiochip7", 17, true, true});
    EXPECT_EQ(e.code, hal::Errc::NotFound) << e.message;
    hal::ButtonEdge edges[1];
    EXPECT_EQ(trigger.readEdges(edges, 1).error.code, hal::Errc::Invalid);
}

TEST_F(GpiodMock, LedStartsOffSwitchesAndIsOffWhenClosed)
{
    prepareHandleFd();
    hal::GpiodLed led;
    hal::Error e = led.open({"/dev/gpiochip0", 27, false, false});
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_TRUE(chip_.requestFlags[27] & GPIOHANDLE_REQUEST_OUTPUT);
    ASSERT_TRUE(led.set(true).ok());
    EXPECT_TRUE(led.isOn());
    ASSERT_TRUE(led.set(false).ok());
    ASSERT_TRUE(led.set(true).ok());
    led.close();
    std::lock_guard<std::mutex> lock(chip_.m);
    // Requested low (off), then on, off, on, and off again when closed.
    EXPECT_EQ(chip_.setValues, (std::vector<int>{0, 1, 0, 1, 0}));
}

TEST_F(GpiodMock, ActiveLowLedInvertsTheLevel)
{
    prepareHandleFd();
    hal::GpiodLed led;
    ASSERT_TRUE(led.open({"/dev/gpiochip0", 27, true, false}).ok());
    ASSERT_TRUE(led.set(true).ok());
    led.close();
    std::lock_guard<std::mutex> lock(chip_.m);
    EXPECT_EQ(chip_.setValues, (std::vector<int>{1, 0, 1}));
}

} // namespace

int main(int argc, char **argv)
{
    return icacam::test::runUnderUmockdev(argc, argv, "gpiod_umockdev_test");
}
