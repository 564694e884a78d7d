#include "host_tools/fe/fe_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace icacam::host::fe {

namespace {
std::string list(const std::vector<double> &v, const char *f = "%.6g")
{
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) {
        char b[40];
        std::snprintf(b, sizeof b, f, v[i]);
        s += (i ? ", " : "") + std::string(b);
    }
    return s;
}
std::string kRange(double lo, double hi)
{
    char b[60];
    if (lo == hi)
        std::snprintf(b, sizeof b, "%g", lo);
    else
        std::snprintf(b, sizeof b, "%g-%g", lo, hi);
    return b;
}
} // namespace

std::string feModelTableText(const TableSources &src, const std::string &sourceDir, double reduction,
                             std::string *summary)
{
    const std::vector<FeRow> baseRows = readSweepCsv(sourceDir + src.base);
    std::vector<std::string> family;
    for (const std::string &name : src.kFamily) family.push_back(sourceDir + name);
    const std::vector<FeRow> familyRows = readSweepCsvs(family);
    // Every snapshot reduction from 30 % to 60 % that has base data (`reduction` must be one).
    std::vector<double> reds;
    std::map<double, PointGrid> byRed;
    std::map<double, KCarry> carryByRed;   // how u moves with K, per reduction (fe_rows.h)
    std::set<double> kCovered;             // the K range the model answers for (below)
    double contactPerK = 0, stickPerK = 0; // the base's regularisation (one family, fe_rows.h)
    // The base is chosen among the named base's runs only; the K carry among the base's and
    // the family's runs (it needs the family at the base's K as its reference).
    std::vector<FeRow> all = baseRows;
    all.insert(all.end(), familyRows.begin(), familyRows.end());
    for (int k = 6; k <= 12; ++k) {
        const double r = std::round(k * 0.05 * 1e6) / 1e6;
        const BaseChoice base = chooseBase(baseRows, r);
        auto pts = basePoints(baseRows, r, base);
        if (pts.empty()) continue;
        reds.push_back(r);
        byRed[r] = std::move(pts);
        carryByRed[r] = kCarry(all, r, base);
        // The K range the model answers for: the K the carry spans (the base's among them),
        // else the base's own.
        const KCarry &c = carryByRed[r];
        if (c.found)
            kCovered.insert(c.k.begin(), c.k.end());
        else
            kCovered.insert(base.kAveraged.begin(), base.kAveraged.end());
        contactPerK = base.contactPerK;
        stickPerK = base.stickPerK;
    }
    if (byRed.empty()) throw std::runtime_error("tables: no usable rows in the base " + src.base);
    reduction = std::round(reduction * 1e6) / 1e6;
    if (!byRed.count(reduction))
        throw std::runtime_error("tables: no base data at reduction " + std::to_string(reduction));
    std::set<double> ns, mus;
    double kMin = 1e9, kMax = 0;
    std::string mesh;
    int tracked = 0, rows = 0;
    for (const auto &[r, pts] : byRed)
        for (const auto &[k, p] : pts) {
            ns.insert(p.n);
            mus.insert(p.mu);
            kMin = std::min(kMin, p.kMin);
            kMax = std::max(kMax, p.kMax);
            mesh = p.mesh;
            tracked += p.tracked;
            rows += p.count;
        }
    const double kLo = kCovered.empty() ? kMin : *kCovered.begin();
    const double kHi = kCovered.empty() ? kMax : *kCovered.rbegin();
    const std::vector<double> nv(ns.begin(), ns.end()), mv(mus.begin(), mus.end());
    // The K carry's K and family: those of the model's own reduction; a reduction where that
    // family lacks a K or a point carries 0 there (counted, said in the file).
    const KCarry &carry0 = carryByRed[reduction];
    std::vector<double> carryK = carry0.found ? carry0.k : std::vector<double>{kMin};
    // A base point whose K run is missing at some reduction (or comes from another family there).
    auto carryAt = [&](double k, double r, double n, double mu) -> const Point * {
        const KCarry &c = carryByRed[r];
        const auto dk = c.delta.find(k);
        const bool same = c.found && c.mesh == carry0.mesh && c.contactPerK == carry0.contactPerK &&
                          c.stickPerK == carry0.stickPerK && dk != c.delta.end();
        if (!same) return nullptr;
        const auto it = dk->second.find({n, mu});
        return it == dk->second.end() ? nullptr : &it->second;
    };
    int carryHoles = 0;
    if (carry0.found)
        for (double k : carryK)
            for (double r : reds)
                for (const auto &[key, p] : byRed[r]) carryHoles += carryAt(k, r, key.first, key.second) == nullptr;
    auto carryTable = [&](auto get) {
        std::string s;
        for (double k : carryK) {
            s += "  {\n";
            for (double r : reds) {
                s += "    {\n";
                for (double n : nv) {
                    std::vector<double> row;
                    for (double mu : mv) {
                        const Point *d = carry0.found && byRed[r].count({n, mu}) ? carryAt(k, r, n, mu) : nullptr;
                        row.push_back(d ? get(*d) : 0.0);
                    }
                    s += "        {" + list(row, "%.5f") + "},\n";
                }
                s += "    },\n";
            }
            s += "  },\n";
        }
        return s;
    };
    const std::string carryU = carryTable([](const Point &p) { return p.u; });
    const std::string carryRi = carryTable([](const Point &p) { return p.ri; });
    const std::string carryRmax = carryTable([](const Point &p) { return p.rMax; });
    auto table = [&](auto get) {
        std::string s;
        for (double r : reds) {
            s += "    {\n";
            for (double n : nv) {
                s += "        {";
                for (size_t j = 0; j < mv.size(); ++j) {
                    const auto it = byRed[r].find({n, mv[j]});
                    s += j ? ", " : "";
                    s += it == byRed[r].end() ? std::string("kNoData") : list({get(it->second)}, "%.5f");
                }
                s += "},\n";
            }
            s += "    },\n";
        }
        return s;
    };
    const char *edge = tracked == rows ? "the contact edge tracked between the nodes' touchdowns (u_track_mm)"
                       : tracked == 0  ? "the interpolated contact edge (u_interp_mm)"
                                       : "the tracked contact edge where the run has it, else the interpolated one";
    std::ostringstream f;
    f << "#pragma once\n"
      << "// GENERATED by `" << src.command << "` — do not edit.\n"
      << "// The FE model's table (friction/fe_model.h): base " << src.base << ",\n"
      << "// CalculiX 2.20 axisymmetric upsetting (host_tools/fe, docs/fe.md),\n"
      << "// D0 = 10 mm, H0 = 15 mm, E = 210 GPa, snapshots at 30-60 % height reduction, mesh " << mesh
      << "\n// (element, far-field size, corner size in mm), contact penalty " << contactPerK << " K and stick slope "
      << stickPerK << " K N/mm³ (K in MPa);\n// each point the mean over the base's K that cover the grid "
      << "(host_tools/fe/fe_rows.h): K " << kRange(kMin, kMax) << " MPa.\n"
      << "// u is " << edge << "; R_o = R_i + u; kNoData marks a grid point without data.\n";
    if (carry0.found) {
        f << "// K carry: u, R_i and R_max at K minus at the base's K, from the runs of one family that cover the\n"
          << "// grid at K " << list(carryK) << " MPa (" << joined(src.kFamily) << ": mesh " << carry0.mesh
          << ", contact penalty " << carry0.contactPerK << " K, stick slope " << carry0.stickPerK
          << " K N/mm³): the model at K adds it, linear in K between them,\n"
          << "// and answers for K " << kRange(kLo, kHi) << " MPa (host_tools/fe/fe_rows.h, KCarry).";
        if (carryHoles) f << " " << carryHoles << " grid points without a K run carry 0.";
        f << "\n";
    } else {
        f << "// K carry: none (no family covers the grid at several K): the model is the same at every K.\n";
    }
    f << "#include \"friction/grid.h\"\n"
      << "namespace icacam::friction::fe_table {\n"
      << "inline constexpr const char *kProvenance = \"" << src.command << "\";\n"
      << "inline constexpr const char *kBase = \"" << src.base << "\";\n"
      << "inline constexpr const char *kKFamily = \"" << joined(src.kFamily) << "\";\n"
      << "inline constexpr double kReduction = " << reduction << "; // the model's own reduction when none is given\n"
      << "inline constexpr double kD0Mm = 10, kH0Mm = 15;\n"
      << "inline constexpr double kKMinMpa = " << kLo << ", kKMaxMpa = " << kHi << ";\n"
      << "inline constexpr int kRCount = " << reds.size() << ", kNCount = " << nv.size() << ", kMuCount = " << mv.size()
      << ";\n"
      << "inline constexpr double kR[kRCount] = {" << list(reds) << "};\n"
      << "inline constexpr double kN[kNCount] = {" << list(nv) << "};\n"
      << "inline constexpr double kMu[kMuCount] = {" << list(mv) << "};\n"
      << "// [reduction][n][μ] in mm\n"
      << "inline constexpr double kU[kRCount][kNCount][kMuCount] = {\n"
      << table([](const Point &p) { return p.u; }) << "};\n"
      << "inline constexpr double kRi[kRCount][kNCount][kMuCount] = {\n"
      << table([](const Point &p) { return p.ri; }) << "};\n"
      << "inline constexpr double kRo[kRCount][kNCount][kMuCount] = {\n"
      << table([](const Point &p) { return p.ro; }) << "};\n"
      << "inline constexpr double kRmax[kRCount][kNCount][kMuCount] = {\n"
      << table([](const Point &p) { return p.rMax; }) << "};\n"
      << "inline constexpr int kKCount = " << carryK.size() << ";\n"
      << "inline constexpr double kK[kKCount] = {" << list(carryK) << "}; // MPa\n"
      << "// [K][reduction][n][μ] in mm\n"
      << "inline constexpr double kDU[kKCount][kRCount][kNCount][kMuCount] = {\n"
      << carryU << "};\n"
      << "inline constexpr double kDRi[kKCount][kRCount][kNCount][kMuCount] = {\n"
      << carryRi << "};\n"
      << "inline constexpr double kDRmax[kKCount][kRCount][kNCount][kMuCount] = {\n"
      << carryRmax << "};\n"
      << "} // namespace icacam::friction::fe_table\n";
    std::ostringstream said;
    said << byRed[reds.front()].size() << "-" << byRed[reduction].size() << " (n, mu) points at " << reds.size()
         << " reductions, n " << list(nv) << ", mu " << list(mv);
    if (carry0.found) said << ", K carry " << list(carryK) << " MPa from " << carry0.mesh;
    if (carryHoles) said << " (" << carryHoles << " points without it)";
    if (summary) *summary = said.str();
    return f.str();
}

} // namespace icacam::host::fe
