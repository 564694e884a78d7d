#include "hal/termios/termios_serial.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace icacam::hal {

namespace {

bool speedOf(int baud, speed_t *out)
{
    struct Entry {
        int baud;
        speed_t speed;
    };
    static const Entry kTable[] = {{9600, B9600},       {19200, B19200},     {38400, B38400},    {57600, B57600},
                                   {115200, B115200},   {230400, B230400},   {460800, B460800},  {921600, B921600},
                                   {1000000, B1000000}, {2000000, B2000000}, {3000000, B3000000}};
    for (const Entry &e : kTable)
        if (e.baud == baud) {
            *out = e.speed;
            return true;
        }
    return false;
}

int64_t nowMs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return int64_t(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
}

} // namespace

Error TermiosSerial::open(const std::string &device, int baud, int writeTimeoutMs, int reopenMs)
{
    speed_t speed{};
    if (!speedOf(baud, &speed))
        return Error::make(Errc::Invalid, "serial: unsupported baud rate " + std::to_string(baud));
    device_ = device;
    baud_ = baud;
    writeTimeoutMs_ = writeTimeoutMs;
    reopenMs_ = reopenMs;
    reopenAtMs_ = -1;
    return openNow();
}

void TermiosSerial::hungUp()
{
    fd_.reset();
    reopenAtMs_ = nowMs() + reopenMs_;
}

bool TermiosSerial::reopenDue()
{
    if (reopenAtMs_ < 0 || nowMs() < reopenAtMs_) return false;
    if (!openNow().ok()) {
        reopenAtMs_ = nowMs() + reopenMs_;
        return false;
    }
    reopenAtMs_ = -1;
    ++reopened_;
    return true;
}

Error TermiosSerial::openNow()
{
    const std::string &device = device_;
    speed_t speed{};
    (void)speedOf(baud_, &speed);
    fd_.reset(::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
    if (!fd_.valid())
        return Error::make(errno == ENOENT ? Errc::NotFound : Errc::Io,
                           "serial " + device + ": " + std::strerror(errno));
    termios t{};
    if (::tcgetattr(fd_.get(), &t) < 0) {
        const Error e = Error::make(Errc::Io, "serial " + device + ": not a terminal: " + std::strerror(errno));
        fd_.reset();
        return e;
    }
    ::cfmakeraw(&t); // no echo, no line editing, no CR/LF translation, 8 bits
    t.c_cflag &= ~tcflag_t(CSTOPB | PARENB | CRTSCTS);
    t.c_cflag |= CLOCAL | CREAD; // ignore modem lines; receive
    t.c_cc[VMIN] = 0;            // reads return what is there (the fd is non-blocking too)
    t.c_cc[VTIME] = 0;
    ::cfsetispeed(&t, speed);
    ::cfsetospeed(&t, speed);
    if (::tcsetattr(fd_.get(), TCSANOW, &t) < 0) {
        const Error e = Error::make(Errc::Io, "serial " + device + ": tcsetattr: " + std::strerror(errno));
        fd_.reset();
        return e;
    }
    ::tcflush(fd_.get(), TCIOFLUSH); // nothing stale from before the program started
    return {};
}

Result<size_t> TermiosSerial::read(char *buf, size_t cap)
{
    if (!fd_.valid() && !reopenDue()) {
        if (reopenAtMs_ >= 0) return {}; // hung up: nothing to read until it is back
        return Result<size_t>::fail(Errc::Invalid, "serial not open");
    }
    const ssize_t n = ::read(fd_.get(), buf, cap);
    if (n > 0) return Result<size_t>{size_t(n), {}};
    if (n == 0) {
        // With VMIN = 0 "nothing yet" and "hung up" both read 0 bytes; poll tells them apart.
        pollfd p{fd_.get(), POLLIN, 0};
        if (::poll(&p, 1, 0) > 0 && (p.revents & POLLHUP)) {
            hungUp();
            return Result<size_t>::fail(Errc::Closed, "serial " + device_ + ": hung up");
        }
        return {};
    }
    if (errno == EAGAIN || errno == EINTR) return {};
    // A hung-up line (USB gadget unplugged, pty closed) reads EIO.
    if (errno == EIO) {
        hungUp();
        return Result<size_t>::fail(Errc::Closed, "serial " + device_ + ": hung up");
    }
    return Result<size_t>::fail(Errc::Io, "serial " + device_ + ": " + std::strerror(errno));
}

Error TermiosSerial::write(std::string_view data)
{
    if (!fd_.valid() && !reopenDue()) {
        if (reopenAtMs_ >= 0) return Error::make(Errc::Closed, "serial " + device_ + ": hung up, reopening");
        return Error::make(Errc::Invalid, "serial not open");
    }
    const int64_t deadline = nowMs() + writeTimeoutMs_;
    size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd_.get(), data.data() + done, data.size() - done);
        if (n > 0) {
            done += size_t(n);
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EINTR) {
            if (errno == EIO) {
                hungUp();
                return Error::make(Errc::Closed, "serial " + device_ + ": hung up");
            }
            return Error::make(Errc::Io, "serial " + device_ + ": " + std::strerror(errno));
        }
        const int64_t left = deadline - nowMs();
        if (left <= 0) break;
        pollfd p{fd_.get(), POLLOUT, 0};
        (void)::poll(&p, 1, int(left));
    }
    if (done < data.size()) {
        dropped_ += long(data.size() - done);
        return Error::make(Errc::Full, "serial " + device_ + ": far end not reading, output dropped");
    }
    return {};
}

} // namespace icacam::hal
