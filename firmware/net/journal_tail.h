#pragma once
// The journal as the network side reads it: journal.jsonl opened read-only beside the
// device that appends to it, read on from where the last look ended, each intact line
// (CRC checked) indexed by its record id. A torn last line is left for the next look.
// Thread-safe; never used on the device's thread.
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace icacam::fw::net {

class JournalTail {
public:
    explicit JournalTail(std::string path) : path_(std::move(path)) {}

    // Reads what was appended since the last call. "" or why the file cannot be read (a
    // missing file is an empty journal).
    std::string refresh();
    long newestId() const;
    // Up to max lines (without '\n') of the records after id `after`, oldest first.
    std::vector<std::string> after(long after, size_t max) const;
    // The last n lines, oldest first.
    std::vector<std::string> last(size_t n) const;
    // The line of record id; false when there is none.
    bool line(long id, std::string *out) const;
    // Every intact line, oldest first, for a download.
    std::string all() const;

private:
    struct Entry {
        long id;
        uint64_t offset;
        uint32_t length;
    };
    static bool readAt(int fd, const Entry &e, std::string *out);

    std::string path_;
    mutable std::mutex mutex_;
    std::vector<Entry> index_;
    uint64_t scanned_ = 0; // bytes up to the end of the last whole line looked at
};

} // namespace icacam::fw::net
