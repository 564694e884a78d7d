#include "firmware/audit_log.h"

#include <cstdio>
#include <cstdlib>

#include "firmware/recipe.h"
#include "reading/record_line.h"

namespace icacam::fw {

namespace {

constexpr std::string_view kEntryField = ",\"entry\":\"";
const std::string kGenesis(64, '0'); // the first entry's prev

std::string text(const reading::FlatObject &o, const char *key)
{
    const reading::JsonField *f = o.find(key);
    return f && f->type == reading::JsonField::Type::String ? f->text : std::string();
}

long whole(const reading::FlatObject &o, const char *key)
{
    const reading::JsonField *f = o.find(key);
    return f && f->type == reading::JsonField::Type::Number ? long(f->number) : -1;
}

// The hash an entry line carries and the hash of what precedes it; false when the line does
// not end in the entry field.
bool entryHashes(std::string_view line, std::string_view *carried, std::string *computed)
{
    const size_t at = line.rfind(kEntryField);
    if (at == std::string_view::npos || line.size() != at + kEntryField.size() + 64 + 2 || line.back() != '}')
        return false;
    *carried = line.substr(at + kEntryField.size(), 64);
    *computed = recipeHash(line.substr(0, at));
    return true;
}

} // namespace

std::string auditLine(AuditEntry *e)
{
    std::string line;
    reading::JsonBuilder j(&line);
    j.integer("seq", e->seq).str("time", e->time).str("who", e->who).str("why", e->why).str("changes", e->changes);
    j.str("recipe", e->recipe).integer("version", e->version).str("hash", e->hash).str("settings", e->settings);
    j.str("prev", e->prev);
    e->entry = recipeHash(line);
    ((line += kEntryField) += e->entry) += "\"}\n";
    return line;
}

AuditCheck checkAudit(std::string_view log, std::string_view head, std::vector<AuditEntry> *entries)
{
    AuditCheck c;
    entries->clear();
    auto problem = [&c](std::string p) { c.problems.push_back(std::move(p)); };
    std::string expectPrev = kGenesis;
    long lastSeq = 0, lineNo = 0;
    std::vector<std::pair<long, std::string>> chain; // every entry read: its seq and carried hash
    reading::FlatObject obj;
    while (!log.empty()) {
        ++lineNo;
        const size_t nl = log.find('\n');
        if (nl == std::string_view::npos) {
            problem("line " + std::to_string(lineNo) + ": a torn last entry (a write cut short)");
            break;
        }
        const std::string_view line = log.substr(0, nl);
        log.remove_prefix(nl + 1);
        const std::string where = "line " + std::to_string(lineNo);
        std::string_view carried;
        std::string computed;
        if (!reading::parseFlatObject(line, &obj).empty() || !entryHashes(line, &carried, &computed)) {
            problem(where + ": not an audit entry (altered or foreign)");
            expectPrev.clear(); // the next entry's link cannot be checked
            continue;
        }
        ++c.entries;
        AuditEntry e;
        e.seq = whole(obj, "seq");
        e.time = text(obj, "time");
        e.who = text(obj, "who");
        e.why = text(obj, "why");
        e.changes = text(obj, "changes");
        e.recipe = text(obj, "recipe");
        e.version = whole(obj, "version");
        e.hash = text(obj, "hash");
        e.settings = text(obj, "settings");
        e.prev = text(obj, "prev");
        e.entry = std::string(carried);
        const std::string name = where + " (entry " + std::to_string(e.seq) + ")";
        bool intact = true;
        if (computed != carried) {
            problem(name + ": altered (its content does not match its hash)");
            intact = false;
        }
        if (!expectPrev.empty() && e.prev != expectPrev)
            problem(name + ": does not follow the entry before it (one was removed, inserted or reordered)");
        if (e.seq != lastSeq + 1)
            problem(name + (e.seq > lastSeq + 1 ? ": entries " + std::to_string(lastSeq + 1) + " to " +
                                                      std::to_string(e.seq - 1) + " are missing"
                                                : ": out of order after entry " + std::to_string(lastSeq)));
        if (recipeHash(e.settings) != e.hash) {
            problem(name + ": the settings of " + e.recipe + " version " + std::to_string(e.version) +
                    " do not match its hash");
            intact = false;
        }
        expectPrev = e.entry;
        lastSeq = e.seq;
        chain.emplace_back(e.seq, e.entry);
        if (intact) entries->push_back(std::move(e));
    }
    // The head: the newest entry as written, kept apart, so a cut tail shows.
    long headSeq = 0;
    char headHash[65] = "";
    while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.remove_suffix(1);
    if (head.empty()) {
        if (!chain.empty()) problem(std::string(kAuditHead) + " is missing");
    } else if (head.size() > 90 || std::sscanf(std::string(head).c_str(), "%ld %64s", &headSeq, headHash) != 2) {
        problem(std::string(kAuditHead) + " is not readable");
    } else if (chain.empty() || headSeq > chain.back().first) {
        problem(std::string(kAuditHead) + " names entry " + std::to_string(headSeq) + " but the trail ends at " +
                std::to_string(chain.empty() ? 0 : chain.back().first) + ": entries at its end were removed");
    } else {
        // A head behind the trail by one: a power loss between an entry and its head.
        bool found = false;
        for (const auto &[seq, hash] : chain)
            if (seq == headSeq) found = hash == headHash;
        if (!found || headSeq + 1 < chain.back().first)
            problem(std::string(kAuditHead) + " does not match entry " + std::to_string(headSeq) +
                    ": the trail's end was replaced");
    }
    return c;
}

AuditCheck AuditLog::load()
{
    hal::Result<std::string> log = storage_.read(kAuditFile), head = storage_.read(kAuditHead);
    const std::string_view logText = log.ok() ? std::string_view(log.value) : std::string_view();
    const std::string_view headText = head.ok() ? std::string_view(head.value) : std::string_view();
    AuditCheck c = checkAudit(logText, headText, &entries_);
    if (!log.ok() && log.error.code != hal::Errc::NotFound) c.problems.push_back("audit: " + log.error.message);
    if (!log.ok() && head.ok()) c.problems.push_back(std::string(kAuditFile) + " is missing but its head is there");
    // The chain goes on from the last entry written, whatever its state: a damage found
    // stays visible to every later check.
    lastSeq_ = 0;
    lastHash_ = kGenesis;
    std::string_view t = logText;
    while (!t.empty()) {
        const size_t nl = t.find('\n');
        if (nl == std::string_view::npos) break;
        std::string_view carried;
        std::string computed;
        reading::FlatObject obj;
        if (entryHashes(t.substr(0, nl), &carried, &computed) &&
            reading::parseFlatObject(t.substr(0, nl), &obj).empty())
            lastSeq_ = whole(obj, "seq"), lastHash_ = std::string(carried);
        t.remove_prefix(nl + 1);
    }
    if (!t.empty()) storage_.truncate(kAuditFile, logText.size() - t.size()); // the torn entry: never took effect
    return c;
}

hal::Error AuditLog::append(AuditEntry e)
{
    e.seq = lastSeq_ + 1;
    e.prev = lastHash_;
    const std::string line = auditLine(&e);
    if (hal::Error err = storage_.append(kAuditFile, line); !err.ok()) return err;
    lastSeq_ = e.seq;
    lastHash_ = e.entry;
    char head[96];
    std::snprintf(head, sizeof head, "%ld %s\n", e.seq, e.entry.c_str());
    entries_.push_back(std::move(e));
    return storage_.writeAtomic(kAuditHead, head);
}

const AuditEntry *AuditLog::newest() const
{
    return entries_.empty() ? nullptr : &entries_.back();
}

long AuditLog::lastVersion(std::string_view id) const
{
    long v = 0;
    for (const AuditEntry &e : entries_)
        if (e.recipe == id && e.version > v) v = e.version;
    return v;
}

} // namespace icacam::fw
