#include "hal/file/pty_serial.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace icacam::hal {

Error PtySerial::open(const std::string &linkPath, int writeTimeoutMs)
{
    int m = -1, s = -1;
    termios tio{};
    cfmakeraw(&tio);
    if (::openpty(&m, &s, nullptr, &tio, nullptr) != 0)
        return Error::make(Errc::Io, std::string("openpty: ") + std::strerror(errno));
    master_.reset(m);
    slave_.reset(s);
    ::fcntl(m, F_SETFD, FD_CLOEXEC);
    ::fcntl(s, F_SETFD, FD_CLOEXEC);
    ::fcntl(m, F_SETFL, ::fcntl(m, F_GETFL) | O_NONBLOCK);
    const char *name = ::ttyname(s);
    if (!name) return Error::make(Errc::Io, std::string("ttyname: ") + std::strerror(errno));
    slavePath_ = name;
    writeTimeoutMs_ = writeTimeoutMs;
    if (!linkPath.empty()) {
        const std::string tmp = linkPath + ".tmp";
        ::unlink(tmp.c_str());
        if (::symlink(slavePath_.c_str(), tmp.c_str()) != 0 || ::rename(tmp.c_str(), linkPath.c_str()) != 0)
            return Error::make(Errc::Io, "serial link '" + linkPath + "': " + std::strerror(errno));
        linkPath_ = linkPath;
    }
    return {};
}

PtySerial::~PtySerial()
{
    if (!linkPath_.empty()) ::unlink(linkPath_.c_str());
}

Result<size_t> PtySerial::read(char *buf, size_t cap)
{
    if (!master_.valid()) return Result<size_t>::fail(Errc::Invalid, "serial not open");
    for (;;) {
        const ssize_t n = ::read(master_.get(), buf, cap);
        if (n >= 0) return {size_t(n), {}};
        if (errno == EINTR) continue;
        if (errno == EAGAIN || errno == EIO) return {0, {}}; // EIO: no slave open right now
        return Result<size_t>::fail(Errc::Io, std::string("serial read: ") + std::strerror(errno));
    }
}

Error PtySerial::write(std::string_view data)
{
    if (!master_.valid()) return Error::make(Errc::Invalid, "serial not open");
    size_t done = 0;
    int waitedMs = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(master_.get(), data.data() + done, data.size() - done);
        if (n > 0) {
            done += size_t(n);
            stalled_ = false;
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && errno != EAGAIN)
            return Error::make(Errc::Io, std::string("serial write: ") + std::strerror(errno));
        // Once a write has timed out, later ones do not wait again until the far end reads:
        // a device with nobody listening must not slow down by the timeout per line.
        if (waitedMs >= (stalled_ ? 0 : writeTimeoutMs_)) {
            stalled_ = true;
            return Error::make(Errc::Full, "serial output dropped: nobody is reading");
        }
        pollfd p{master_.get(), POLLOUT, 0};
        ::poll(&p, 1, 10);
        waitedMs += 10;
    }
    return {};
}

} // namespace icacam::hal
