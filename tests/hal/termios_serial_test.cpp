// The termios serial port over a pseudo-terminal pair (openpty honours termios natively and
// under qemu, PLATFORM.md): raw mode and baud applied, bytes both ways, non-blocking reads,
// a stuck far end drops output instead of stalling, hang-up reported.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <utility>

#include "hal/termios/termios_serial.h"

namespace {

using namespace icacam;

struct Pty {
    int master = -1, slave = -1;
    std::string path;
    Pty()
    {
        char name[128];
        if (openpty(&master, &slave, name, nullptr, nullptr) == 0) path = name;
    }
    ~Pty()
    {
        if (master >= 0) ::close(master);
        if (slave >= 0) ::close(slave);
    }
};

TEST(TermiosSerial, RawModeBaudAndBytesBothWays)
{
    Pty pty;
    ASSERT_FALSE(pty.path.empty());
    hal::TermiosSerial serial;
    hal::Error e = serial.open(pty.path, 115200);
    ASSERT_TRUE(e.ok()) << e.message;
    termios t{};
    ASSERT_EQ(tcgetattr(pty.slave, &t), 0);
    EXPECT_EQ(cfgetospeed(&t), speed_t(B115200));
    EXPECT_FALSE(t.c_lflag & (ICANON | ECHO));
    EXPECT_FALSE(t.c_oflag & OPOST);
    EXPECT_EQ(t.c_cflag & CSIZE, tcflag_t(CS8));

    char buf[64];
    auto r = serial.read(buf, sizeof buf);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.value, 0u); // nothing there: returns at once

    const std::string cmd = "{\"cmd\":\"measure\"}\r\n";
    ASSERT_EQ(::write(pty.master, cmd.data(), cmd.size()), ssize_t(cmd.size()));
    std::string got;
    for (int i = 0; i < 100 && got.size() < cmd.size(); ++i) {
        r = serial.read(buf, sizeof buf);
        ASSERT_TRUE(r.ok()) << r.error.message;
        got.append(buf, r.value);
        if (!r.value) usleep(2000);
    }
    EXPECT_EQ(got, cmd); // raw: CR kept, no echo, no translation

    ASSERT_TRUE(serial.write("{\"ok\":true}\n").ok());
    char out[64];
    const ssize_t n = ::read(pty.master, out, sizeof out);
    ASSERT_GT(n, 0);
    EXPECT_EQ(std::string(out, size_t(n)), "{\"ok\":true}\n"); // no \n → \r\n
}

TEST(TermiosSerial, StuckFarEndDropsOutputWithinTheTimeout)
{
    Pty pty;
    hal::TermiosSerial serial;
    ASSERT_TRUE(serial.open(pty.path, 9600, 50).ok());
    const std::string block(4096, 'x');
    hal::Error e;
    for (int i = 0; i < 64 && e.ok(); ++i) e = serial.write(block); // nobody reads the master
    EXPECT_EQ(e.code, hal::Errc::Full) << e.message;
    EXPECT_GT(serial.droppedBytes(), 0);
}

TEST(TermiosSerial, HangUpIsClosed)
{
    Pty pty;
    hal::TermiosSerial serial;
    ASSERT_TRUE(serial.open(pty.path, 115200).ok());
    ::close(pty.slave);
    pty.slave = -1;
    ::close(pty.master); // the far end goes away
    pty.master = -1;
    char buf[8];
    auto r = serial.read(buf, sizeof buf);
    EXPECT_EQ(r.error.code, hal::Errc::Closed) << r.error.message;
}

// The USB gadget unplugged and plugged back: the tty comes back under the same name (here a
// symlink repointed to a new pseudo-terminal) and the port is opened again by itself.
TEST(TermiosSerial, HungUpPortIsReopenedWhenTheDeviceComesBack)
{
    char t[] = "/tmp/icacam-tty-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    const std::string link = dir + "/ttyGS0";
    auto first = std::make_unique<Pty>();
    ASSERT_EQ(::symlink(first->path.c_str(), link.c_str()), 0);
    hal::TermiosSerial serial;
    ASSERT_TRUE(serial.open(link, 115200, 200, 20).ok());
    ::close(std::exchange(first->slave, -1));
    ::close(std::exchange(first->master, -1)); // unplugged
    char buf[16];
    EXPECT_EQ(serial.read(buf, sizeof buf).error.code, hal::Errc::Closed);
    auto quiet = serial.read(buf, sizeof buf); // while it is away: nothing, no error
    EXPECT_TRUE(quiet.ok()) << quiet.error.message;
    EXPECT_EQ(quiet.value, 0u);

    Pty second; // plugged back in
    ::unlink(link.c_str());
    ASSERT_EQ(::symlink(second.path.c_str(), link.c_str()), 0);
    ::usleep(30000);
    ASSERT_TRUE(serial.read(buf, sizeof buf).ok()); // reopens (and flushes what was pending)
    EXPECT_EQ(serial.reopened(), 1);
    ASSERT_EQ(::write(second.master, "status\n", 7), 7);
    size_t got = 0;
    for (int i = 0; i < 50 && got == 0; ++i) {
        auto r = serial.read(buf, sizeof buf);
        ASSERT_TRUE(r.ok()) << r.error.message;
        got = r.value;
        if (!got) ::usleep(10000);
    }
    EXPECT_EQ(std::string(buf, got), "status\n");
    EXPECT_EQ(serial.reopened(), 1);
    EXPECT_TRUE(serial.write("ok\n").ok());
    char back[8] = {};
    ::usleep(10000);
    EXPECT_EQ(::read(second.master, back, sizeof back), 3);
    EXPECT_EQ(std::string(back, 3), "ok\n");
    ::unlink(link.c_str());
    ::rmdir(dir.c_str());
}

TEST(TermiosSerial, BadBaudAndMissingDevice)
{
    hal::TermiosSerial serial;
    EXPECT_EQ(serial.open("/dev/null", 12345).code, hal::Errc::Invalid);
    EXPECT_EQ(serial.open("/dev/ttyNOPE", 115200).code, hal::Errc::NotFound);
    EXPECT_EQ(serial.open("/dev/null", 115200).code, hal::Errc::Io); // not a terminal
}

} // namespace
