// The service notifications as systemd receives them: a datagram socket bound where
// $NOTIFY_SOCKET points (a path, and an abstract "@name"), read back datagram by datagram.
#include <gtest/gtest.h>

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <string>

#include "firmware/sd_notify.h"

namespace {

using icacam::fw::SystemdNotifier;

// The service manager's end.
class Manager {
public:
    explicit Manager(const std::string &address) : address_(address)
    {
        fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        sockaddr_un a{};
        a.sun_family = AF_UNIX;
        std::memcpy(a.sun_path, address.data(), address.size());
        if (a.sun_path[0] == '@') a.sun_path[0] = '\0';
        const socklen_t len = socklen_t(offsetof(sockaddr_un, sun_path) + address.size());
        bound_ = ::bind(fd_, reinterpret_cast<const sockaddr *>(&a), len) == 0;
    }
    ~Manager()
    {
        ::close(fd_);
        if (address_[0] == '/') ::unlink(address_.c_str());
    }
    bool bound() const { return bound_; }
    // The next datagram, "" when none arrives within 200 ms.
    std::string next()
    {
        pollfd p{fd_, POLLIN, 0};
        if (::poll(&p, 1, 200) != 1) return {};
        char buf[1024];
        const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
        return n > 0 ? std::string(buf, size_t(n)) : std::string();
    }

private:
    std::string address_;
    int fd_ = -1;
    bool bound_ = false;
};

std::string tempSocket()
{
    return "/tmp/icacam-notify-" + std::to_string(::getpid()) + "-" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

TEST(SystemdNotifier, ReadyStatusAndStoppingArriveAsDatagrams)
{
    const std::string path = tempSocket();
    Manager manager(path);
    ASSERT_TRUE(manager.bound());
    SystemdNotifier n(path, 0, 0);
    ASSERT_TRUE(n.active());
    ASSERT_TRUE(n.ready("idle").ok());
    EXPECT_EQ(manager.next(), "READY=1\nSTATUS=idle");
    // A status is one assignment: a newline in the text cannot start another one.
    ASSERT_TRUE(n.status("no camera:\nlibcamera: no camera found").ok());
    EXPECT_EQ(manager.next(), "STATUS=no camera: libcamera: no camera found");
    ASSERT_TRUE(n.stopping().ok());
    EXPECT_EQ(manager.next(), "STOPPING=1");
}

TEST(SystemdNotifier, AnAbstractSocketNameIsReachedToo)
{
    const std::string name = "@icacam-notify-" + std::to_string(::getpid());
    Manager manager(name);
    ASSERT_TRUE(manager.bound());
    SystemdNotifier n(name, 0, 0);
    ASSERT_TRUE(n.ready().ok());
    EXPECT_EQ(manager.next(), "READY=1");
}

TEST(SystemdNotifier, TheWatchdogIsFedEveryHalfInterval)
{
    const std::string path = tempSocket();
    Manager manager(path);
    ASSERT_TRUE(manager.bound());
    SystemdNotifier n(path, 30000000, 0); // WatchdogSec=30
    EXPECT_EQ(n.watchdogIntervalUs(), 30000000);
    ASSERT_TRUE(n.keepAlive(1000).ok());
    EXPECT_EQ(manager.next(), "WATCHDOG=1");
    ASSERT_TRUE(n.keepAlive(15999).ok()); // under half the interval since: nothing sent
    EXPECT_EQ(manager.next(), "");
    ASSERT_TRUE(n.keepAlive(16000).ok());
    EXPECT_EQ(manager.next(), "WATCHDOG=1");
}

TEST(SystemdNotifier, AWatchdogMeantForAnotherProcessIsNotFed)
{
    const std::string path = tempSocket();
    Manager manager(path);
    SystemdNotifier n(path, 30000000, ::getpid() + 1);
    EXPECT_EQ(n.watchdogIntervalUs(), 0);
    ASSERT_TRUE(n.keepAlive(1000).ok());
    EXPECT_EQ(manager.next(), "");
}

TEST(SystemdNotifier, TheEnvironmentIsRead)
{
    const std::string path = tempSocket();
    Manager manager(path);
    ::setenv("NOTIFY_SOCKET", path.c_str(), 1);
    ::setenv("WATCHDOG_USEC", "20000000", 1);
    ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
    SystemdNotifier n = SystemdNotifier::fromEnvironment();
    ::unsetenv("NOTIFY_SOCKET");
    ::unsetenv("WATCHDOG_USEC");
    ::unsetenv("WATCHDOG_PID");
    EXPECT_TRUE(n.active());
    EXPECT_EQ(n.watchdogIntervalUs(), 20000000);
    ASSERT_TRUE(n.keepAlive(0).ok());
    EXPECT_EQ(manager.next(), "WATCHDOG=1");
}

TEST(SystemdNotifier, WithoutSystemdEveryCallIsANoOp)
{
    ::unsetenv("NOTIFY_SOCKET");
    SystemdNotifier n = SystemdNotifier::fromEnvironment();
    EXPECT_FALSE(n.active());
    EXPECT_TRUE(n.ready("idle").ok());
    EXPECT_TRUE(n.keepAlive(0).ok());
}

TEST(SystemdNotifier, BadAddressesAndAGoneManagerAreErrorsNotCrashes)
{
    SystemdNotifier relative("run/notify", 0, 0);
    EXPECT_EQ(relative.ready().code, icacam::hal::Errc::Invalid);
    SystemdNotifier nobody(tempSocket(), 0, 0); // nothing bound there
    EXPECT_EQ(nobody.ready().code, icacam::hal::Errc::Io);
    SystemdNotifier tooLong("/" + std::string(200, 'x'), 0, 0);
    EXPECT_EQ(tooLong.ready().code, icacam::hal::Errc::Invalid);
    const std::string path = tempSocket() + "-long";
    Manager manager(path);
    SystemdNotifier n(path, 0, 0);
    ASSERT_TRUE(n.status(std::string(2000, 's')).ok()); // cut to one datagram
    EXPECT_EQ(manager.next().size(), SystemdNotifier::kMaxMessage);
}

} // namespace
