#include "firmware/journal.h"

#include <array>
#include <cstdio>

#include "reading/record_line.h"

namespace icacam::fw {

Journal::Journal(hal::Storage &storage, int memory) : storage_(storage), ring_(size_t(memory > 0 ? memory : 1))
{
    for (std::string &s : ring_) s.reserve(1024); // a result line is about 400 bytes
    line_.reserve(1024);
}

void Journal::remember(std::string_view line)
{
    ring_[head_].assign(line);
    head_ = (head_ + 1) % ring_.size();
    if (used_ < ring_.size()) ++used_;
}

long Journal::checkLine(std::string_view line)
{
    if (!reading::recordLineIntact(line)) return -1;
    reading::FlatObject obj;
    if (!reading::parseFlatObject(line, &obj).empty()) return -1;
    const reading::JsonField *id = obj.find("id");
    if (!id || id->type != reading::JsonField::Type::Number || id->number < 1) return -1;
    return long(id->number);
}

hal::Error Journal::recover(JournalRecovery *out)
{
    *out = {};
    if (auto names = storage_.list(); names.ok()) {
        for (const std::string &n : names.value)
            if (n.size() > 4 && n.compare(n.size() - 4, 4, ".tmp") == 0 && storage_.remove(n).ok())
                ++out->tempFilesRemoved;
    } else {
        return names.error;
    }
    hal::Result<std::string> text = storage_.read(kFile);
    if (!text.ok()) return text.error.code == hal::Errc::NotFound ? hal::Error{} : text.error;
    const std::string &t = text.value;
    size_t good = 0;
    while (good < t.size()) {
        const size_t nl = t.find('\n', good);
        if (nl == std::string::npos) break; // torn last line
        const long id = checkLine(std::string_view(t).substr(good, nl - good));
        if (id < 0) break;
        ++out->records;
        if (id > out->lastId) out->lastId = id;
        remember(std::string_view(t).substr(good, nl - good));
        good = nl + 1;
    }
    if (good < t.size()) {
        out->cutBytes = t.size() - good;
        char name[48];
        std::snprintf(name, sizeof name, "journal.damaged-%zu", good);
        if (hal::Error e = storage_.writeAtomic(name, std::string_view(t).substr(good)); !e.ok()) return e;
        if (hal::Error e = storage_.truncate(kFile, good); !e.ok()) return e;
    }
    count_ = out->records;
    return {};
}

hal::Error Journal::append(std::string_view record)
{
    if (record.size() < 3 || record.substr(record.size() - 2) != "}\n")
        return hal::Error::make(hal::Errc::Invalid, "journal record must be one JSON object line");
    line_.assign(record.substr(0, record.size() - 2));
    reading::sealRecordLine(&line_);
    line_.push_back('\n');
    if (hal::Error e = storage_.append(kFile, line_); !e.ok()) return e;
    line_.pop_back();
    remember(line_);
    ++count_;
    return {};
}

} // namespace icacam::fw
