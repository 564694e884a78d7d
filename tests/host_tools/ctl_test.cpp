// `icacam ctl` against a scripted device on a pseudo-terminal.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
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

// `--out FILE snapshot`: the snapshot's name from the device's answer, then `fetch NAME`, the
// base64 lines put back together into the file; a line missing is refused, not written.
TEST(Ctl, SnapshotIsFetchedOverTheSameLine)
{
    PtyPair pty;
    char t[] = "/tmp/icacam-ctl-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    std::string asked, fetched;
    std::thread device([&] {
        asked = readLine(pty.master);
        writeAll(pty.master, "{\"type\":\"snapshot\",\"image\":\"snap-000004-17.png\",\"width\":64}\n");
        fetched = readLine(pty.master);
        // "\x89PNG\r\n" and "abc": two lines, the second with padding.
        writeAll(pty.master, "{\"type\":\"file\",\"name\":\"snap-000004-17.png\",\"bytes\":9,\"lines\":2}\n"
                             "{\"type\":\"data\",\"i\":0,\"b64\":\"iVBORw0K\"}\n"
                             "{\"type\":\"data\",\"i\":1,\"b64\":\"YWJj\"}\n"
                             "{\"type\":\"file_end\",\"name\":\"snap-000004-17.png\",\"bytes\":9}\n");
    });
    EXPECT_EQ(icacam::host::ctlCommand({"--port", pty.name, "--out", dir + "/s.png", "snapshot"}), 0);
    device.join();
    EXPECT_EQ(asked, "snapshot");
    EXPECT_EQ(fetched, "fetch snap-000004-17.png");
    std::ifstream in(dir + "/s.png", std::ios::binary);
    const std::string got((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(got, std::string("\x89PNG\r\n", 6) + "abc");

    std::thread broken([&] {
        readLine(pty.master);
        writeAll(pty.master, "{\"type\":\"snapshot\",\"image\":\"snap-000005-18.png\"}\n");
        readLine(pty.master);
        writeAll(pty.master, "{\"type\":\"file\",\"name\":\"snap-000005-18.png\",\"bytes\":9,\"lines\":2}\n"
                             "{\"type\":\"data\",\"i\":1,\"b64\":\"YWJj\"}\n"
                             "{\"type\":\"file_end\",\"name\":\"snap-000005-18.png\",\"bytes\":9}\n");
    });
    EXPECT_THROW(icacam::host::ctlCommand({"--port", pty.name, "--out", dir + "/t.png", "snapshot"}),
                 std::runtime_error);
    broken.join();
    EXPECT_FALSE(std::ifstream(dir + "/t.png").good());
    EXPECT_THROW(icacam::host::ctlCommand({"--port", pty.name, "--out", dir + "/u.png", "status"}), std::exception);
    std::filesystem::remove_all(dir);
}
