// `icacam ctl` against a scripted device on a pseudo-terminal.
#include <gtest/gtest.h>

#include <pty.h>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>

#include "host_tools/ctl_command.h"

namespace {
struct PtyPair {
    int master = -1, slave = -1;
    std::string name;
    PtyPair()
    {
        char buf[128];
        if (::openpty(&master, &slave, buf, nullptr, nullptr) == 0) name = buf;
    }
    ~PtyPair()
    {
        if (master >= 0) ::close(master);
        if (slave >= 0) ::close(slave);
    }
};

std::string readLine(int fd)
{
    std::string line;
    char c;
    while (::read(fd, &c, 1) == 1 && c != '\n') line += c;
    return line;
}
void writeAll(int fd, const std::string &s)
{
    ASSERT_EQ(::write(fd, s.data(), s.size()), ssize_t(s.size()));
}
} // namespace

TEST(Ctl, SendsTheRequestAndReadsTheAnswer)
{
    PtyPair pty;
    ASSERT_FALSE(pty.name.empty());
    std::string got;
    std::thread device([&] {
        got = readLine(pty.master);
        writeAll(pty.master, "{\"type\":\"hello\",\"records\":0}\n{\"type\":\"status\",\"state\":\"idle\"}\n");
    });
    EXPECT_EQ(icacam::host::ctlCommand({"--port", pty.name, "--timeout-ms", "3000", "status"}), 0);
    device.join();
    EXPECT_EQ(got, "status");
}

TEST(Ctl, ResultsWaitsForEveryRecord)
{
    PtyPair pty;
    std::string got;
    std::thread device([&] {
        got = readLine(pty.master);
        writeAll(pty.master, "{\"type\":\"results\",\"count\":2}\n{\"type\":\"record\",\"id\":1}\n");
        usleep(50000);
        writeAll(pty.master, "{\"type\":\"record\",\"id\":2}\n");
    });
    EXPECT_EQ(icacam::host::ctlCommand({"--port", pty.name, "results", "2"}), 0);
    device.join();
    EXPECT_EQ(got, "results 2");
}

TEST(Ctl, ErrorAnswerAndSilenceAreReported)
{
    PtyPair pty;
    std::thread device([&] {
        readLine(pty.master);
        writeAll(pty.master, "{\"type\":\"error\",\"code\":\"unknown_command\",\"message\":\"no\"}\n");
    });
    EXPECT_EQ(icacam::host::ctlCommand({"--port", pty.name, "frobnicate"}), 3);
    device.join();
    EXPECT_THROW(icacam::host::ctlCommand({"--port", pty.name, "--timeout-ms", "200", "status"}), std::runtime_error);
    EXPECT_THROW(icacam::host::ctlCommand({"--port", "/nonexistent/tty", "status"}), std::runtime_error);
}
