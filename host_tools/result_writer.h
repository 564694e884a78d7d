#pragma once
// One output row per manifest record, as CSV or JSON lines (PRODUCT.md §6 columns first,
// then the diagnostics the loop and the overlays use).
#include <ostream>
#include <string>
#include <vector>

#include "vision/measurement.h"

namespace icacam::host {

struct ResultRow {
    std::string id;
    std::string status = "error";
    std::string message;
    const vision::Measurement *m = nullptr; // null for rows that never reached vision
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
