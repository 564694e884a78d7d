#include "host_tools/fe/fe_results.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace icacam::host::fe {

namespace {
double num(const std::string &line, size_t pos, size_t len)
{
    if (line.size() < pos + 1) throw std::runtime_error("frd: short line: " + line);
    const std::string s = line.substr(pos, len);
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str()) throw std::runtime_error("frd: bad number in: " + line);
    return v;
}
// " -1" + I10 node + E12.5 values (the short frd format CalculiX writes by default).
void readNodeLine(const std::string &line, NodeXY &into)
{
    const int id = int(num(line, 3, 10));
    into[id] = {num(line, 13, 12), num(line, 25, 12)};
}
} // namespace

FrdResults parseFrd(const std::string &text)
{
    FrdResults r;
    std::istringstream in(text);
    std::string line;
    enum { kNone, kCoords, kDisp, kOther } block = kNone;
    double time = 0;
    while (std::getline(in, line)) {
        if (line.size() >= 6 && line.compare(0, 6, "    2C") == 0) {
            block = kCoords;
            continue;
        }
        if (line.size() >= 7 && line.compare(0, 7, "  100CL") == 0) {
            time = num(line, 12, 12);
            block = kOther;
            continue;
        }
        if (line.size() >= 9 && line.compare(0, 3, " -4") == 0) {
            if (line.compare(3, 6, "  DISP") == 0) {
                block = kDisp;
                r.steps.push_back({time, {}});
            } else
                block = kOther;
            continue;
        }
        if (line.compare(0, 3, " -3") == 0) {
            block = kNone;
            continue;
        }
        if (line.compare(0, 3, " -1") != 0) continue;
        if (block == kCoords)
            readNodeLine(line, r.coords);
        else if (block == kDisp)
            readNodeLine(line, r.steps.back().disp);
    }
    if (r.coords.empty()) throw std::runtime_error("frd: no node block");
    return r;
}

FrdResults readFrd(const std::string &path)
{
    std::ifstream f(path, std::ios::binary);
    std::ostringstream text;
    text << f.rdbuf();
    return parseFrd(text.str());
}

std::vector<ForcePoint> parseDatTotals(const std::string &text)
{
    std::vector<ForcePoint> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto at = line.find("and time");
        if (line.find("total force") == std::string::npos || at == std::string::npos) continue;
        ForcePoint p;
        p.time = std::strtod(line.c_str() + at + 8, nullptr);
        std::string values;
        while (std::getline(in, values) && values.find_first_not_of(" \t\r") == std::string::npos) {}
        std::istringstream v(values);
        if (!(v >> p.fx >> p.fy)) throw std::runtime_error("dat: bad totals line: " + values);
        out.push_back(p);
    }
    return out;
}

} // namespace icacam::host::fe
