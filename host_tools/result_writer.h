#pragma once
// One output row per manifest record, as CSV or JSON lines: the record id, then the
// reading's fields in the one schema the device uses too (reading/reading_record.h).
#include <ostream>
#include <string>
#include <vector>

#include "reading/reading.h"

namespace icacam::host {

struct ResultRow {
    std::string id;
    std::string message;                 // why a row never reached vision; else "" (the reading says)
    const reading::Reading *m = nullptr; // null for rows that never reached vision
    std::string model;
};

class ResultWriter {
public:
    ResultWriter(std::ostream &out, bool jsonl) : out_(out), jsonl_(jsonl) {}
    void header();
    void write(const ResultRow &r);
    static std::vector<std::string> columns();
    static std::string flagList(uint32_t flags);

private:
    std::ostream &out_;
    bool jsonl_;
};

} // namespace icacam::host
