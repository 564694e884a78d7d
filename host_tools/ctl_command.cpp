// `icacam ctl`: the PC side of the device's JSON-lines serial protocol.
#include "host_tools/ctl_command.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <poll.h>
#include <stdexcept>
#include <termios.h>
#include <unistd.h>

#include "host_tools/cli_options.h"
#include "reading/record_line.h"

namespace icacam::host {

namespace {

const char *kUsage = "usage: icacam ctl --port DEVICE [--baud 115200] [--timeout-ms 3000] COMMAND [ARG...]\n"
                     "       icacam ctl --port DEVICE [...] --out FILE snapshot\n"
                     "Sends one request (help, status, trigger, get [KEY], set KEY VALUE, results [N],\n"
                     "scalecheck DIAMETER_MM [TOLERANCE_PCT [THICKNESS_MM]], aim, snapshot, lens POSITION,\n"
                     "focus) and prints the device's answer lines. Unprompted lines (hello, results of button\n"
                     "presses) that arrive meanwhile are printed too. With --out, snapshot also fetches the\n"
                     "picture over the same line and writes it to FILE (a PNG); --timeout-ms is then the\n"
                     "longest silence.\n";

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

void writeLine(int fd, const std::string &port, std::string line)
{
    line += "\n";
    for (size_t off = 0; off < line.size();) {
        const ssize_t n = ::write(fd, line.data() + off, line.size() - off);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error("write to " + port + " failed: " + std::strerror(errno));
        off += size_t(n);
    }
}

// The next line from the device, or false after timeoutMs of silence.
bool readLine(int fd, const std::string &port, std::string *buf, long timeoutMs, std::string *line)
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    char chunk[4096];
    for (;;) {
        if (const size_t nl = buf->find('\n'); nl != std::string::npos) {
            *line = buf->substr(0, nl);
            buf->erase(0, nl + 1);
            if (!line->empty()) return true;
            continue;
        }
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) return false;
        pollfd pfd{fd, POLLIN, 0};
        const int r = ::poll(&pfd, 1, int(left));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        if (pfd.revents & (POLLHUP | POLLERR) && !(pfd.revents & POLLIN))
            throw std::runtime_error("device hung up on " + port);
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n <= 0) return false;
        buf->append(chunk, size_t(n));
        if (buf->size() > (1u << 20)) throw std::runtime_error("answer longer than 1 MiB without a newline");
    }
}

// A text field of a device line ("" when absent); the device's lines are flat JSON.
std::string field(const std::string &line, const std::string &key)
{
    reading::FlatObject o;
    if (!reading::parseFlatObject(line, &o).empty()) return {};
    const reading::JsonField *f = o.find(key);
    if (!f) return {};
    return f->type == reading::JsonField::Type::Number ? std::to_string(static_cast<long long>(f->number)) : f->text;
}

bool isType(const std::string &line, const char *type)
{
    return line.find(std::string("{\"type\":\"") + type + "\"") == 0;
}

void appendBase64(const std::string &text, std::string *out)
{
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    };
    if (text.size() % 4 != 0) throw std::runtime_error("fetch: a data line is not base64");
    for (size_t i = 0; i < text.size(); i += 4) {
        int v[4];
        for (int k = 0; k < 4; ++k) v[k] = text[i + size_t(k)] == '=' ? 0 : value(text[i + size_t(k)]);
        if (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[3] < 0) throw std::runtime_error("fetch: a data line is not base64");
        const uint32_t w = uint32_t(v[0]) << 18 | uint32_t(v[1]) << 12 | uint32_t(v[2]) << 6 | uint32_t(v[3]);
        out->push_back(char(w >> 16));
        if (text[i + 2] != '=') out->push_back(char((w >> 8) & 0xff));
        if (text[i + 3] != '=') out->push_back(char(w & 0xff));
    }
}

// `snapshot` and then `fetch NAME`: the picture written to outPath. 0, or 3 for a device error.
int snapshotToFile(int fd, const std::string &port, long timeoutMs, const std::string &outPath)
{
    std::string buf, line, name;
    writeLine(fd, port, "snapshot");
    while (name.empty()) {
        if (!readLine(fd, port, &buf, timeoutMs, &line))
            throw std::runtime_error("no snapshot from " + port + " within " + std::to_string(timeoutMs) + " ms");
        std::cout << line << "\n";
        if (isType(line, "error")) return 3;
        if (isType(line, "snapshot")) name = field(line, "image");
    }
    writeLine(fd, port, "fetch " + name);
    std::string bytes;
    long want = -1, next = 0;
    for (;;) {
        if (!readLine(fd, port, &buf, timeoutMs, &line))
            throw std::runtime_error("fetch " + name + ": silent for " + std::to_string(timeoutMs) + " ms");
        if (isType(line, "error")) {
            std::cout << line << "\n";
            return 3;
        }
        if (isType(line, "file")) {
            want = std::atol(field(line, "bytes").c_str());
        } else if (isType(line, "data")) {
            if (std::atol(field(line, "i").c_str()) != next++)
                throw std::runtime_error("fetch: a data line is missing");
            appendBase64(field(line, "b64"), &bytes);
        } else if (isType(line, "file_end")) {
            break;
        } else {
            std::cout << line << "\n"; // unprompted lines (a button press) meanwhile
        }
    }
    if (want < 0 || long(bytes.size()) != want)
        throw std::runtime_error("fetch " + name + ": " + std::to_string(bytes.size()) + " bytes arrived, " +
                                 std::to_string(want) + " announced");
    std::ofstream out(outPath, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) throw std::runtime_error("cannot write " + outPath);
    std::cout << "{\"type\":\"saved\",\"image\":\"" << name << "\",\"out\":\"" << outPath
              << "\",\"bytes\":" << bytes.size() << "}\n";
    return 0;
}

} // namespace

int ctlCommand(const std::vector<std::string> &args)
{
    std::string port, outPath;
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
        else if (opts.is("--out"))
            outPath = opts.value();
        else
            opts.unknown();
    }
    if (port.empty() || words.empty()) opts.missing("--port and a command");
    if (!outPath.empty() && !(words.size() == 1 && words[0] == "snapshot"))
        throw cli::UsageError("--out goes with the snapshot command alone", kUsage);
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
    if (!outPath.empty()) return snapshotToFile(p.fd, port, long(timeoutMs), outPath);
    std::string line;
    for (size_t i = 0; i < words.size(); ++i) line += (i ? " " : "") + words[i];
    writeLine(p.fd, port, line);

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
