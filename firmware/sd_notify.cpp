#include "firmware/sd_notify.h"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace icacam::fw {

namespace {

int64_t parseInt(const char *s)
{
    if (!s || !*s) return 0;
    char *end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s, &end, 10);
    return errno == 0 && end && *end == '\0' && v > 0 ? int64_t(v) : 0;
}

// "VAR=value" lines into a fixed buffer; false when they do not fit.
struct Message {
    char text[SystemdNotifier::kMaxMessage];
    size_t size = 0;

    bool add(std::string_view line, bool cut = false)
    {
        const size_t room = sizeof text - size - (size ? 1 : 0);
        if (line.size() > room && !cut) return false;
        if (size) text[size++] = '\n';
        const size_t n = line.size() < room ? line.size() : room;
        std::memcpy(text + size, line.data(), n);
        size += n;
        return true;
    }
    bool addStatus(std::string_view status)
    {
        constexpr std::string_view key = "STATUS=";
        char line[SystemdNotifier::kMaxMessage];
        size_t n = 0;
        std::memcpy(line, key.data(), key.size());
        n = key.size();
        // One line: a newline in the text would start another assignment.
        for (char c : status) {
            if (n == sizeof line) break;
            line[n++] = c == '\n' || c == '\r' ? ' ' : c;
        }
        return add(std::string_view(line, n), true);
    }
};

} // namespace

SystemdNotifier SystemdNotifier::fromEnvironment()
{
    const char *socket = std::getenv("NOTIFY_SOCKET");
    return SystemdNotifier(socket ? socket : "", parseInt(std::getenv("WATCHDOG_USEC")),
                           pid_t(parseInt(std::getenv("WATCHDOG_PID"))));
}

SystemdNotifier::SystemdNotifier(std::string socket, int64_t watchdogUs, pid_t watchdogPid)
        : socket_(std::move(socket)), watchdogUs_(watchdogUs > 0 ? watchdogUs : 0)
{
    // A watchdog meant for another process (a parent that did not unset the variables).
    if (watchdogPid > 0 && watchdogPid != ::getpid()) watchdogUs_ = 0;
}

hal::Error SystemdNotifier::send(std::string_view message)
{
    if (!active()) return {};
    if (message.empty() || message.size() > kMaxMessage)
        return hal::Error::make(hal::Errc::Invalid, "sd_notify: message empty or too long");
    if (socket_[0] != '/' && socket_[0] != '@')
        return hal::Error::make(hal::Errc::Invalid, "sd_notify: NOTIFY_SOCKET is neither a path nor @name");
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (socket_.size() >= sizeof addr.sun_path)
        return hal::Error::make(hal::Errc::Invalid, "sd_notify: NOTIFY_SOCKET too long for AF_UNIX");
    std::memcpy(addr.sun_path, socket_.data(), socket_.size());
    // An abstract name is its bytes, no terminator: the address length says where it ends.
    if (addr.sun_path[0] == '@') addr.sun_path[0] = '\0';
    const socklen_t len = socklen_t(offsetof(sockaddr_un, sun_path) + socket_.size());
    if (!fd_.valid()) {
        fd_.reset(::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0));
        if (!fd_.valid())
            return hal::Error::make(hal::Errc::Io, std::string("sd_notify: socket: ") + std::strerror(errno));
    }
    ssize_t n;
    do {
        n = ::sendto(fd_.get(), message.data(), message.size(), MSG_NOSIGNAL, reinterpret_cast<const sockaddr *>(&addr),
                     len);
    } while (n < 0 && errno == EINTR);
    if (n != ssize_t(message.size()))
        return hal::Error::make(hal::Errc::Io, std::string("sd_notify: ") + (n < 0 ? std::strerror(errno) : "short"));
    return {};
}

hal::Error SystemdNotifier::ready(std::string_view status)
{
    Message m;
    m.add("READY=1");
    if (!status.empty()) m.addStatus(status);
    return send(std::string_view(m.text, m.size));
}

hal::Error SystemdNotifier::status(std::string_view text)
{
    Message m;
    m.addStatus(text);
    return send(std::string_view(m.text, m.size));
}

hal::Error SystemdNotifier::stopping()
{
    return send("STOPPING=1");
}

hal::Error SystemdNotifier::keepAlive(int64_t nowMs)
{
    if (watchdogUs_ == 0 || !active()) return {};
    if (keptAlive_ && nowMs - lastKeepAliveMs_ < watchdogUs_ / 2000) return {};
    lastKeepAliveMs_ = nowMs;
    keptAlive_ = true;
    return send("WATCHDOG=1");
}

} // namespace icacam::fw
