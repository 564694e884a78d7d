#include "host_tools/fe/fe_sweep_csv.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "host_tools/fe/fe_runner.h"

namespace icacam::host::fe {

namespace fs = std::filesystem;

namespace {
std::string field(const std::string &line, size_t index)
{
    size_t at = 0;
    for (size_t i = 0; i < index; ++i) {
        at = line.find(',', at);
        if (at == std::string::npos) return "";
        ++at;
    }
    return line.substr(at, line.find(',', at) - at);
}
size_t column(const std::string &header, const std::string &name)
{
    for (size_t i = 0;; ++i) {
        const std::string f = field(header, i);
        if (f == name) return i;
        if (f.empty()) return std::string::npos;
    }
}
} // namespace

std::set<std::string> casesIn(const std::string &csv)
{
    std::set<std::string> s;
    std::ifstream f(csv);
    std::string line;
    std::getline(f, line);
    while (std::getline(f, line))
        if (!line.empty()) s.insert(line.substr(0, line.find(',')));
    return s;
}

std::map<std::string, CaseStatus> caseStatuses(const std::string &csv)
{
    std::map<std::string, CaseStatus> m;
    std::ifstream f(csv);
    std::string head, line;
    std::getline(f, head);
    const size_t status = column(head, "status"), message = column(head, "message");
    while (std::getline(f, line)) {
        if (line.empty()) continue;
        const std::string label = field(line, 0);
        if (m.count(label)) continue;
        m[label] = {status == std::string::npos ? "" : field(line, status),
                    message == std::string::npos ? "" : field(line, message)};
    }
    return m;
}

void appendRows(const std::string &csv, const std::vector<std::string> &rows)
{
    const bool fresh = !fs::exists(csv) || fs::file_size(csv) == 0;
    if (fs::path(csv).has_parent_path()) fs::create_directories(fs::path(csv).parent_path());
    if (!fresh) {
        // A file from before columns were added (they only ever are, at the end): extend its
        // header so the new rows' columns have names; its old rows simply lack them.
        std::ifstream in(csv);
        std::string head;
        std::getline(in, head);
        const std::string now = csvHeader();
        if (head != now && now.compare(0, head.size(), head) == 0 && now[head.size()] == ',') {
            std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            in.close();
            std::ofstream rewrite(csv, std::ios::trunc);
            rewrite << now << "\n" << rest;
            if (!rewrite) throw std::runtime_error("cannot write " + csv);
        } else if (head != now)
            throw std::runtime_error(csv +
                                     ": its header is not this version's (nor a prefix of it); write to a new file");
    }
    std::ofstream f(csv, std::ios::app);
    if (fresh) f << csvHeader() << "\n";
    for (const auto &r : rows) f << r << "\n";
    if (!f) throw std::runtime_error("cannot write " + csv);
}

void dropCases(const std::string &csv, const std::set<std::string> &labels)
{
    if (labels.empty() || !fs::exists(csv)) return;
    std::ifstream in(csv);
    std::string head, line, kept;
    std::getline(in, head);
    while (std::getline(in, line))
        if (!line.empty() && !labels.count(field(line, 0))) kept += line + "\n";
    in.close();
    // Written beside and renamed: a kill midway leaves the old file, never half of one.
    const std::string tmp = csv + ".rewrite";
    {
        std::ofstream out(tmp, std::ios::trunc);
        out << head << "\n" << kept;
        if (!out) throw std::runtime_error("cannot write " + tmp);
    }
    fs::rename(tmp, csv);
}

std::vector<std::string> readRows(const std::string &csv)
{
    std::ifstream f(csv);
    if (!f) throw std::runtime_error("cannot read " + csv);
    std::string head, line;
    std::getline(f, head);
    if (head != csvHeader()) throw std::runtime_error(csv + ": not a result of this version (header differs)");
    std::vector<std::string> rows;
    while (std::getline(f, line))
        if (!line.empty()) rows.push_back(line);
    return rows;
}

} // namespace icacam::host::fe
