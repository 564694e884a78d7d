#include "host_tools/fe/fe_rows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace icacam::host::fe {

namespace {
std::vector<std::string> split(const std::string &line)
{
    std::vector<std::string> out;
    std::string cell;
    std::istringstream s(line);
    while (std::getline(s, cell, ',')) out.push_back(cell);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}
double d(const std::string &s)
{
    return s.empty() ? 0.0 : std::strtod(s.c_str(), nullptr);
}
} // namespace

std::string meshKey(const FeRow &r)
{
    char b[80];
    std::snprintf(b, sizeof b, "%s h%g c%g%s", r.element.c_str(), r.elem, r.cornerMm,
                  r.contact.rfind("surface", 0) == 0 ? " s2s" : "");
    return b;
}

bool reachedSnapshot(const FeRow &r, double reduction)
{
    return (r.status == "ok" || r.status == "failed") && std::fabs(r.reduction - reduction) < 1e-6 && r.reduction > 0;
}

bool isPaperSpecimen(const FeRow &r)
{
    return r.eMpa == 210000 && r.d0 == 10 && r.h0 == 15;
}

std::vector<FeRow> readSweepCsv(const std::string &path)
{
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot read " + path);
    std::string line;
    std::getline(f, line);
    const auto head = split(line);
    std::map<std::string, size_t> col;
    for (size_t i = 0; i < head.size(); ++i) col[head[i]] = i;
    for (const char *need : {"case", "status", "k_mpa", "n", "mu", "e_mpa", "d0_mm", "h0_mm", "reduction", "elem_mm",
                             "r_i_mm", "r_o_interp_mm", "r_max_mm", "u_interp_mm", "force_kn"})
        if (!col.count(need)) throw std::runtime_error(path + ": missing column " + need);
    std::vector<FeRow> rows;
    while (std::getline(f, line)) {
        if (line.empty()) continue;
        const auto c = split(line);
        auto get = [&](const char *k) {
            const auto it = col.find(k);
            return it != col.end() && it->second < c.size() ? c[it->second] : std::string();
        };
        FeRow r;
        r.caseId = get("case");
        r.status = get("status");
        r.message = get("message");
        r.kMpa = d(get("k_mpa"));
        r.n = d(get("n"));
        r.mu = d(get("mu"));
        r.eMpa = d(get("e_mpa"));
        r.d0 = d(get("d0_mm"));
        r.h0 = d(get("h0_mm"));
        r.reductionMax = d(get("reduction_max"));
        r.reduction = d(get("reduction"));
        r.elem = d(get("elem_mm"));
        if (col.count("element")) r.element = get("element");
        if (col.count("contact") && !get("contact").empty()) r.contact = get("contact");
        if (col.count("corner_mm")) r.cornerMm = d(get("corner_mm"));
        if (col.count("stick_slope")) r.stickSlope = d(get("stick_slope"));
        if (col.count("contact_slope")) r.contactSlope = d(get("contact_slope"));
        if (col.count("nu")) r.nu = d(get("nu"));
        r.ri = d(get("r_i_mm"));
        r.ro = d(get("r_o_mm"));
        r.roInterp = d(get("r_o_interp_mm"));
        r.rMax = d(get("r_max_mm"));
        r.u = d(get("u_mm"));
        r.uInterp = d(get("u_interp_mm"));
        r.force = d(get("force_kn"));
        r.wallS = d(get("wall_s"));
        if (!get("u_track_mm").empty()) r.uTrack = d(get("u_track_mm"));
        rows.push_back(r);
    }
    return rows;
}

std::vector<FeRow> readSweepCsvs(const std::vector<std::string> &paths)
{
    std::vector<FeRow> rows;
    for (const auto &path : paths) {
        auto r = readSweepCsv(path);
        rows.insert(rows.end(), r.begin(), r.end());
    }
    return rows;
}

namespace {
// The contact penalty and the stick slope of a row per MPa of K (N/mm³ per MPa): the
// regularisation in the problem's own units (docs/fe.md, the factorial). Keyed to 1e-3.
using SlopesPerK = std::pair<long, long>;
SlopesPerK slopesPerK(const FeRow &r)
{
    auto perK = [&](double slope) { return r.kMpa > 0 ? std::lround(slope / r.kMpa * 1000) : 0L; };
    return {perK(r.contactSlope), perK(r.stickSlope)};
}
} // namespace

bool BaseChoice::sameRegularisation(const FeRow &r) const
{
    return slopesPerK(r) == SlopesPerK{std::lround(contactPerK * 1000), std::lround(stickPerK * 1000)};
}

namespace {

// A family: one mesh with one regularisation (slopes per K).
using Family = std::pair<std::string, SlopesPerK>;
using Grid = std::set<std::pair<double, double>>; // (n, μ)

// A family's rows, its finest element (the corner, or the uniform size) and the (n, μ) grid of
// each K in it, over the cases, whatever reduction they reached, so that every reduction of
// the model comes from the same runs.
struct FamilyInfo {
    int rows = 0;
    double size = 0;
    std::map<double, Grid> grid;
};

std::map<Family, FamilyInfo> familiesOf(const std::vector<FeRow> &rows)
{
    auto inCases = [](const FeRow &r) {
        return (r.status == "ok" || r.status == "failed") && r.reduction > 0 && isPaperSpecimen(r);
    };
    std::map<Family, FamilyInfo> families;
    for (const auto &r : rows)
        if (inCases(r)) {
            FamilyInfo &f = families[{meshKey(r), slopesPerK(r)}];
            ++f.rows;
            f.size = r.cornerMm > 0 ? r.cornerMm : r.elem;
            f.grid[r.kMpa].insert({r.n, r.mu});
        }
    return families;
}

// The finest mesh that covers the whole grid (every (n, μ) any family has at one K) at one K
// is the best answer the data has; a finer mesh at a few points is a mesh study, not a base.
// On that mesh, the stiffest stick slope, then contact penalty, that covers the grid: the
// regularised Coulomb law and the penalty contact are approximations that approach the exact
// laws as the slopes grow (the penalty study), so the stiffer complete set is the better
// answer too. Ties: the most rows. No complete family: the most common one. nullptr: none.
const Family *bestFamily(const std::map<Family, FamilyInfo> &families)
{
    Grid whole;
    for (const auto &[key, f] : families)
        for (const auto &[k, g] : f.grid) whole.insert(g.begin(), g.end());
    auto complete = [&](const FamilyInfo &f) {
        for (const auto &[k, g] : f.grid)
            if (std::includes(g.begin(), g.end(), whole.begin(), whole.end())) return true;
        return false;
    };
    const Family *chosen = nullptr;
    const FamilyInfo *info = nullptr;
    for (const auto &[key, f] : families) {
        bool better = !chosen;
        if (!better) {
            if (complete(f) != complete(*info))
                better = complete(f);
            else if (!complete(f))
                better = f.rows > info->rows;
            else if (f.size != info->size)
                better = f.size < info->size;
            else if (key.second.second != chosen->second.second)
                better = key.second.second > chosen->second.second;
            else if (key.second.first != chosen->second.first)
                better = key.second.first > chosen->second.first;
            else
                better = f.rows > info->rows;
        }
        if (better) {
            chosen = &key;
            info = &f;
        }
    }
    return chosen;
}

// The K the base averages and the K range the model answers for, at one reduction.
// Averaged: the K of the base's own family that cover its grid. Covered: the K of any family
// that covers the grid at the base's K too — a factorial run with one regularisation scaled
// with K, which checked K-independence (on a coarser mesh, or with other slopes per K, it
// still shows that u does not depend on K beyond what docs/fe.md states).
void baseKRange(const std::vector<FeRow> &rows, double reduction, const Family &chosen, BaseChoice *b)
{
    // The (n, μ) grid of each family and K at this reduction.
    std::map<Family, std::map<double, Grid>> grid;
    for (const auto &r : rows)
        if (reachedSnapshot(r, reduction) && isPaperSpecimen(r))
            grid[{meshKey(r), slopesPerK(r)}][r.kMpa].insert({r.n, r.mu});
    const auto &baseGrid = grid[chosen][b->kMpa];
    auto covers = [&](const Grid &g) { return std::includes(g.begin(), g.end(), baseGrid.begin(), baseGrid.end()); };
    std::set<double> covered;
    for (const auto &[fam, byK] : grid) {
        const auto atBaseK = byK.find(b->kMpa);
        if (atBaseK == byK.end() || !covers(atBaseK->second)) continue;
        for (const auto &[k, g] : byK) {
            if (!covers(g)) continue;
            covered.insert(k);
            if (fam == chosen) b->kAveraged.push_back(k);
        }
    }
    b->kCovered.assign(covered.begin(), covered.end());
}

} // namespace

BaseChoice chooseBase(const std::vector<FeRow> &rows, double reduction)
{
    BaseChoice b;
    const std::map<Family, FamilyInfo> families = familiesOf(rows);
    const Family *chosen = bestFamily(families);
    if (!chosen) return b;
    b.mesh = chosen->first;
    b.contactPerK = double(chosen->second.first) / 1000.0;
    b.stickPerK = double(chosen->second.second) / 1000.0;
    // The base's K: the most common among its snapshots at this reduction (ties: the lowest).
    std::map<double, int> kCount;
    for (const auto &r : rows)
        if (reachedSnapshot(r, reduction) && isPaperSpecimen(r) && meshKey(r) == b.mesh && b.sameRegularisation(r))
            ++kCount[r.kMpa];
    int best = 0;
    for (auto [k, c] : kCount)
        if (c > best) {
            best = c;
            b.kMpa = k;
        }
    b.found = best > 0;
    if (!b.found) return b;
    baseKRange(rows, reduction, *chosen, &b);
    return b;
}

bool BaseChoice::includes(const FeRow &r, double reduction) const
{
    return found && reachedSnapshot(r, reduction) && isPaperSpecimen(r) && meshKey(r) == mesh && hasK(r.kMpa) &&
           sameRegularisation(r);
}

bool BaseChoice::hasK(double k) const
{
    return std::find(kAveraged.begin(), kAveraged.end(), k) != kAveraged.end();
}

PointGrid basePoints(const std::vector<FeRow> &rows, double reduction)
{
    return basePoints(rows, reduction, chooseBase(rows, reduction));
}

PointGrid basePoints(const std::vector<FeRow> &rows, double reduction, const BaseChoice &base)
{
    PointGrid pts;
    if (!base.found) return pts;
    for (const auto &r : rows) {
        if (!base.includes(r, reduction)) continue;
        Point &p = pts[{r.n, r.mu}];
        p.n = r.n;
        p.mu = r.mu;
        p.elem = r.elem;
        p.mesh = base.mesh;
        const double u = r.uBest();
        p.tracked += r.uTrack >= 0;
        p.u += u;
        p.ri += r.ri;
        p.ro += r.ri + u;
        p.rMax += r.rMax;
        p.force += r.force / r.kMpa;
        p.kMin = std::min(p.kMin, r.kMpa);
        p.kMax = std::max(p.kMax, r.kMpa);
        ++p.count;
    }
    for (auto &[k, p] : pts) {
        const double c = p.count;
        p.u /= c;
        p.ri /= c;
        p.ro /= c;
        p.rMax /= c;
        p.force /= c;
    }
    return pts;
}

KCarry kCarry(const std::vector<FeRow> &rows, double reduction, const BaseChoice &base)
{
    KCarry c;
    if (!base.found) return c;
    using Family = std::pair<std::string, SlopesPerK>;
    // family → K → (n, μ) → the rows there (repeats averaged)
    std::map<Family, std::map<double, PointGrid>> fams;
    std::map<Family, double> famSize; // the finest element: the corner, or the uniform size
    for (const auto &r : rows) {
        if (!reachedSnapshot(r, reduction) || !isPaperSpecimen(r)) continue;
        famSize[{meshKey(r), slopesPerK(r)}] = r.cornerMm > 0 ? r.cornerMm : r.elem;
        Point &p = fams[{meshKey(r), slopesPerK(r)}][r.kMpa][{r.n, r.mu}];
        const double u = r.uBest();
        p.n = r.n;
        p.mu = r.mu;
        p.u += u;
        p.ri += r.ri;
        p.ro += r.ri + u;
        p.rMax += r.rMax;
        ++p.count;
    }
    for (auto &[fam, byK] : fams)
        for (auto &[k, pts] : byK)
            for (auto &[key, p] : pts) {
                p.u /= p.count;
                p.ri /= p.count;
                p.ro /= p.count;
                p.rMax /= p.count;
            }
    const PointGrid basePts = basePoints(rows, reduction, base);
    auto covers = [&](const PointGrid &g) {
        for (const auto &[key, p] : basePts)
            if (!g.count(key)) return false;
        return true;
    };
    const Family *best = nullptr;
    std::vector<double> bestK;
    double bestSize = 0;
    for (const auto &[fam, byK] : fams) {
        // The family must have every K the base averages: the differences are taken from them.
        bool hasBaseK = true;
        for (double k : base.kAveraged) hasBaseK = hasBaseK && byK.count(k) && covers(byK.at(k));
        if (!hasBaseK) continue;
        std::vector<double> ks;
        for (const auto &[k, pts] : byK)
            if (covers(pts)) ks.push_back(k);
        if (ks.size() < 2) continue;
        const double size = famSize.at(fam);
        bool better = !best || ks.size() > bestK.size();
        if (best && ks.size() == bestK.size()) {
            if (size != bestSize)
                better = size < bestSize;
            else
                better = fam.second.second > best->second.second;
        }
        if (better) {
            best = &fam;
            bestK = ks;
            bestSize = size;
        }
    }
    if (!best) return c;
    c.found = true;
    c.mesh = best->first;
    c.contactPerK = double(best->second.first) / 1000.0;
    c.stickPerK = double(best->second.second) / 1000.0;
    c.k = bestK;
    const auto &byK = fams.at(*best);
    for (const auto &[key, b] : basePts) {
        Point ref; // the family at the base's K (their mean, as the base averages them)
        for (double k : base.kAveraged) {
            const Point &p = byK.at(k).at(key);
            ref.u += p.u;
            ref.ri += p.ri;
            ref.ro += p.ro;
            ref.rMax += p.rMax;
        }
        const double m = double(base.kAveraged.size());
        for (double k : c.k) {
            const Point &p = byK.at(k).at(key);
            Point &d = c.delta[k][key];
            d.n = p.n;
            d.mu = p.mu;
            d.mesh = c.mesh;
            d.count = p.count;
            d.u = p.u - ref.u / m;
            d.ri = p.ri - ref.ri / m;
            d.ro = p.ro - ref.ro / m;
            d.rMax = p.rMax - ref.rMax / m;
        }
    }
    return c;
}

PointGrid basePoints(const std::vector<std::string> &in, double reduction)
{
    return basePoints(readSweepCsvs(in), reduction);
}

} // namespace icacam::host::fe
