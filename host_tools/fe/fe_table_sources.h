#pragma once
// What the generated model tables (friction/*_table.h) are made from, as `icacam fe tables`
// names it: one FE base and the runs of the carries, as the repository names the files.
#include <string>
#include <vector>

namespace icacam::host::fe {

struct TableSources {
    std::string command;              // the command line that makes the tables, as written into each
    std::string base;                 // the base: u, R_i, R_o, R_max and du/dr of the 10 x 15 mm specimen
    std::vector<std::string> kFamily; // the K carry: runs of one family at several K, the base's K among them
    std::vector<std::string> aspect;  // the slenderness ratios: runs at other H0 and their 1.5 reference
};

// The files as one space-separated list (the form the headers keep them in).
inline std::string joined(const std::vector<std::string> &files)
{
    std::string s;
    for (const std::string &f : files) s += (s.empty() ? "" : " ") + f;
    return s;
}

// The files of such a list (a table's kFeSources), in order.
inline std::vector<std::string> splitSources(const std::string &sources)
{
    std::vector<std::string> out;
    size_t at = 0;
    while (at < sources.size()) {
        const size_t end = sources.find(' ', at);
        const std::string part = sources.substr(at, end == std::string::npos ? std::string::npos : end - at);
        if (!part.empty()) out.push_back(part);
        if (end == std::string::npos) break;
        at = end + 1;
    }
    return out;
}

} // namespace icacam::host::fe
