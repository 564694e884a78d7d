#include "host_tools/fe/fe_aspect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

#include "host_tools/fe/fe_rows.h"

namespace icacam::host::fe {

namespace {
constexpr double kBaseAspect = 1.5;
double aspectOf(const FeRow &r)
{
    return std::round(r.h0 / r.d0 * 1000) / 1000;
}
bool usable(const FeRow &r)
{
    return (r.status == "ok" || r.status == "failed") && r.reduction >= 0.3 - 1e-9;
}
std::string list(const std::vector<double> &v)
{
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) {
        char b[40];
        std::snprintf(b, sizeof b, "%.6g", v[i]);
        s += (i ? ", " : "") + std::string(b);
    }
    return s;
}
} // namespace

AspectRatios aspectRatios(const std::vector<std::string> &in, double minU)
{
    const std::vector<FeRow> rows = readSweepCsvs(in);
    AspectRatios out;
    // The mesh and K of the other-aspect runs decide which base rows they are compared with.
    std::map<std::string, int> meshCount;
    for (const auto &r : rows)
        if (usable(r) && std::fabs(aspectOf(r) - kBaseAspect) > 1e-6) ++meshCount[meshKey(r)];
    int best = 0;
    for (const auto &[m, c] : meshCount)
        if (c > best) {
            best = c;
            out.mesh = m;
        }
    // The same physics and the same regularisation (contact penalty, stick slope): a ratio of
    // two runs that differ only in slenderness.
    auto key = [](const FeRow &r) {
        return std::make_tuple(r.kMpa, r.n, r.mu, r.eMpa, std::round(r.reduction * 1e4) / 1e4, r.contactSlope,
                               r.stickSlope);
    };
    // Both sides tracked, or neither: the tracked edge when every selected row has it.
    out.tracked = true;
    for (const auto &r : rows)
        if (usable(r) && meshKey(r) == out.mesh && r.uTrack < 0) out.tracked = false;
    auto u = [&](const FeRow &r) { return out.tracked ? r.uTrack : r.uInterp; };
    std::map<std::tuple<double, double, double, double, double, double, double>, const FeRow *> base;
    for (const auto &r : rows)
        if (usable(r) && meshKey(r) == out.mesh && std::fabs(aspectOf(r) - kBaseAspect) < 1e-6 && r.d0 == 10)
            base[key(r)] = &r;
    for (const auto &r : rows) {
        if (!usable(r) || meshKey(r) != out.mesh || std::fabs(aspectOf(r) - kBaseAspect) < 1e-6 || r.d0 != 10) continue;
        const auto it = base.find(key(r));
        if (it == base.end()) continue;
        const auto k = std::make_tuple(aspectOf(r), r.n, std::round(r.reduction * 1e4) / 1e4, r.mu);
        if (it->second->rMax > 0) out.rMaxRatio[k] = r.rMax / it->second->rMax;
        if (u(*it->second) > minU) out.ratio[k] = u(r) / u(*it->second);
    }
    return out;
}

namespace {

using RatioMap = std::map<std::tuple<double, double, double, double>, double>;

// The table's axes: every simulated slenderness (the base's among them), n, reduction and μ.
struct AspectAxes {
    std::vector<double> aspect, n, reduction, mu;
};

AspectAxes aspectAxes(const RatioMap &ratio)
{
    std::set<double> as{kBaseAspect}, ns, rs, ms;
    for (const auto &[k, v] : ratio) {
        as.insert(std::get<0>(k));
        ns.insert(std::get<1>(k));
        rs.insert(std::get<2>(k));
        ms.insert(std::get<3>(k));
    }
    return {{as.begin(), as.end()}, {ns.begin(), ns.end()}, {rs.begin(), rs.end()}, {ms.begin(), ms.end()}};
}

// A full table for the device's multilinear lookup: a point not simulated takes the nearest
// simulated one of the same slenderness (distance in μ, reduction and n, each over its span
// in the paper's study); the base slenderness is 1 by definition.
double nearestRatio(const RatioMap &m, double a, double n, double r, double mu)
{
    if (std::fabs(a - kBaseAspect) < 1e-6) return 1.0;
    if (const auto it = m.find({a, n, r, mu}); it != m.end()) return it->second;
    double best = 1e9, value = 1.0;
    for (const auto &[k, v] : m) {
        if (std::fabs(std::get<0>(k) - a) > 1e-6) continue;
        const double dist = std::fabs(std::get<1>(k) - n) / 0.45 + std::fabs(std::get<2>(k) - r) / 0.3 +
                            std::fabs(std::get<3>(k) - mu) / 0.25;
        if (dist < best) {
            best = dist;
            value = v;
        }
    }
    return value;
}

// The three [aspect][n][reduction][μ] tables' rows: u's ratio, whether it was simulated, and
// R_max's ratio; count: the simulated points.
struct AspectTables {
    std::string values, simulated, rMaxValues;
    int count = 0;
};

AspectTables aspectTables(const AspectRatios &ar, const AspectAxes &x)
{
    AspectTables t;
    for (double a : x.aspect) {
        t.values += "    {\n";
        t.simulated += "    {\n";
        t.rMaxValues += "    {\n";
        for (double n : x.n) {
            t.values += "        {\n";
            t.simulated += "        {\n";
            t.rMaxValues += "        {\n";
            for (double r : x.reduction) {
                std::string line = "            {", sline = "            {", rline = "            {";
                for (size_t mi = 0; mi < x.mu.size(); ++mi) {
                    const bool sim = ar.ratio.count({a, n, r, x.mu[mi]}) > 0;
                    char b[32];
                    std::snprintf(b, sizeof b, "%s%.5f", mi ? ", " : "", nearestRatio(ar.ratio, a, n, r, x.mu[mi]));
                    line += b;
                    std::snprintf(b, sizeof b, "%s%.5f", mi ? ", " : "", nearestRatio(ar.rMaxRatio, a, n, r, x.mu[mi]));
                    rline += b;
                    sline += std::string(mi ? ", " : "") + (sim ? "1" : "0");
                    t.count += sim;
                }
                t.values += line + "},\n";
                t.simulated += sline + "},\n";
                t.rMaxValues += rline + "},\n";
            }
            t.values += "        },\n";
            t.simulated += "        },\n";
            t.rMaxValues += "        },\n";
        }
        t.values += "    },\n";
        t.simulated += "    },\n";
        t.rMaxValues += "    },\n";
    }
    return t;
}

} // namespace

std::string aspectTableText(const TableSources &src, const std::string &sourceDir, std::string *summary)
{
    std::vector<std::string> in;
    for (const std::string &name : src.aspect) in.push_back(sourceDir + name);
    const AspectRatios ar = aspectRatios(in);
    if (ar.ratio.empty()) throw std::runtime_error("tables: no run at another H0/D0 with a base run to compare");
    const AspectAxes x = aspectAxes(ar.ratio);
    const AspectTables t = aspectTables(ar, x);
    std::ostringstream f;
    f << "#pragma once\n"
      << "// GENERATED by `" << src.command << "` — do not edit.\n"
      << "// u(H0/D0) / u(1.5): how much wider the ICA of another slenderness is than the paper's\n"
      << "// 10 x 15 mm specimen's at the same n, μ and height reduction (D0 10 mm; CalculiX runs\n"
      << "// " << joined(src.aspect) << ",\n"
      << "// mesh " << ar.mesh << ", u from the " << (ar.tracked ? "tracked" : "interpolated")
      << " contact edge; host_tools/fe/fe_aspect.cpp, docs/fe.md): a ratio of runs of one family, carried onto\n"
      << "// the base's model (friction/aspect_corrected_model.h).\n"
      << "// Only where u(1.5) > 0.1 mm; points not simulated (kSimulated 0) copy the nearest simulated\n"
      << "// point of the same slenderness (distance in n, reduction and μ over 0.45, 0.3 and 0.25).\n"
      << "namespace icacam::friction::aspect_table {\n"
      << "inline constexpr const char *kProvenance = \"" << src.command << "\";\n"
      << "inline constexpr const char *kInputs = \"" << joined(src.aspect) << "\";\n"
      << "inline constexpr double kBaseAspect = " << kBaseAspect << ";\n"
      << "inline constexpr int kACount = " << x.aspect.size() << ", kNCount = " << x.n.size()
      << ", kRCount = " << x.reduction.size() << ", kMuCount = " << x.mu.size() << ";\n"
      << "inline constexpr double kAspect[kACount] = {" << list(x.aspect) << "};\n"
      << "inline constexpr double kN[kNCount] = {" << list(x.n) << "};\n"
      << "inline constexpr double kR[kRCount] = {" << list(x.reduction) << "};\n"
      << "inline constexpr double kMu[kMuCount] = {" << list(x.mu) << "};\n"
      << "// [aspect][n][reduction][μ]\n"
      << "inline constexpr double kURatio[kACount][kNCount][kRCount][kMuCount] = {\n"
      << t.values << "};\n"
      << "inline constexpr unsigned char kSimulated[kACount][kNCount][kRCount][kMuCount] = {\n"
      << t.simulated << "};\n"
      << "// R_max(H0/D0) / R_max(1.5), the silhouette's ratio, on the same axes (every run pair; the\n"
      << "// nearest simulated one where there is none).\n"
      << "inline constexpr double kRMaxRatio[kACount][kNCount][kRCount][kMuCount] = {\n"
      << t.rMaxValues << "};\n"
      << "} // namespace icacam::friction::aspect_table\n";
    if (summary)
        *summary = std::to_string(t.count) + " simulated ratios, H0/D0 " + list(x.aspect) + ", n " + list(x.n) +
                   ", mu " + list(x.mu);
    return f.str();
}

} // namespace icacam::host::fe
