#pragma once
// The manifest CSV (PRODUCT.md §6): a header row, then one record per row. Fields may be
// quoted ("a,b" and "" escapes). A malformed row becomes a record with an error, so that
// one bad row never stops a batch.
#include <map>
#include <string>
#include <vector>

namespace icacam::host {

struct ManifestRow {
    int line = 0; // 1-based line in the file
    std::map<std::string, std::string> cells;
    std::string error; // non-empty: the row could not be parsed

    std::string get(const std::string &key, const std::string &fallback = "") const;
    bool has(const std::string &key) const;
};

struct Manifest {
    std::vector<std::string> columns;
    std::vector<ManifestRow> rows;
    std::string baseDir; // paths in the manifest are relative to this

    bool hasColumn(const std::string &name) const;
};

// Parses CSV text. Returns false (with `error`) only when there is no usable header.
bool parseManifest(const std::string &text, Manifest *out, std::string *error);
bool readManifest(const std::string &path, Manifest *out, std::string *error);

// Splits one CSV line into fields; false on an unterminated quote.
bool splitCsvLine(const std::string &line, std::vector<std::string> *fields);

// Splits a list held in one field ("a;b;c") at sep; an empty text is no element, empty
// entries between separators are kept.
std::vector<std::string> splitList(const std::string &text, char sep = ';');

// Parses a finite number; false on anything else (empty, text, inf, nan, trailing junk).
bool parseNumber(const std::string &s, double *out);

} // namespace icacam::host
