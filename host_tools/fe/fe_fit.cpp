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

// The base's points at every snapshot reduction from 30 % to 60 % that has base data, and the
// K carry at each.
struct BaseTables {
    std::vector<double> reds;
    std::map<double, PointGrid> byRed;
    std::map<double, KCarry> carryByRed;   // how u moves with K, per reduction (fe_rows.h)
    std::set<double> kCovered;             // the K range the model answers for (below)
    double contactPerK = 0, stickPerK = 0; // the base's regularisation (one family, fe_rows.h)
};

BaseTables readBaseTables(const TableSources &src, const std::string &sourceDir)
{
    const std::vector<FeRow> baseRows = readSweepCsv(sourceDir + src.base);
    std::vector<std::string> family;
    for (const std::string &name : src.kFamily) family.push_back(sourceDir + name);
    const std::vector<FeRow> familyRows = readSweepCsvs(family);
    BaseTables t;
    // The base is chosen among the named base's runs only; the K carry among the base's and
    // the family's runs (it needs the family at the base's K as its reference).
    std::vector<FeRow> all = baseRows;
    all.insert(all.end(), familyRows.begin(), familyRows.end());
    for (int k = 6; k <= 12; ++k) {
        const double r = std::round(k * 0.05 * 1e6) / 1e6;
        const BaseChoice base = chooseBase(baseRows, r);
        auto pts = basePoints(baseRows, r, base);
        if (pts.empty()) continue;
        t.reds.push_back(r);
        t.byRed[r] = std::move(pts);
        t.carryByRed[r] = kCarry(all, r, base);
        // The K range the model answers for: the K the carry spans (the base's among them),
        // else the base's own.
        const KCarry &c = t.carryByRed[r];
        if (c.found)
            t.kCovered.insert(c.k.begin(), c.k.end());
        else
            t.kCovered.insert(base.kAveraged.begin(), base.kAveraged.end());
        t.contactPerK = base.contactPerK;
        t.stickPerK = base.stickPerK;
    }
    return t;
}

// The (n, μ) grid over every reduction, the K the base's points average, the mesh, and how
// many rows have the tracked contact edge.
struct GridSpan {
    std::vector<double> n, mu;
    double kMin = 1e9, kMax = 0;
    std::string mesh;
    int tracked = 0, rows = 0;
};

GridSpan gridSpan(const BaseTables &t)
{
    GridSpan g;
    std::set<double> ns, mus;
    for (const auto &[r, pts] : t.byRed)
        for (const auto &[k, p] : pts) {
            ns.insert(p.n);
            mus.insert(p.mu);
            g.kMin = std::min(g.kMin, p.kMin);
            g.kMax = std::max(g.kMax, p.kMax);
            g.mesh = p.mesh;
            g.tracked += p.tracked;
            g.rows += p.count;
        }
    g.n.assign(ns.begin(), ns.end());
    g.mu.assign(mus.begin(), mus.end());
    return g;
}

using PointValue = double (*)(const Point &);
double pointU(const Point &p)
{
    return p.u;
}
double pointRi(const Point &p)
{
    return p.ri;
}
double pointRo(const Point &p)
{
    return p.ro;
}
double pointRmax(const Point &p)
{
    return p.rMax;
}

// One [reduction][n][μ] table's rows.
std::string pointTable(const BaseTables &t, const GridSpan &g, PointValue get)
{
    std::string s;
    for (double r : t.reds) {
        const PointGrid &pts = t.byRed.at(r);
        s += "    {\n";
        for (double n : g.n) {
            s += "        {";
            for (size_t j = 0; j < g.mu.size(); ++j) {
                const auto it = pts.find({n, g.mu[j]});
                s += j ? ", " : "";
                s += it == pts.end() ? std::string("kNoData") : list({get(it->second)}, "%.5f");
            }
            s += "},\n";
        }
        s += "    },\n";
    }
    return s;
}

// The K carry's tables: its K and family are those of the model's own reduction; a reduction
// where that family lacks a K or a point carries 0 there (counted, said in the file).
struct CarryTables {
    const KCarry *carry0 = nullptr;
    std::vector<double> k;
    int holes = 0;
    std::string u, ri, rMax;
};

CarryTables carryTables(const BaseTables &t, const GridSpan &g, double reduction)
{
    CarryTables c;
    const KCarry &carry0 = t.carryByRed.at(reduction);
    c.carry0 = &carry0;
    c.k = carry0.found ? carry0.k : std::vector<double>{g.kMin};
    // A base point whose K run is missing at some reduction (or comes from another family there).
    auto carryAt = [&](double k, double r, double n, double mu) -> const Point * {
        const KCarry &at = t.carryByRed.at(r);
        const auto dk = at.delta.find(k);
        const bool same = at.found && at.mesh == carry0.mesh && at.contactPerK == carry0.contactPerK &&
                          at.stickPerK == carry0.stickPerK && dk != at.delta.end();
        if (!same) return nullptr;
        const auto it = dk->second.find({n, mu});
        return it == dk->second.end() ? nullptr : &it->second;
    };
    if (carry0.found)
        for (double k : c.k)
            for (double r : t.reds)
                for (const auto &[key, p] : t.byRed.at(r)) c.holes += carryAt(k, r, key.first, key.second) == nullptr;
    auto table = [&](PointValue get) {
        std::string s;
        for (double k : c.k) {
            s += "  {\n";
            for (double r : t.reds) {
                s += "    {\n";
                for (double n : g.n) {
                    std::vector<double> row;
                    for (double mu : g.mu) {
                        const Point *d = carry0.found && t.byRed.at(r).count({n, mu}) ? carryAt(k, r, n, mu) : nullptr;
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
    c.u = table(pointU);
    c.ri = table(pointRi);
    c.rMax = table(pointRmax);
    return c;
}

// The header's comment: where the table comes from and what it holds.
void writeProvenance(std::ostream &f, const TableSources &src, const BaseTables &t, const GridSpan &g,
                     const CarryTables &c, double kLo, double kHi)
{
    const char *edge = g.tracked == g.rows ? "the contact edge tracked between the nodes' touchdowns (u_track_mm)"
                       : g.tracked == 0    ? "the interpolated contact edge (u_interp_mm)"
                                           : "the tracked contact edge where the run has it, else the interpolated one";
    f << "#pragma once\n"
      << "// GENERATED by `" << src.command << "` — do not edit.\n"
      << "// The FE model's table (friction/fe_model.h): base " << src.base << ",\n"
      << "// CalculiX 2.20 axisymmetric upsetting (host_tools/fe, docs/fe.md),\n"
      << "// D0 = 10 mm, H0 = 15 mm, E = 210 GPa, snapshots at 30-60 % height reduction, mesh " << g.mesh
      << "\n// (element, far-field size, corner size in mm), contact penalty " << t.contactPerK << " K and stick slope "
      << t.stickPerK << " K N/mm³ (K in MPa);\n// each point the mean over the base's K that "
      << "cover the grid (host_tools/fe/fe_rows.h): K " << kRange(g.kMin, g.kMax) << " MPa.\n"
      << "// u is " << edge << "; R_o = R_i + u; kNoData marks a grid point without data.\n";
    if (c.carry0->found) {
        f << "// K carry: u, R_i and R_max at K minus at the base's K, from the runs of one family that cover the\n"
          << "// grid at K " << list(c.k) << " MPa (" << joined(src.kFamily) << ": mesh " << c.carry0->mesh
          << ", contact penalty " << c.carry0->contactPerK << " K, stick slope " << c.carry0->stickPerK
          << " K N/mm³): the model at K adds it, linear in K between them,\n"
          << "// and answers for K " << kRange(kLo, kHi) << " MPa (host_tools/fe/fe_rows.h, KCarry).";
        if (c.holes) f << " " << c.holes << " grid points without a K run carry 0.";
        f << "\n";
    } else {
        f << "// K carry: none (no family covers the grid at several K): the model is the same at every K.\n";
    }
}

} // namespace

std::string feModelTableText(const TableSources &src, const std::string &sourceDir, double reduction,
                             std::string *summary)
{
    const BaseTables t = readBaseTables(src, sourceDir);
    if (t.byRed.empty()) throw std::runtime_error("tables: no usable rows in the base " + src.base);
    reduction = std::round(reduction * 1e6) / 1e6;
    if (!t.byRed.count(reduction))
        throw std::runtime_error("tables: no base data at reduction " + std::to_string(reduction));
    const GridSpan g = gridSpan(t);
    const double kLo = t.kCovered.empty() ? g.kMin : *t.kCovered.begin();
    const double kHi = t.kCovered.empty() ? g.kMax : *t.kCovered.rbegin();
    const CarryTables c = carryTables(t, g, reduction);
    std::ostringstream f;
    writeProvenance(f, src, t, g, c, kLo, kHi);
    f << "#include \"friction/grid.h\"\n"
      << "namespace icacam::friction::fe_table {\n"
      << "inline constexpr const char *kProvenance = \"" << src.command << "\";\n"
      << "inline constexpr const char *kBase = \"" << src.base << "\";\n"
      << "inline constexpr const char *kKFamily = \"" << joined(src.kFamily) << "\";\n"
      << "inline constexpr double kReduction = " << reduction << "; // the model's own reduction when none is given\n"
      << "inline constexpr double kD0Mm = 10, kH0Mm = 15;\n"
      << "inline constexpr double kKMinMpa = " << kLo << ", kKMaxMpa = " << kHi << ";\n"
      << "inline constexpr int kRCount = " << t.reds.size() << ", kNCount = " << g.n.size()
      << ", kMuCount = " << g.mu.size() << ";\n"
      << "inline constexpr double kR[kRCount] = {" << list(t.reds) << "};\n"
      << "inline constexpr double kN[kNCount] = {" << list(g.n) << "};\n"
      << "inline constexpr double kMu[kMuCount] = {" << list(g.mu) << "};\n"
      << "// [reduction][n][μ] in mm\n"
      << "inline constexpr double kU[kRCount][kNCount][kMuCount] = {\n"
      << pointTable(t, g, pointU) << "};\n"
      << "inline constexpr double kRi[kRCount][kNCount][kMuCount] = {\n"
      << pointTable(t, g, pointRi) << "};\n"
      << "inline constexpr double kRo[kRCount][kNCount][kMuCount] = {\n"
      << pointTable(t, g, pointRo) << "};\n"
      << "inline constexpr double kRmax[kRCount][kNCount][kMuCount] = {\n"
      << pointTable(t, g, pointRmax) << "};\n"
      << "inline constexpr int kKCount = " << c.k.size() << ";\n"
      << "inline constexpr double kK[kKCount] = {" << list(c.k) << "}; // MPa\n"
      << "// [K][reduction][n][μ] in mm\n"
      << "inline constexpr double kDU[kKCount][kRCount][kNCount][kMuCount] = {\n"
      << c.u << "};\n"
      << "inline constexpr double kDRi[kKCount][kRCount][kNCount][kMuCount] = {\n"
      << c.ri << "};\n"
      << "inline constexpr double kDRmax[kKCount][kRCount][kNCount][kMuCount] = {\n"
      << c.rMax << "};\n"
      << "} // namespace icacam::friction::fe_table\n";
    std::ostringstream said;
    said << t.byRed.at(t.reds.front()).size() << "-" << t.byRed.at(reduction).size() << " (n, mu) points at "
         << t.reds.size() << " reductions, n " << list(g.n) << ", mu " << list(g.mu);
    if (c.carry0->found) said << ", K carry " << list(c.k) << " MPa from " << c.carry0->mesh;
    if (c.holes) said << " (" << c.holes << " points without it)";
    if (summary) *summary = said.str();
    return f.str();
}

} // namespace icacam::host::fe
