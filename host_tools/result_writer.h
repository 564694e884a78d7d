#pragma once
// One output row per manifest record, as CSV or JSON lines: the record id, then the
// reading's fields in the one schema the device uses too (reading/reading_record.h); or, for
// a person at a terminal, a short table (id, μ ± U, status, the finding or the advice) and a
// summary.
#include <map>
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

enum class ResultFormat { Csv, Jsonl, Table };

class ResultWriter {
public:
    ResultWriter(std::ostream &out, ResultFormat format) : out_(out), format_(format) {}
    void header();
    void write(const ResultRow &r);
    // The table's closing lines: the counts by status and by the tolerance decision, and the
    // advice most readings share (nothing for CSV and JSON lines).
    void summary();
    static std::vector<std::string> columns();
    static std::string flagList(uint32_t flags);
    // The table's line for one record (no newline).
    static std::string tableLine(const ResultRow &r);

private:
    std::ostream &out_;
    ResultFormat format_;
    int ok_ = 0, warn_ = 0, error_ = 0, within_ = 0, beyond_ = 0;
    std::map<std::string, int> advised_; // by the advised input's name
};

} // namespace icacam::host
