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

#include <algorithm>
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

constexpr int kLines = 32;
constexpr int kChips = 2;   // /dev/gpiochip0 and /dev/gpiochip1
constexpr int kHandles = 6; // line handle nodes, /dev/gpiohandle0 …

// A line as the fake knows it: chip · kLines + offset (on gpiochip0 the offset itself).
int lineKey(int chip, uint32_t offset)
{
    return chip * kLines + int(offset);
}

// The number at the end of a node's path ("/dev/gpiochip1" → 1), -1 for another node.
int nodeIndex(const char *devnode, const char *prefix)
{
    const size_t n = std::strlen(prefix);
    if (!devnode || std::strncmp(devnode, prefix, n) != 0) return -1;
    return std::atoi(devnode + n);
}

// The kernel's side of the chips: line names/flags, who requested what, values set. A line
// handle is a node of its own (/dev/gpiohandleN), so a value set through it names its line.
struct FakeChip {
    std::mutex m;
    bool busy[kChips * kLines] = {};
    uint32_t requestFlags[kChips * kLines] = {};
    std::vector<int> setValues;          // every GPIOHANDLE_SET_LINE_VALUES, first value
    std::vector<unsigned long> requests; // ioctl request codes seen, in order
    std::vector<int> handleFds;          // handed out by GPIO_GET_LINEHANDLE_IOCTL, in order
    size_t nextHandle = 0;
    int handleLine[kHandles] = {};           // the line each handle node was handed out for
    int level[kChips * kLines] = {};         // each line's level, as last requested or set
    std::vector<std::pair<int, int>> writes; // (line, level) in order, the request's default too
    int failLine = -1;                       // setting this line's value fails with EIO
    int eventFd = -1;                        // handed out by GPIO_GET_LINEEVENT_IOCTL
    uint32_t eventFlags = 0;

    void write(int line, int value)
    {
        level[line] = value;
        writes.emplace_back(line, value);
    }
};

// The ioctl's argument is a pointer into the caller: resolve() fetches the struct it points
// at; changes to it are copied back when the call completes.
gboolean onIoctl(UMockdevIoctlBase *, UMockdevIoctlClient *client, gpointer user)
{
    auto *chip = static_cast<FakeChip *>(user);
    std::lock_guard<std::mutex> lock(chip->m);
    const unsigned long req = umockdev_ioctl_client_get_request(client);
    const char *node = umockdev_ioctl_client_get_devnode(client);
    const int chipNo = std::max(0, nodeIndex(node, "/dev/gpiochip"));
    chip->requests.push_back(req);
    auto fail = [&](int err) {
        umockdev_ioctl_client_complete(client, -1, err);
        return TRUE;
    };
    switch (req) {
    case GPIO_GET_CHIPINFO_IOCTL: {
        auto *info = test::ioctlArg<gpiochip_info>(client);
        if (!info) return fail(EFAULT);
        std::snprintf(info->name, sizeof info->name, "gpiochip%d", chipNo);
        std::snprintf(info->label, sizeof info->label, "icacam-mock");
        info->lines = kLines;
        break;
    }
    case GPIO_GET_LINEINFO_IOCTL: {
        auto *info = test::ioctlArg<gpioline_info>(client);
        if (!info || info->line_offset >= kLines) return fail(EINVAL);
        const uint32_t off = info->line_offset;
        std::snprintf(info->name, sizeof info->name, "GPIO%u", off);
        info->flags = chip->busy[lineKey(chipNo, off)] ? GPIOLINE_FLAG_KERNEL : 0;
        break;
    }
    case GPIO_GET_LINEHANDLE_IOCTL: {
        auto *r = test::ioctlArg<gpiohandle_request>(client);
        if (!r || r->lines != 1 || r->lineoffsets[0] >= kLines) return fail(EINVAL);
        const int line = lineKey(chipNo, r->lineoffsets[0]);
        if (chip->busy[line] || chip->nextHandle >= chip->handleFds.size()) return fail(EBUSY);
        chip->busy[line] = true;
        chip->requestFlags[line] = r->flags;
        chip->setValues.push_back(r->default_values[0]);
        chip->write(line, r->default_values[0]);
        chip->handleLine[chip->nextHandle] = line;
        r->fd = std::exchange(chip->handleFds[chip->nextHandle++], -1);
        break;
    }
    case GPIO_GET_LINEEVENT_IOCTL: {
        auto *r = test::ioctlArg<gpioevent_request>(client);
        if (!r || r->lineoffset >= kLines) return fail(EINVAL);
        const int line = lineKey(chipNo, r->lineoffset);
        if (chip->busy[line] || chip->eventFd < 0) return fail(EBUSY);
        chip->busy[line] = true;
        chip->requestFlags[line] = r->handleflags;
        chip->eventFlags = r->eventflags;
        r->fd = std::exchange(chip->eventFd, -1);
        break;
    }
    case GPIOHANDLE_SET_LINE_VALUES_IOCTL: {
        auto *v = test::ioctlArg<gpiohandle_data>(client);
        const int handle = nodeIndex(node, "/dev/gpiohandle");
        if (!v) return fail(EFAULT);
        if (handle < 0 || handle >= kHandles) return fail(ENOTTY);
        if (chip->handleLine[handle] == chip->failLine) return fail(EIO);
        chip->setValues.push_back(v->values[0]);
        chip->write(chip->handleLine[handle], v->values[0]);
        break;
    }
    default: return fail(ENOTTY);
    }
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
}

// A node in the testbed: a GPIO chip (with the /sys/bus/gpio/devices link libgpiod checks
// its numbers against) or a line handle. False with the reason in *error.
bool addNode(UMockdevTestbed *bed, const std::string &name, int minor, bool gpioChip, std::string *error)
{
    GError *err = nullptr;
    const std::string sysPath = "/devices/platform/gpio-mock/" + name;
    const std::string dev = "P: " + sysPath + "\nN: " + name + "\nE: SUBSYSTEM=" + (gpioChip ? "gpio" : "gpio-handle") +
                            "\nE: DEVNAME=/dev/" + name + "\nA: dev=254:" + std::to_string(minor) + "\\n\n";
    if (!umockdev_testbed_add_from_string(bed, dev.c_str(), &err)) {
        *error = err ? err->message : "umockdev_testbed_add_from_string failed";
        if (err) g_error_free(err);
        return false;
    }
    if (gpioChip) {
        gchar *sys = umockdev_testbed_get_sys_dir(bed);
        const std::string bus = std::string(sys) + "/bus/gpio/devices";
        g_mkdir_with_parents(bus.c_str(), 0755);
        (void)symlink((std::string(sys) + sysPath).c_str(), (bus + "/" + name).c_str());
        g_free(sys);
    }
    return true;
}

class GpiodMock : public ::testing::Test {
protected:
    void SetUp() override
    {
        bed_ = umockdev_testbed_new();
        std::string why;
        ASSERT_TRUE(test::addGpioChip0(bed_, &why)) << why;
        ASSERT_TRUE(addNode(bed_, "gpiochip1", 1, true, &why)) << why;
        for (int h = 0; h < kHandles; ++h)
            ASSERT_TRUE(addNode(bed_, "gpiohandle" + std::to_string(h), 64 + h, false, &why)) << why;
        GError *err = nullptr;
        handler_ = umockdev_ioctl_base_new();
        g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(onIoctl), &chip_);
        std::vector<std::string> nodes{"/dev/gpiochip0", "/dev/gpiochip1"};
        for (int h = 0; h < kHandles; ++h) nodes.push_back("/dev/gpiohandle" + std::to_string(h));
        for (const std::string &n : nodes)
            ASSERT_TRUE(umockdev_testbed_attach_ioctl(bed_, n.c_str(), handler_, &err)) << (err ? err->message : "");
    }
    void TearDown() override
    {
        if (eventWrite_ >= 0) ::close(eventWrite_);
        for (int fd : chip_.handleFds)
            if (fd >= 0) ::close(fd);
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
    // The next n line handles: nodes of the mocked testbed, whose ioctls come to the same
    // handler, named by the node.
    void prepareHandleFds(int n)
    {
        ASSERT_LE(chip_.handleFds.size() + size_t(n), size_t(kHandles));
        for (int i = 0; i < n; ++i) {
            const std::string node = "/dev/gpiohandle" + std::to_string(chip_.handleFds.size());
            chip_.handleFds.push_back(::open(node.c_str(), O_RDWR | O_CLOEXEC));
            ASSERT_GE(chip_.handleFds.back(), 0) << node << ": " << std::strerror(errno);
        }
    }
    void prepareHandleFd() { prepareHandleFds(1); }
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

// The most lines lit at once from the write'th level change on, replaying the chip's history.
int mostLitTogether(const FakeChip &chip, size_t from)
{
    int level[kChips * kLines] = {};
    for (size_t i = 0; i < from; ++i) level[chip.writes[i].first] = chip.writes[i].second;
    int most = 0;
    for (size_t i = from; i < chip.writes.size(); ++i) {
        level[chip.writes[i].first] = chip.writes[i].second;
        most = std::max(most, int(std::count(level, level + kChips * kLines, 1)));
    }
    return most;
}

TEST_F(GpiodMock, SegmentedRingOpensALineEachAndLightsOneSegmentAlone)
{
    prepareHandleFds(4);
    hal::GpiodLed led;
    std::vector<hal::GpioLineSpec> ring;
    for (unsigned off : {20u, 21u, 22u, 23u}) ring.push_back({"/dev/gpiochip0", off, false, false});
    const hal::Error e = led.open(ring);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(led.segments(), 4);
    EXPECT_FALSE(led.isOn());
    {
        std::lock_guard<std::mutex> lock(chip_.m);
        for (int off : {20, 21, 22, 23}) {
            EXPECT_TRUE(chip_.requestFlags[off] & GPIOHANDLE_REQUEST_OUTPUT) << off;
            EXPECT_EQ(chip_.level[off], 0) << off; // requested off
        }
    }
    ASSERT_TRUE(led.set(true).ok()); // the whole ring: every segment
    EXPECT_TRUE(led.isOn());
    EXPECT_EQ(std::vector<int>(chip_.level + 20, chip_.level + 24), (std::vector<int>{1, 1, 1, 1}));
    ASSERT_TRUE(led.lightSegment(2).ok());
    EXPECT_TRUE(led.isOn());
    EXPECT_EQ(std::vector<int>(chip_.level + 20, chip_.level + 24), (std::vector<int>{0, 0, 1, 0}));
    // From one segment to the next: the old one is off before the new one lights.
    const size_t before = chip_.writes.size();
    ASSERT_TRUE(led.lightSegment(0).ok());
    ASSERT_TRUE(led.lightSegment(3).ok());
    EXPECT_EQ(std::vector<int>(chip_.level + 20, chip_.level + 24), (std::vector<int>{0, 0, 0, 1}));
    EXPECT_EQ(mostLitTogether(chip_, before), 1);
    // No such segment: refused, nothing switched.
    const size_t writes = chip_.writes.size();
    EXPECT_EQ(led.lightSegment(4).code, hal::Errc::Invalid);
    EXPECT_EQ(led.lightSegment(-1).code, hal::Errc::Invalid);
    EXPECT_EQ(chip_.writes.size(), writes);
    ASSERT_TRUE(led.set(false).ok()); // ends the segment
    EXPECT_FALSE(led.isOn());
    EXPECT_EQ(std::vector<int>(chip_.level + 20, chip_.level + 24), (std::vector<int>{0, 0, 0, 0}));
    ASSERT_TRUE(led.lightSegment(1).ok());
    led.close(); // off when closed
    EXPECT_EQ(std::vector<int>(chip_.level + 20, chip_.level + 24), (std::vector<int>{0, 0, 0, 0}));
    EXPECT_EQ(led.lightSegment(1).code, hal::Errc::Invalid); // closed
}

TEST_F(GpiodMock, ActiveLowSegmentsOnTwoChips)
{
    prepareHandleFds(3);
    hal::GpiodLed led;
    const hal::Error e = led.open(std::vector<hal::GpioLineSpec>{
        {"/dev/gpiochip0", 5, true, false}, {"/dev/gpiochip1", 5, true, false}, {"/dev/gpiochip0", 6, true, false}});
    ASSERT_TRUE(e.ok()) << e.message;
    ASSERT_EQ(led.segments(), 3);
    const int lines[3] = {lineKey(0, 5), lineKey(1, 5), lineKey(0, 6)};
    auto levels = [&] {
        std::lock_guard<std::mutex> lock(chip_.m);
        return std::vector<int>{chip_.level[lines[0]], chip_.level[lines[1]], chip_.level[lines[2]]};
    };
    EXPECT_EQ(levels(), (std::vector<int>{1, 1, 1})); // requested off: high
    ASSERT_TRUE(led.lightSegment(1).ok());
    EXPECT_EQ(levels(), (std::vector<int>{1, 0, 1})); // the segment on the second chip, low
    ASSERT_TRUE(led.set(true).ok());
    EXPECT_EQ(levels(), (std::vector<int>{0, 0, 0}));
    ASSERT_TRUE(led.lightSegment(2).ok());
    EXPECT_EQ(levels(), (std::vector<int>{1, 1, 0}));
    led.close();
    EXPECT_EQ(levels(), (std::vector<int>{1, 1, 1}));
}

TEST_F(GpiodMock, OneLineRingHasNoSegmentToLightAlone)
{
    prepareHandleFd();
    hal::GpiodLed led;
    ASSERT_TRUE(led.open({"/dev/gpiochip0", 27, false, false}).ok());
    EXPECT_EQ(led.segments(), 1);
    EXPECT_EQ(led.lightSegment(0).code, hal::Errc::Invalid);
    EXPECT_FALSE(led.isOn());
    EXPECT_EQ(led.open(std::vector<hal::GpioLineSpec>{}).code, hal::Errc::Invalid);
}

TEST_F(GpiodMock, ASegmentLineThatFailsIsNamed)
{
    // Busy when opened: the ring is not opened, the error names the segment's line. (The
    // fake does not see the lines opened before it released: the next ring takes others.)
    chip_.busy[22] = true;
    prepareHandleFds(2);
    hal::GpiodLed busy;
    std::vector<hal::GpioLineSpec> ring;
    for (unsigned off : {20u, 21u, 22u}) ring.push_back({"/dev/gpiochip0", off, false, false});
    hal::Error e = busy.open(ring);
    EXPECT_EQ(e.code, hal::Errc::Io);
    EXPECT_NE(e.message.find("segment 2 line /dev/gpiochip0:22"), std::string::npos) << e.message;
    EXPECT_EQ(busy.segments(), 1); // nothing open
    EXPECT_EQ(busy.lightSegment(0).code, hal::Errc::Invalid);

    // A line that refuses its value: the others are still switched; a segment beside it is
    // not lit while it may still be.
    prepareHandleFds(3);
    hal::GpiodLed led;
    ring = {{"/dev/gpiochip0", 10, false, false},
            {"/dev/gpiochip0", 11, false, false},
            {"/dev/gpiochip0", 12, false, false}};
    ASSERT_TRUE(led.open(ring).ok());
    chip_.failLine = 11;
    e = led.set(true);
    EXPECT_EQ(e.code, hal::Errc::Io);
    EXPECT_NE(e.message.find("LED segment 1 line /dev/gpiochip0:11"), std::string::npos) << e.message;
    EXPECT_EQ(chip_.level[10], 1);
    EXPECT_EQ(chip_.level[12], 1);
    e = led.lightSegment(0);
    EXPECT_EQ(e.code, hal::Errc::Io);
    EXPECT_NE(e.message.find("gpiochip0:11"), std::string::npos) << e.message;
    EXPECT_EQ(chip_.level[12], 0); // the others off all the same
    EXPECT_EQ(chip_.level[10], 0); // and segment 0 not lit beside a line that may be
    EXPECT_TRUE(led.isOn());       // line 11's level is unknown
    chip_.failLine = -1;
    ASSERT_TRUE(led.lightSegment(0).ok()); // the line answers again: switched off, then 0 on
    EXPECT_EQ(chip_.level[11], 0);
    EXPECT_EQ(chip_.level[10], 1);
}

} // namespace

int main(int argc, char **argv)
{
    return icacam::test::runUnderUmockdev(argc, argv, "gpiod_umockdev_test");
}
