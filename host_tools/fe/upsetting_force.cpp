#include "host_tools/fe/upsetting_force.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "host_tools/fe/fe_rows.h"

namespace icacam::host::fe {

namespace {

// The interval of a sorted axis that holds x, and x's share across it; false outside.
bool bracket(const std::vector<double> &axis, double x, size_t *i, double *t)
{
    if (axis.size() < 2 || x < axis.front() - 1e-9 || x > axis.back() + 1e-9) return false;
    size_t k = 0;
    while (k + 2 < axis.size() && x > axis[k + 1]) ++k;
    *i = k;
    *t = std::clamp((x - axis[k]) / (axis[k + 1] - axis[k]), 0.0, 1.0);
    return true;
}

} // namespace

bool UpsettingForce::load(const std::vector<std::string> &sweepCsvs, std::string *error)
{
    grids_.clear();
    std::vector<FeRow> rows;
    try {
        rows = readSweepCsvs(sweepCsvs);
    } catch (const std::exception &e) {
        *error = e.what();
        return false;
    }
    std::set<double> reductions;
    for (const FeRow &r : rows)
        if (r.reduction > 0 && r.force > 0) reductions.insert(std::round(r.reduction * 1e4) / 1e4);
    for (double red : reductions) {
        const PointGrid pts = basePoints(rows, red);
        if (pts.empty()) continue;
        Grid g;
        std::set<double> ns, mus;
        for (const auto &[key, p] : pts) ns.insert(p.n), mus.insert(p.mu);
        g.n.assign(ns.begin(), ns.end());
        g.mu.assign(mus.begin(), mus.end());
        if (g.n.size() < 2 || g.mu.size() < 2) continue;
        g.perK.assign(g.n.size() * g.mu.size(), NAN);
        for (const auto &[key, p] : pts) {
            const size_t i = size_t(std::find(g.n.begin(), g.n.end(), p.n) - g.n.begin());
            const size_t j = size_t(std::find(g.mu.begin(), g.mu.end(), p.mu) - g.mu.begin());
            if (p.force > 0) g.perK[i * g.mu.size() + j] = p.force;
        }
        grids_[red] = std::move(g);
    }
    if (grids_.size() < 2) {
        *error = "no FE base with forces at two reductions or more";
        return false;
    }
    return true;
}

bool UpsettingForce::atGrid(const Grid &g, double n, double mu, double *v) const
{
    size_t i, j;
    double tn, tm;
    if (!bracket(g.n, n, &i, &tn) || !bracket(g.mu, mu, &j, &tm)) return false;
    const size_t m = g.mu.size();
    const double a = g.perK[i * m + j], b = g.perK[i * m + j + 1];
    const double c = g.perK[(i + 1) * m + j], d = g.perK[(i + 1) * m + j + 1];
    *v = (1 - tn) * ((1 - tm) * a + tm * b) + tn * ((1 - tm) * c + tm * d);
    return std::isfinite(*v);
}

bool UpsettingForce::at(double n, double mu, double reduction, double kMpa, double d0Mm, double *kN) const
{
    if (grids_.size() < 2 || !(kMpa > 0) || !(d0Mm > 0)) return false;
    auto hi = grids_.lower_bound(reduction - 1e-9);
    if (hi == grids_.end()) return false;
    double perK;
    if (std::fabs(hi->first - reduction) < 1e-9) {
        if (!atGrid(hi->second, n, mu, &perK)) return false;
    } else {
        if (hi == grids_.begin()) return false;
        const auto lo = std::prev(hi);
        double a, b;
        if (!atGrid(lo->second, n, mu, &a) || !atGrid(hi->second, n, mu, &b)) return false;
        const double t = (reduction - lo->first) / (hi->first - lo->first);
        perK = (1 - t) * a + t * b;
    }
    *kN = perK * kMpa * (d0Mm / 10) * (d0Mm / 10);
    return true;
}

} // namespace icacam::host::fe
