#include "fe_rows.h"

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
double d(const std::string &s) { return s.empty() ? 0.0 : std::strtod(s.c_str(), nullptr); }
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
    return (r.status == "ok" || r.status == "failed") && std::fabs(r.reduction - reduction) < 1e-6 &&
           r.reduction > 0;
}

bool isPaperSpecimen(const FeRow &r) { return r.eMpa == 210000 && r.d0 == 10 && r.h0 == 15; }

std::vector<FeRow> readSweepCsv(const std::string &path)
{
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot read " + path);
    std::string line;
    std::getline(f, line);
    const auto head = split(line);
    std::map<std::string, size_t> col;
    for (size_t i = 0; i < head.size(); ++i) col[head[i]] = i;
    for (const char *need : {"case", "status", "k_mpa", "n", "mu", "e_mpa", "d0_mm", "h0_mm", "reduction",
                             "elem_mm", "r_i_mm", "r_o_interp_mm", "r_max_mm", "u_interp_mm", "force_kn"})
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
        r.caseId = get("case"); r.status = get("status");
        r.kMpa = d(get("k_mpa")); r.n = d(get("n")); r.mu = d(get("mu")); r.eMpa = d(get("e_mpa"));
        r.d0 = d(get("d0_mm")); r.h0 = d(get("h0_mm")); r.reductionMax = d(get("reduction_max"));
        r.reduction = d(get("reduction")); r.elem = d(get("elem_mm"));
        if (col.count("element")) r.element = get("element");
        if (col.count("contact") && !get("contact").empty()) r.contact = get("contact");
        if (col.count("corner_mm")) r.cornerMm = d(get("corner_mm"));
        if (col.count("stick_slope")) r.stickSlope = d(get("stick_slope"));
        if (col.count("contact_slope")) r.contactSlope = d(get("contact_slope"));
        if (col.count("nu")) r.nu = d(get("nu"));
        r.ri = d(get("r_i_mm")); r.ro = d(get("r_o_mm")); r.roInterp = d(get("r_o_interp_mm"));
        r.rMax = d(get("r_max_mm")); r.u = d(get("u_mm")); r.uInterp = d(get("u_interp_mm"));
        r.force = d(get("force_kn")); r.wallS = d(get("wall_s"));
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

BaseChoice chooseBase(const std::vector<FeRow> &rows, double reduction)
{
    BaseChoice b;
    auto inBase = [&](const FeRow &r) { return reachedSnapshot(r, reduction) && isPaperSpecimen(r); };
    // Per mesh: its rows, its finest element (the corner, or the uniform size) and the
    // (n, μ) grid of each K on it — over the cases, whatever reduction they reached, so that
    // every reduction of the model comes from the same mesh.
    auto inCases = [](const FeRow &r) {
        return (r.status == "ok" || r.status == "failed") && r.reduction > 0 && isPaperSpecimen(r);
    };
    struct MeshInfo {
        int rows = 0;
        double size = 0;
        std::map<double, std::set<std::pair<double, double>>> grid;
    };
    std::map<std::string, MeshInfo> meshes;
    for (const auto &r : rows)
        if (inCases(r)) {
            MeshInfo &m = meshes[meshKey(r)];
            ++m.rows;
            m.size = r.cornerMm > 0 ? r.cornerMm : r.elem;
            m.grid[r.kMpa].insert({r.n, r.mu});
        }
    // The whole grid: every (n, μ) any mesh has at one K.
    std::set<std::pair<double, double>> whole;
    for (const auto &[key, m] : meshes)
        for (const auto &[k, g] : m.grid) whole.insert(g.begin(), g.end());
    auto complete = [&](const MeshInfo &m) {
        for (const auto &[k, g] : m.grid)
            if (std::includes(g.begin(), g.end(), whole.begin(), whole.end())) return true;
        return false;
    };
    // The finest mesh that covers the whole grid at one K is the best answer the data has;
    // a finer mesh at a few points is a mesh study, not a base (ties: the most rows). No
    // complete mesh: the most common one.
    const MeshInfo *chosen = nullptr;
    for (const auto &[key, m] : meshes) {
        const bool better = !chosen || (complete(m) != complete(*chosen) ? complete(m)
                                        : complete(m) && m.size != chosen->size ? m.size < chosen->size
                                                                                 : m.rows > chosen->rows);
        if (better) { chosen = &m; b.mesh = key; }
    }
    if (!chosen) return b;
    std::map<double, int> kCount;
    for (const auto &r : rows)
        if (inBase(r) && meshKey(r) == b.mesh) ++kCount[r.kMpa];
    int best = 0;
    for (auto [k, c] : kCount) if (c > best) { best = c; b.kMpa = k; }
    b.found = best > 0;
    if (!b.found) return b;
    // Slopes per K and the (n, μ) grid of each (mesh, K).
    auto perK = [](double slope, double k) { return k > 0 ? slope / k : 0.0; };
    using MeshK = std::pair<std::string, double>;
    std::map<MeshK, std::set<std::pair<double, double>>> grid;
    std::map<MeshK, std::set<std::pair<double, double>>> slopes; // → {(contact/K, stick/K)}
    for (const auto &r : rows)
        if (inBase(r)) {
            grid[{meshKey(r), r.kMpa}].insert({r.n, r.mu});
            slopes[{meshKey(r), r.kMpa}].insert({perK(r.contactSlope, r.kMpa), perK(r.stickSlope, r.kMpa)});
        }
    const MeshK base{b.mesh, b.kMpa};
    const auto &baseGrid = grid[base];
    const auto &baseSlopes = slopes[base];
    auto close = [](const std::pair<double, double> &a, const std::pair<double, double> &c) {
        return std::fabs(a.first - c.first) <= 1e-6 * std::fabs(c.first) &&
               std::fabs(a.second - c.second) <= 1e-6 * std::fabs(c.second);
    };
    std::set<double> covered;
    for (const auto &[mk, g] : grid) {
        const bool covers = std::includes(g.begin(), g.end(), baseGrid.begin(), baseGrid.end());
        const bool sameSlopes = slopes[mk].size() == 1 && baseSlopes.size() == 1 &&
                                close(*slopes[mk].begin(), *baseSlopes.begin());
        if (mk == base || (covers && sameSlopes)) {
            covered.insert(mk.second);
            if (mk.first == b.mesh) b.kAveraged.push_back(mk.second);
        }
    }
    b.kCovered.assign(covered.begin(), covered.end());
    return b;
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
        if (!reachedSnapshot(r, reduction) || !isPaperSpecimen(r) || meshKey(r) != base.mesh || !base.hasK(r.kMpa))
            continue;
        Point &p = pts[{r.n, r.mu}];
        p.n = r.n; p.mu = r.mu; p.elem = r.elem; p.mesh = base.mesh;
        const double u = r.uBest();
        p.tracked += r.uTrack >= 0;
        p.u += u; p.ri += r.ri; p.ro += r.ri + u; p.rMax += r.rMax; p.force += r.force / r.kMpa;
        p.kMin = std::min(p.kMin, r.kMpa); p.kMax = std::max(p.kMax, r.kMpa);
        ++p.count;
    }
    for (auto &[k, p] : pts) {
        const double c = p.count;
        p.u /= c; p.ri /= c; p.ro /= c; p.rMax /= c; p.force /= c;
    }
    return pts;
}

PointGrid basePoints(const std::vector<std::string> &in, double reduction)
{
    return basePoints(readSweepCsvs(in), reduction);
}

} // namespace icacam::host::fe
