#pragma once
// The result journal: append-only JSON lines in journal.jsonl, each closed by a CRC-32 of the
// line, fsynced before the result is reported anywhere; each frame saved beside it by
// write-temp-then-rename. recover() at start-up cuts a torn or corrupt tail (keeping the
// bytes in journal.damaged-OFFSET) and removes temporary files, so after a power loss only
// the measurement in flight is lost.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hal/storage.h"

namespace icacam::fw {

struct JournalRecovery {
    long records = 0;      // intact records found
    long lastId = 0;       // highest record id (0 when empty)
    uint64_t cutBytes = 0; // bytes removed from a damaged tail
    int tempFilesRemoved = 0;
};

class Journal {
public:
    static constexpr const char *kFile = "journal.jsonl";

    // memory: how many recent records to keep in RAM (a ring sized once, lines reused).
    Journal(hal::Storage &storage, int memory);
    hal::Error recover(JournalRecovery *out);

    // Appends one record (a JSON object line without the crc, ending in "}\n"). On success
    // the record is durable. Errors: Full, Io.
    hal::Error append(std::string_view record);
    // Saves an image durably (temp + fsync + rename).
    hal::Error saveImage(std::string_view name, std::string_view bytes) { return storage_.writeAtomic(name, bytes); }

    // The most recent records (with crc): recentCount() of them, index 0 the oldest.
    size_t recentCount() const { return used_; }
    std::string_view recent(size_t i) const { return ring_[(head_ + ring_.size() - used_ + i) % ring_.size()]; }
    long count() const { return count_; }

    // Checks one stored line (without its '\n'); returns the record id or -1.
    static long checkLine(std::string_view line);

private:
    hal::Storage &storage_;
    void remember(std::string_view line);

    std::vector<std::string> ring_;
    size_t head_ = 0; // next slot to write
    size_t used_ = 0;
    std::string line_;
    long count_ = 0;
};

} // namespace icacam::fw
