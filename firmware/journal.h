#pragma once
// The result journal: append-only JSON lines in journal.jsonl, each closed by a CRC-32 of the
// line, fsynced before the result is reported anywhere; each frame saved beside it by
// write-temp-then-rename. recover() at start-up cuts a torn or corrupt tail (keeping the
// bytes in journal.damaged-OFFSET) and removes temporary files, so after a power loss only
// the measurement in flight is lost.
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>

#include "hal/storage.h"

namespace icacam::fw {

uint32_t crc32(std::string_view data);

struct JournalRecovery {
    long records = 0;       // intact records found
    long lastId = 0;        // highest record id (0 when empty)
    uint64_t cutBytes = 0;  // bytes removed from a damaged tail
    int tempFilesRemoved = 0;
};

class Journal {
public:
    static constexpr const char *kFile = "journal.jsonl";

    explicit Journal(hal::Storage &storage, int memory) : storage_(storage), memory_(size_t(memory)) {}
    hal::Error recover(JournalRecovery *out);

    // Appends one record (a JSON object line without the crc, ending in "}\n"). On success
    // the record is durable. Errors: Full, Io.
    hal::Error append(std::string_view record);
    // Saves an image durably (temp + fsync + rename).
    hal::Error saveImage(std::string_view name, std::string_view bytes) { return storage_.writeAtomic(name, bytes); }

    // The most recent records (with crc), oldest first, at most memory.
    const std::deque<std::string> &recent() const { return recent_; }
    long count() const { return count_; }

    // Checks one stored line (without its '\n'); returns the record id or -1.
    static long checkLine(std::string_view line);

private:
    hal::Storage &storage_;
    size_t memory_;
    std::deque<std::string> recent_;
    std::string line_;
    long count_ = 0;
};

} // namespace icacam::fw
