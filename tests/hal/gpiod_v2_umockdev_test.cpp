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
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "hal/file/clocks.h"
#include "hal/gpiod/gpiod_lines.h"
#include "tests/support/umockdev_mock.h"

namespace {

using namespace icacam;

constexpr unsigned kLines = 32;
constexpr int kHandles = 4; // line request nodes for a ring of segments, /dev/gpiohandle0 …

// The number at the end of a line request node's path ("/dev/gpiohandle1" → 1), else -1.
int handleIndex(const char *devnode)
{
    const char prefix[] = "/dev/gpiohandle";
    if (!devnode || std::strncmp(devnode, prefix, sizeof prefix - 1) != 0) return -1;
    return std::atoi(devnode + sizeof prefix - 1);
}

// The kernel's side of a v2 chip: line names GPIO0…GPIO31, requests with their config. A
// request handed out as a node of its own (/dev/gpiohandleN) names its line when a value is
// set through it.
struct FakeChip {
    std::mutex m;
    std::vector<unsigned long> requests;
    gpio_v2_line_request last{};   // the last line request, as the kernel received it
    std::vector<uint64_t> setBits; // every SET_VALUES, the bits of line 0 of the request
    int nextFd = -1;               // handed out as the request's fd
    uint64_t level = 0;            // GET_VALUES answers this
    std::vector<int> handleFds;    // handed out in turn when nextFd is not set
    size_t nextHandle = 0;
    unsigned handleLine[kHandles] = {};
    int lineLevel[kLines] = {};                   // each line's level, as last requested or set
    std::vector<std::pair<unsigned, int>> writes; // (line, level) in order, the request's too
};

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

gboolean onIoctl(UMockdevIoctlBase *, UMockdevIoctlClient *client, gpointer user)
{
    auto *chip = static_cast<FakeChip *>(user);
    std::lock_guard<std::mutex> lock(chip->m);
    const unsigned long req = umockdev_ioctl_client_get_request(client);
    const int handle = handleIndex(umockdev_ioctl_client_get_devnode(client));
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
        chip->last = *r;
        if (chip->nextFd >= 0) {
            r->fd = std::exchange(chip->nextFd, -1);
        } else if (chip->nextHandle < chip->handleFds.size()) {
            const unsigned off = r->offsets[0];
            chip->handleLine[chip->nextHandle] = off;
            chip->lineLevel[off] = int(attr(r->config, GPIO_V2_LINE_ATTR_ID_OUTPUT_VALUES) & 1u);
            chip->writes.emplace_back(off, chip->lineLevel[off]);
            r->fd = std::exchange(chip->handleFds[chip->nextHandle++], -1);
        } else {
            return fail(EBUSY);
        }
        break;
    }
    case GPIO_V2_LINE_SET_VALUES_IOCTL: {
        auto *v = test::ioctlArg<gpio_v2_line_values>(client);
        if (!v) return fail(EFAULT);
        chip->setBits.push_back(v->bits & v->mask & 1u);
        if (handle >= 0 && handle < kHandles) {
            const unsigned off = chip->handleLine[handle];
            chip->lineLevel[off] = int(v->bits & v->mask & 1u);
            chip->writes.emplace_back(off, chip->lineLevel[off]);
        }
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

class GpiodV2Mock : public ::testing::Test {
protected:
    void SetUp() override
    {
        bed_ = umockdev_testbed_new();
        std::string why;
        ASSERT_TRUE(test::addGpioChip0(bed_, &why)) << why;
        GError *err = nullptr;
        for (int h = 0; h < kHandles; ++h) {
            const std::string name = "gpiohandle" + std::to_string(h);
            const std::string dev = "P: /devices/platform/gpio-mock/" + name + "\nN: " + name +
                                    "\nE: SUBSYSTEM=gpio-handle\nA: dev=254:" + std::to_string(64 + h) + "\\n\n";
            ASSERT_TRUE(umockdev_testbed_add_from_string(bed_, dev.c_str(), &err)) << (err ? err->message : "");
        }
        handler_ = umockdev_ioctl_base_new();
        g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(onIoctl), &chip_);
        ASSERT_TRUE(umockdev_testbed_attach_ioctl(bed_, "/dev/gpiochip0", handler_, &err)) << (err ? err->message : "");
        for (int h = 0; h < kHandles; ++h)
            ASSERT_TRUE(
                umockdev_testbed_attach_ioctl(bed_, ("/dev/gpiohandle" + std::to_string(h)).c_str(), handler_, &err))
                << (err ? err->message : "");
    }
    void TearDown() override
    {
        if (eventWrite_ >= 0) ::close(eventWrite_);
        for (int fd : chip_.handleFds)
            if (fd >= 0) ::close(fd);
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
    // The next n requests' fds: nodes of their own, so a value set names its line.
    void nextFdsAreHandles(int n)
    {
        ASSERT_LE(chip_.handleFds.size() + size_t(n), size_t(kHandles));
        for (int i = 0; i < n; ++i) {
            const std::string node = "/dev/gpiohandle" + std::to_string(chip_.handleFds.size());
            chip_.handleFds.push_back(::open(node.c_str(), O_RDWR | O_CLOEXEC));
            ASSERT_GE(chip_.handleFds.back(), 0) << node << ": " << std::strerror(errno);
        }
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

TEST_F(GpiodV2Mock, SegmentedActiveLowRingLightsOneSegmentAlone)
{
    nextFdsAreHandles(3);
    hal::GpiodLed led;
    std::vector<hal::GpioLineSpec> ring;
    for (unsigned off : {5u, 6u, 7u}) ring.push_back({"/dev/gpiochip0", off, true, false});
    const hal::Error e = led.open(ring);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(led.segments(), 3);
    auto levels = [&] {
        std::lock_guard<std::mutex> lock(chip_.m);
        return std::vector<int>(chip_.lineLevel + 5, chip_.lineLevel + 8);
    };
    EXPECT_EQ(levels(), (std::vector<int>{1, 1, 1})); // each requested off: high
    ASSERT_TRUE(led.set(true).ok());
    EXPECT_EQ(levels(), (std::vector<int>{0, 0, 0}));
    ASSERT_TRUE(led.lightSegment(2).ok());
    EXPECT_EQ(levels(), (std::vector<int>{1, 1, 0}));
    // From one segment to another: the old one is off (high) before the new one lights.
    const size_t from = chip_.writes.size();
    ASSERT_TRUE(led.lightSegment(0).ok());
    EXPECT_EQ(levels(), (std::vector<int>{0, 1, 1}));
    {
        std::lock_guard<std::mutex> lock(chip_.m);
        ASSERT_EQ(chip_.writes.size(), from + 2);
        EXPECT_EQ(chip_.writes[from], (std::pair<unsigned, int>{7, 1}));
        EXPECT_EQ(chip_.writes[from + 1], (std::pair<unsigned, int>{5, 0}));
    }
    EXPECT_EQ(led.lightSegment(3).code, hal::Errc::Invalid);
    led.close();
    EXPECT_EQ(levels(), (std::vector<int>{1, 1, 1}));
}

} // namespace

int main(int argc, char **argv)
{
    return icacam::test::runUnderUmockdev(argc, argv, "gpiod_v2_umockdev_test");
}
