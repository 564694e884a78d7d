#pragma once
// The audit trail of the recipe (ISO/IEC 17025 §7.11: data protected against tampering and
// loss): audit.jsonl beside the journal, append-only, each entry fsynced before the change
// it records takes effect. An entry says when (UTC), who, why (a reason is required), what
// changed (key: old -> new) and the version it made, with that version's whole canonical
// text: the trail is also the store of every version, each immutable.
//
// The entries are chained: each carries the previous entry's hash ("prev") and its own
// ("entry", the SHA-256 of its line before that field), and audit.head (written atomically
// after each entry) names the newest entry's number and hash. checkAudit() finds an edited
// entry (its hash), a removed or reordered one (the chain), a cut tail (the head) and a
// version whose text does not match its hash.
#include <string>
#include <string_view>
#include <vector>

#include "hal/storage.h"

namespace icacam::fw {

struct AuditEntry {
    long seq = 0; // 1, 2, ... in the order written
    std::string time, who, why, changes;
    std::string recipe; // the version made: its recipe id, number, hash and text
    long version = 0;
    std::string hash, settings;
    std::string prev, entry; // the chain: the previous entry's hash, this one's
};

struct AuditCheck {
    long entries = 0;                  // entries read
    std::vector<std::string> problems; // empty: intact
    bool ok() const { return problems.empty(); }
};

inline constexpr const char *kAuditFile = "audit.jsonl";
inline constexpr const char *kAuditHead = "audit.head";

// Checks a trail's text and its head file's text (head empty: none); the entries that
// could be read into *entries (each with its own hash checked: an entry edited is left out).
AuditCheck checkAudit(std::string_view log, std::string_view head, std::vector<AuditEntry> *entries);
// One entry's line (with its prev and entry hashes set from e.prev; e.entry is filled in).
std::string auditLine(AuditEntry *e);

class AuditLog {
public:
    explicit AuditLog(hal::Storage &storage) : storage_(storage) {}
    // Reads and checks the trail; the entries readable are kept for newest() and append().
    AuditCheck load();
    // Appends e as the next entry (its seq and prev set here), fsynced, then the head.
    hal::Error append(AuditEntry e);
    // The newest entry whose own hash and version hash hold (nullptr: none).
    const AuditEntry *newest() const;
    // The highest version of recipe id so far (0: none).
    long lastVersion(std::string_view id) const;

private:
    hal::Storage &storage_;
    std::vector<AuditEntry> entries_;
    long lastSeq_ = 0;
    std::string lastHash_;
};

} // namespace icacam::fw
