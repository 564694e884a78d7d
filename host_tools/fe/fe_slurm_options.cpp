#include "host_tools/fe/fe_slurm_options.h"

#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>

namespace icacam::host::fe {

namespace {
const std::set<std::string> kKeys{"partition", "time",   "cpus-per-task", "sbatch", "setup",
                                  "slurm-dir", "icacam", "array-limit",   "poll"};

std::string trim(const std::string &s)
{
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

double number(const std::string &key, const std::string &v, double min)
{
    size_t pos = 0;
    double x = 0;
    try {
        x = std::stod(v, &pos);
    } catch (...) {
        pos = 0;
    }
    if (pos != v.size() || !std::isfinite(x) || x < min)
        throw std::runtime_error("slurm option " + key + ": expected a number >= " + std::to_string(int(min)) +
                                 ", not '" + v + "'");
    return x;
}

void set(SlurmOptions &o, const std::string &key, const std::string &v)
{
    if (key == "partition")
        o.partition = v;
    else if (key == "time")
        o.timeLimit = v;
    else if (key == "cpus-per-task")
        o.cpusPerTask = int(number(key, v, 1));
    else if (key == "sbatch")
        o.sbatchExtra = v;
    else if (key == "setup")
        o.setup = v;
    else if (key == "slurm-dir")
        o.dir = v;
    else if (key == "icacam")
        o.icacam = v;
    else if (key == "array-limit")
        o.arrayLimit = int(number(key, v, 0));
    else if (key == "poll")
        o.pollS = number(key, v, 0);
    else
        throw std::runtime_error("unknown slurm option '" + key + "'");
}
} // namespace

bool isSlurmKey(const std::string &key)
{
    return kKeys.count(key) > 0;
}

SlurmOptions slurmOptions(const std::string &configFile, const std::map<std::string, std::string> &given)
{
    SlurmOptions o;
    if (!configFile.empty()) {
        std::ifstream f(configFile);
        if (!f) throw std::runtime_error("cannot read slurm config " + configFile);
        std::string line;
        for (int n = 1; std::getline(f, line); ++n) {
            // A '#' starts a comment only at the line's start: setup lines may contain one.
            const std::string t = trim(line);
            if (t.empty() || t[0] == '#') continue;
            const auto eq = t.find('=');
            if (eq == std::string::npos)
                throw std::runtime_error(configFile + ":" + std::to_string(n) + ": expected key = value");
            const std::string key = trim(t.substr(0, eq));
            if (!isSlurmKey(key))
                throw std::runtime_error(configFile + ":" + std::to_string(n) + ": unknown key '" + key + "'");
            set(o, key, trim(t.substr(eq + 1)));
        }
    }
    for (const auto &[key, v] : given) set(o, key, v);
    return o;
}

} // namespace icacam::host::fe
