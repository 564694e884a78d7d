// `icacam ctl`: the PC side of the device's JSON-lines serial protocol.
#include "host_tools/ctl_command.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <poll.h>
#include <stdexcept>
#include <termios.h>
#include <unistd.h>

#include "host_tools/cli_options.h"

namespace icacam::host {

namespace {

const char *kUsage = "usage: icacam ctl --port DEVICE [--baud 115200] [--timeout-ms 3000] COMMAND [ARG...]\n"
                     "Sends one request (help, status, trigger, get [KEY], set KEY VALUE, results [N],\n"
                     "scalecheck DIAMETER_MM [TOLERANCE_PCT [THICKNESS_MM]], aim, snapshot) and\n"
                     "prints the device's answer lines. Unprompted lines (hello, results of button presses)\n"
                     "that arrive meanwhile are printed too.\n";

speed_t baudConstant(long baud)
{
    switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    default:
        throw cli::UsageError("--baud: unsupported rate " + std::to_string(baud) +
                                  " (9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)",
                              kUsage);
    }
}

// RAII for the port's file descriptor.
struct Port {
    int fd = -1;
    ~Port()
    {
        if (fd >= 0) ::close(fd);
    }
};

// How many answer lines a request gets: `results` announces its count first.
bool answerComplete(const std::string &cmd, const std::string &line, long *expectMore)
{
    if (line.find("\"type\":\"results\"") != std::string::npos) {
        const auto p = line.find("\"count\":");
        *expectMore = p == std::string::npos ? 0 : std::atol(line.c_str() + p + 8);
        return *expectMore == 0;
    }
    if (line.find("\"type\":\"record\"") != std::string::npos) return --*expectMore <= 0;
    if (line.find("\"type\":\"hello\"") != std::string::npos) return false;
    if (cmd == "trigger")
        return line.find("\"type\":\"result\"") != std::string::npos ||
               line.find("\"type\":\"error\"") != std::string::npos;
    return true;
}

} // namespace

int ctlCommand(const std::vector<std::string> &args)
{
    std::string port;
    double baud = 115200, timeoutMs = 3000;
    std::vector<std::string> words;
    // Options come before the device command; everything from the command on is sent.
    cli::OptionReader opts(args, kUsage);
    while (opts.next()) {
        if (!opts.isOption()) {
            words = opts.rest();
            break;
        }
        if (opts.isHelp()) {
            std::cout << kUsage;
            return 0;
        } else if (opts.is("--port"))
            port = opts.value();
        else if (opts.is("--baud")) {
            baud = double(opts.wholeNumber(1, 4000000));
            baudConstant(long(baud)); // refused here, before the port is opened
        } else if (opts.is("--timeout-ms"))
            timeoutMs = double(opts.wholeNumber(1, 3600000));
        else
            opts.unknown();
    }
    if (port.empty() || words.empty()) opts.missing("--port and a command");
    Port p;
    p.fd = ::open(port.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (p.fd < 0) throw std::runtime_error("cannot open " + port + ": " + std::strerror(errno));
    termios tio{};
    if (::tcgetattr(p.fd, &tio) == 0) { // a pty or UART; a plain file or FIFO is used as is
        ::cfmakeraw(&tio);
        const speed_t sp = baudConstant(long(baud));
        ::cfsetispeed(&tio, sp);
        ::cfsetospeed(&tio, sp);
        tio.c_cflag |= CLOCAL | CREAD;
        ::tcsetattr(p.fd, TCSANOW, &tio);
    }
    std::string line;
    for (size_t i = 0; i < words.size(); ++i) line += (i ? " " : "") + words[i];
    line += "\n";
    for (size_t off = 0; off < line.size();) {
        const ssize_t n = ::write(p.fd, line.data() + off, line.size() - off);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error("write to " + port + " failed: " + std::strerror(errno));
        off += size_t(n);
    }

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(long(timeoutMs));
    std::string buf;
    long expectMore = 0;
    int answered = 0;
    char chunk[4096];
    while (std::chrono::steady_clock::now() < deadline) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        pollfd pfd{p.fd, POLLIN, 0};
        const int r = ::poll(&pfd, 1, int(std::max<long long>(1, left)));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        if (pfd.revents & (POLLHUP | POLLERR) && !(pfd.revents & POLLIN))
            throw std::runtime_error("device hung up on " + port);
        const ssize_t n = ::read(p.fd, chunk, sizeof chunk);
        if (n <= 0) break;
        buf.append(chunk, size_t(n));
        if (buf.size() > (1u << 20)) throw std::runtime_error("answer longer than 1 MiB without a newline");
        for (size_t nl; (nl = buf.find('\n')) != std::string::npos;) {
            const std::string l = buf.substr(0, nl);
            buf.erase(0, nl + 1);
            if (l.empty()) continue;
            std::cout << l << "\n";
            if (answerComplete(words[0], l, &expectMore))
                return l.find("\"type\":\"error\"") == std::string::npos ? 0 : 3;
            ++answered;
        }
    }
    std::cout.flush();
    throw std::runtime_error("no complete answer from " + port + " within " + std::to_string(long(timeoutMs)) + " ms" +
                             (answered ? " (partial answer above)" : ""));
}

} // namespace icacam::host
