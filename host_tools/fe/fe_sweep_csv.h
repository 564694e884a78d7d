#pragma once
// The sweep CSV as a store of solved cases: which cases it holds, appending a case's rows,
// dropping cases (to run them again). Rows are csvRows() lines (fe_runner.h).
#include <map>
#include <set>
#include <string>
#include <vector>

namespace icacam::host::fe {

// The case labels that have rows in csv (none when it does not exist).
std::set<std::string> casesIn(const std::string &csv);

// A case's status and message as its rows say (the first row of the case).
struct CaseStatus {
    std::string status, message;
};
std::map<std::string, CaseStatus> caseStatuses(const std::string &csv);

// Appends rows, writing the header to a new file; a file whose header is a prefix of this
// version's (columns are only ever added at the end) gets the new header. Throws on a file
// of another layout.
void appendRows(const std::string &csv, const std::vector<std::string> &rows);

// Rewrites csv without the rows of these cases.
void dropCases(const std::string &csv, const std::set<std::string> &labels);

// The rows of a CSV written by appendRows (header checked against this version's).
std::vector<std::string> readRows(const std::string &csv);

} // namespace icacam::host::fe
