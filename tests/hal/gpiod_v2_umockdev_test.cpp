// The libgpiod 2.x path of hal/gpiod run for real: the trixie library (its C part runs on
// bookworm's glibc) opens a umockdev-mocked /dev/gpiochip0 and talks the GPIO v2 uAPI to
// this test, which answers as the kernel would. Built and run by .ci/check-apis (the library
// is not installable here: docs/hardware.md), not by CMake. Exits 77 without umockdev.
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

constexpr unsigned kLines = 32;

// The kernel's side of a v2 chip: line names GPIO0…GPIO31, requests with their config.
struct FakeChip {
    std::mutex m;
    std::vector<unsigned long> requests;
    gpio_v2_line_request last{};   // the last line request, as the kernel received it
    std::vector<uint64_t> setBits; // every SET_VALUES, the bits of line 0 of the request
    int nextFd = -1;               // handed out as the request's fd
    uint64_t level = 0;            // GET_VALUES answers this
};

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
        std::snprintf(info->label, sizeof info->label, "pinctrl-mock");
        info->lines = kLines;
        break;
    }
    case GPIO_V2_GET_LINEINFO_IOCTL: {
        auto *info = test::ioctlArg<gpio_v2_line_info>(client);
        if (!info || info->offset >= kLines) return fail(EINVAL);
        const unsigned off = info->offset;
        std::memset(info, 0, sizeof *info);
        info->offset = off;
        std::snprintf(info->name, sizeof info->name, "GPIO%u", off);
        break;
    }
    case GPIO_V2_GET_LINE_IOCTL: {
        auto *r = test::ioctlArg<gpio_v2_line_request>(client);
        if (!r || r->num_lines != 1 || r->offsets[0] >= kLines) return fail(EINVAL);
        if (chip->nextFd < 0) return fail(EBUSY);
        chip->last = *r;
        r->fd = std::exchange(chip->nextFd, -1);
        break;
    }
    case GPIO_V2_LINE_SET_VALUES_IOCTL: {
        auto *v = test::ioctlArg<gpio_v2_line_values>(client);
        if (!v) return fail(EFAULT);
        chip->setBits.push_back(v->bits & v->mask & 1u);
        break;
    }
    case GPIO_V2_LINE_GET_VALUES_IOCTL: {
        auto *v = test::ioctlArg<gpio_v2_line_values>(client);
        if (!v) return fail(EFAULT);
        v->bits = chip->level & v->mask;
        break;
    }
    default: return fail(ENOTTY);
    }
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
}

uint64_t attr(const gpio_v2_line_config &c, uint32_t id)
{
    for (uint32_t i = 0; i < c.num_attrs; ++i)
        if (c.attrs[i].attr.id == id) {
            switch (id) {
            case GPIO_V2_LINE_ATTR_ID_FLAGS: return c.attrs[i].attr.flags;
            case GPIO_V2_LINE_ATTR_ID_DEBOUNCE: return c.attrs[i].attr.debounce_period_us;
            default: return c.attrs[i].attr.values;
            }
        }
    return 0;
}

class GpiodV2Mock : public ::testing::Test {
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
    // The request's fd: a pipe for the button (its edge events are read from it), another
    // open of the mocked chip for the LED (its value ioctls come to the handler).
    void nextFdIsEventPipe()
    {
        int p[2];
        ASSERT_EQ(pipe2(p, O_CLOEXEC | O_NONBLOCK), 0);
        chip_.nextFd = p[0];
        eventWrite_ = p[1];
    }
    void nextFdIsChip()
    {
        chip_.nextFd = ::open("/dev/gpiochip0", O_RDWR | O_CLOEXEC);
        ASSERT_GE(chip_.nextFd, 0) << std::strerror(errno);
    }
    void sendEdge(bool rising, uint64_t ns, uint32_t offset, uint32_t seq)
    {
        gpio_v2_line_event e{};
        e.timestamp_ns = ns;
        e.id = rising ? GPIO_V2_LINE_EVENT_RISING_EDGE : GPIO_V2_LINE_EVENT_FALLING_EDGE;
        e.offset = offset;
        e.seqno = e.line_seqno = seq;
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

TEST_F(GpiodV2Mock, ButtonByNameWithBiasKernelDebounceAndEdgesInOrder)
{
    nextFdIsEventPipe();
    hal::ManualClock clock(100000);
    hal::GpiodTrigger trigger(clock);
    hal::GpioLineSpec spec;
    spec.chipPath = "/dev/gpiochip0";
    hal::parseGpioLine("GPIO17", &spec);
    spec.activeLow = true;
    spec.pullUp = true;
    spec.debounceUs = 15000;
    const hal::Error e = trigger.open(spec);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(trigger.where(), "/dev/gpiochip0:17"); // found by name
    {
        std::lock_guard<std::mutex> lock(chip_.m);
        EXPECT_EQ(chip_.last.offsets[0], 17u);
        const uint64_t flags = chip_.last.config.flags | attr(chip_.last.config, GPIO_V2_LINE_ATTR_ID_FLAGS);
        EXPECT_TRUE(flags & GPIO_V2_LINE_FLAG_INPUT);
        EXPECT_TRUE(flags & GPIO_V2_LINE_FLAG_BIAS_PULL_UP);
        EXPECT_TRUE(flags & GPIO_V2_LINE_FLAG_EDGE_RISING);
        EXPECT_TRUE(flags & GPIO_V2_LINE_FLAG_EDGE_FALLING);
        EXPECT_FALSE(flags & GPIO_V2_LINE_FLAG_ACTIVE_LOW);                        // raw edges, decided in the HAL
        EXPECT_EQ(attr(chip_.last.config, GPIO_V2_LINE_ATTR_ID_DEBOUNCE), 15000u); // the kernel debounces
    }
    hal::ButtonEdge edges[8];
    auto none = trigger.readEdges(edges, 8);
    ASSERT_TRUE(none.ok()) << none.error.message;
    EXPECT_EQ(none.value, 0u);
    const uint64_t t = nowNs();
    sendEdge(false, t - 50000000, 17, 1); // pressed (active low) 50 ms ago
    sendEdge(true, t - 20000000, 17, 2);  // released 20 ms ago
    auto r = trigger.readEdges(edges, 8);
    ASSERT_TRUE(r.ok()) << r.error.message;
    ASSERT_EQ(r.value, 2u);
    EXPECT_TRUE(edges[0].pressed);
    EXPECT_FALSE(edges[1].pressed);
    EXPECT_NEAR(double(edges[0].timeMs), 100000.0 - 50, 5);
    EXPECT_NEAR(double(edges[1].timeMs - edges[0].timeMs), 30, 2);
}

TEST_F(GpiodV2Mock, LedByOffsetStartsOffSwitchesAndActiveLowInverts)
{
    nextFdIsChip();
    hal::GpiodLed led;
    ASSERT_TRUE(led.open({"/dev/gpiochip0", 27, false, false}).ok());
    ASSERT_TRUE(led.set(true).ok());
    ASSERT_TRUE(led.set(false).ok());
    {
        std::lock_guard<std::mutex> lock(chip_.m);
        const uint64_t flags = chip_.last.config.flags | attr(chip_.last.config, GPIO_V2_LINE_ATTR_ID_FLAGS);
        EXPECT_TRUE(flags & GPIO_V2_LINE_FLAG_OUTPUT);
        EXPECT_EQ(attr(chip_.last.config, GPIO_V2_LINE_ATTR_ID_OUTPUT_VALUES) & 1u, 0u); // requested off
        EXPECT_EQ(chip_.setBits, (std::vector<uint64_t>{1, 0}));
        chip_.setBits.clear();
    }
    led.close();
    nextFdIsChip();
    hal::GpiodLed low;
    ASSERT_TRUE(low.open({"/dev/gpiochip0", 27, true, false}).ok());
    ASSERT_TRUE(low.set(true).ok());
    std::lock_guard<std::mutex> lock(chip_.m);
    EXPECT_EQ(attr(chip_.last.config, GPIO_V2_LINE_ATTR_ID_OUTPUT_VALUES) & 1u, 1u); // off = high
    EXPECT_EQ(chip_.setBits, (std::vector<uint64_t>{0}));
}

TEST_F(GpiodV2Mock, UnknownLineNameIsNotFound)
{
    hal::SystemClock clock;
    hal::GpiodTrigger trigger(clock);
    hal::GpioLineSpec spec;
    spec.chipPath = "/dev/gpiochip0";
    spec.name = "GPIO99";
    const hal::Error e = trigger.open(spec);
    EXPECT_EQ(e.code, hal::Errc::NotFound) << e.message;
    EXPECT_NE(e.message.find("GPIO99"), std::string::npos);
}

} // namespace

int main(int argc, char **argv)
{
    return icacam::test::runUnderUmockdev(argc, argv, "gpiod_v2_umockdev_test");
}
