#include "firmware/net/journal_tail.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "firmware/journal.h"

namespace icacam::fw::net {

namespace {

struct Fd {
    int fd;
    ~Fd()
    {
        if (fd >= 0) ::close(fd);
    }
};

bool preadAll(int fd, char *buf, size_t n, uint64_t offset)
{
    while (n > 0) {
        const ssize_t r = ::pread(fd, buf, n, off_t(offset));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        buf += r;
        n -= size_t(r);
        offset += uint64_t(r);
    }
    return true;
}

} // namespace

std::string JournalTail::refresh()
{
    std::lock_guard<std::mutex> lock(mutex_);
    Fd f{::open(path_.c_str(), O_RDONLY | O_CLOEXEC)};
    if (f.fd < 0) {
        if (errno == ENOENT) {
            index_.clear();
            scanned_ = 0;
            return "";
        }
        return path_ + ": " + std::strerror(errno);
    }
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) return path_ + ": " + std::strerror(errno);
    const uint64_t size = uint64_t(st.st_size);
    if (size < scanned_) { // cut at the device's start (a torn tail): read it again
        index_.clear();
        scanned_ = 0;
    }
    std::string chunk;
    constexpr size_t kChunk = 256 * 1024;
    while (scanned_ < size) {
        const size_t n = size_t(std::min<uint64_t>(kChunk, size - scanned_));
        chunk.resize(n);
        if (!preadAll(f.fd, chunk.data(), n, scanned_)) return path_ + ": read failed";
        size_t start = 0;
        for (;;) {
            const size_t nl = chunk.find('\n', start);
            if (nl == std::string::npos) break;
            const std::string_view line(chunk.data() + start, nl - start);
            const long id = Journal::checkLine(line);
            // Ids rise through the journal; a line out of order or damaged is not indexed.
            if (id > 0 && (index_.empty() || id > index_.back().id))
                index_.push_back({id, scanned_ + start, uint32_t(line.size())});
            start = nl + 1;
        }
        if (start == 0) {
            if (n == kChunk) { // a line longer than a chunk is no record: skip it
                scanned_ += n;
                continue;
            }
            break; // a torn last line: looked at again next time
        }
        scanned_ += start;
    }
    return "";
}

long JournalTail::newestId() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return index_.empty() ? 0 : index_.back().id;
}

bool JournalTail::readAt(int fd, const Entry &e, std::string *out)
{
    out->resize(e.length);
    return fd >= 0 && preadAll(fd, out->data(), e.length, e.offset);
}

std::vector<std::string> JournalTail::after(long after, size_t max) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out;
    Fd f{::open(path_.c_str(), O_RDONLY | O_CLOEXEC)};
    auto it = std::upper_bound(index_.begin(), index_.end(), after, [](long id, const Entry &e) { return id < e.id; });
    for (; it != index_.end() && out.size() < max; ++it) {
        std::string s;
        if (!readAt(f.fd, *it, &s)) break;
        out.push_back(std::move(s));
    }
    return out;
}

std::vector<std::string> JournalTail::last(size_t n) const
{
    long after = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (n < index_.size()) after = index_[index_.size() - n - 1].id;
    }
    return this->after(after, n);
}

bool JournalTail::line(long id, std::string *out) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = std::lower_bound(index_.begin(), index_.end(), id, [](const Entry &e, long v) { return e.id < v; });
    if (it == index_.end() || it->id != id) return false;
    Fd f{::open(path_.c_str(), O_RDONLY | O_CLOEXEC)};
    return readAt(f.fd, *it, out);
}

std::string JournalTail::all() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    std::string out, s;
    Fd f{::open(path_.c_str(), O_RDONLY | O_CLOEXEC)};
    for (const Entry &e : index_)
        if (readAt(f.fd, e, &s)) (out += s) += '\n';
    return out;
}

} // namespace icacam::fw::net
