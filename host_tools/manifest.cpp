#include "host_tools/manifest.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace icacam::host {

std::string ManifestRow::get(const std::string &key, const std::string &fallback) const
{
    auto it = cells.find(key);
    return it == cells.end() || it->second.empty() ? fallback : it->second;
}

bool Manifest::hasColumn(const std::string &name) const
{
    return std::find(columns.begin(), columns.end(), name) != columns.end();
}

bool ManifestRow::has(const std::string &key) const
{
    auto it = cells.find(key);
    return it != cells.end() && !it->second.empty();
}

bool splitCsvLine(const std::string &line, std::vector<std::string> *fields)
{
    fields->clear();
    std::string cur;
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"') {
                if (i + 1 < line.size() && line[i + 1] == '"') {
                    cur += '"';
                    ++i;
                } else
                    quoted = false;
            } else
                cur += c;
        } else if (c == '"')
            quoted = true;
        else if (c == ',') {
            fields->push_back(cur);
            cur.clear();
        } else if (c != '\r')
            cur += c;
    }
    if (quoted) return false;
    fields->push_back(cur);
    return true;
}

std::vector<std::string> splitList(const std::string &text, char sep)
{
    std::vector<std::string> out;
    if (text.empty()) return out;
    for (size_t a = 0;;) {
        const size_t b = text.find(sep, a);
        out.push_back(text.substr(a, b == std::string::npos ? std::string::npos : b - a));
        if (b == std::string::npos) return out;
        a = b + 1;
    }
}

static std::string trim(const std::string &s)
{
    size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t')) ++a;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t')) --b;
    return s.substr(a, b - a);
}

bool parseNumber(const std::string &s0, double *out)
{
    const std::string s = trim(s0);
    if (s.empty() || s.size() > 64) return false;
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

bool parseManifest(const std::string &text, Manifest *out, std::string *error)
{
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    std::vector<std::string> fields;
    out->columns.clear();
    out->rows.clear();
    // Header: the first non-empty line. A UTF-8 byte-order mark is tolerated.
    while (std::getline(in, line)) {
        ++lineNo;
        if (lineNo == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line = line.substr(3);
        if (trim(line).empty() || trim(line) == "\r") continue;
        if (!splitCsvLine(line, &fields)) {
            *error = "header has an unterminated quote";
            return false;
        }
        for (auto &f : fields) out->columns.push_back(trim(f));
        break;
    }
    if (out->columns.empty()) {
        *error = "manifest is empty (no header row)";
        return false;
    }
    bool hasId = false;
    for (auto &c : out->columns) hasId |= c == "id";
    if (!hasId) {
        *error = "manifest header has no 'id' column";
        return false;
    }

    while (std::getline(in, line)) {
        ++lineNo;
        if (trim(line).empty() || trim(line) == "\r") continue;
        ManifestRow row;
        row.line = lineNo;
        if (line.size() > 65536)
            row.error = "row longer than 64 KiB";
        else if (!splitCsvLine(line, &fields))
            row.error = "unterminated quote";
        else if (fields.size() != out->columns.size())
            row.error = "row has " + std::to_string(fields.size()) + " fields, header has " +
                        std::to_string(out->columns.size());
        if (row.error.empty())
            for (size_t i = 0; i < fields.size(); ++i) row.cells[out->columns[i]] = trim(fields[i]);
        else if (!fields.empty())
            row.cells["id"] = trim(fields[0]);
        out->rows.push_back(std::move(row));
    }
    return true;
}

bool readManifest(const std::string &path, Manifest *out, std::string *error)
{
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        *error = "cannot open manifest '" + path + "'";
        return false;
    }
    std::stringstream ss;
    ss << f.rdbuf();
    const auto slash = path.find_last_of('/');
    out->baseDir = slash == std::string::npos ? "." : path.substr(0, slash);
    return parseManifest(ss.str(), out, error);
}

} // namespace icacam::host
