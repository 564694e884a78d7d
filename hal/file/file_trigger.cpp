#include "hal/file/file_trigger.h"

#include <fcntl.h>
#include <sys/stat.h>

#include <cerrno>
#include <charconv>
#include <cstring>

namespace icacam::hal {

Error FileTrigger::open(const std::string &path)
{
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        return Error::make(Errc::NotFound, "trigger script '" + path + "': " + std::strerror(errno));
    const int flags = (S_ISFIFO(st.st_mode) ? O_RDWR : O_RDONLY) | O_NONBLOCK | O_CLOEXEC;
    fd_.reset(::open(path.c_str(), flags));
    if (!fd_.valid()) return Error::make(Errc::Io, "trigger script '" + path + "': " + std::strerror(errno));
    start_ = cursor_ = lastQueued_ = clock_.monotonicMs();
    return {};
}

void FileTrigger::feed(std::string_view text)
{
    partial_.append(text);
    size_t nl;
    while ((nl = partial_.find('\n')) != std::string::npos) {
        parseLine(std::string_view(partial_).substr(0, nl));
        partial_.erase(0, nl + 1);
    }
    if (partial_.size() > 4096) partial_.clear(); // a runaway line is dropped, not buffered forever
}

void FileTrigger::pushEdge(int64_t t, bool pressed)
{
    if (t < lastQueued_) t = lastQueued_; // edges stay in time order, as the kernel delivers them
    lastQueued_ = t;
    queue_.push_back({t, pressed});
}

void FileTrigger::parseLine(std::string_view line)
{
    if (size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::string_view words[3];
    int nw = 0;
    size_t i = 0;
    while (nw < 3) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        if (i >= line.size()) break;
        const size_t b = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        words[nw++] = line.substr(b, i - b);
    }
    if (nw == 0) return;
    auto number = [](std::string_view w, int64_t *v) {
        auto r = std::from_chars(w.data(), w.data() + w.size(), *v);
        return r.ec == std::errc() && r.ptr == w.data() + w.size() && *v >= 0;
    };
    const int64_t now = clock_.monotonicMs();
    if (cursor_ < now) cursor_ = now;
    int64_t v = 0;
    if (words[0] == "press") {
        int64_t hold = 100;
        if (nw >= 2 && !number(words[1], &hold)) {
            lastError_ = "bad hold time in: " + std::string(line);
            return;
        }
        pushEdge(cursor_, true);
        cursor_ += hold;
        pushEdge(cursor_, false);
    } else if (words[0] == "down" || words[0] == "up") {
        pushEdge(cursor_, words[0] == "down");
    } else if (words[0] == "wait" && nw >= 2 && number(words[1], &v)) {
        cursor_ += v;
    } else if (nw >= 2 && number(words[0], &v) && (words[1] == "down" || words[1] == "up")) {
        cursor_ = start_ + v;
        pushEdge(cursor_, words[1] == "down");
    } else {
        lastError_ = "unknown trigger script line: " + std::string(line);
    }
}

Result<size_t> FileTrigger::readEdges(ButtonEdge *out, size_t cap)
{
    if (fd_.valid()) {
        char buf[1024];
        for (;;) {
            const ssize_t n = ::read(fd_.get(), buf, sizeof buf);
            if (n > 0) {
                feed(std::string_view(buf, size_t(n)));
                continue;
            }
            if (n < 0 && errno == EINTR) continue;
            if (n < 0 && errno != EAGAIN) return Result<size_t>::fail(Errc::Io, std::strerror(errno));
            break; // EAGAIN, or end of a script file
        }
    }
    const int64_t now = clock_.monotonicMs();
    size_t n = 0;
    while (n < cap && !queue_.empty() && queue_.front().timeMs <= now) {
        out[n++] = queue_.front();
        queue_.pop_front();
    }
    return {n, {}};
}

} // namespace icacam::hal
