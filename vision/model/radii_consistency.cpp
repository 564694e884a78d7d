#include "radii_consistency.h"

#include <algorithm>
#include <cmath>

#include "aspect_corrected_model.h"
#include "reduction_table.h"

namespace icacam::vision {

namespace t = reduction_table;

namespace {

double snapStep() { return t::kRCount > 1 ? t::kR[t::kRCount - 1] - t::kR[t::kRCount - 2] : 0.05; }

using Table = float[t::kNCount][t::kMuCount][t::kRCount];

// One simulated (n, μ) point's radius at reduction r: linear between the bracketing
// snapshots, or continued from the last two. False if those snapshots are missing.
bool atPoint(const Table &tab, int ni, int mi, double r, double *v)
{
    if (t::kRCount < 2) return false;
    int k = 0;
    while (k < t::kRCount - 2 && r > t::kR[k + 1]) ++k;
    const double a = tab[ni][mi][k], b = tab[ni][mi][k + 1];
    if (a < 0 || b < 0) return false;
    const double w = (r - t::kR[k]) / (t::kR[k + 1] - t::kR[k]);
    if (w < 0) return false; // before the first snapshot: not covered
    *v = a + w * (b - a);
    return true;
}

// One n row at μ: linear between the nearest simulated μ with data, held beyond them.
bool atRow(const Table &tab, int ni, double mu, double r, double *v)
{
    int lo = -1, hi = -1;
    double vlo = 0, vhi = 0, x;
    for (int j = 0; j < t::kMuCount; ++j) {
        if (!atPoint(tab, ni, j, r, &x)) continue;
        if (t::kMu[j] <= mu) lo = j, vlo = x;
        else if (hi < 0) hi = j, vhi = x;
    }
    if (lo < 0 && hi < 0) return false;
    if (lo < 0) { *v = vhi; return true; }
    if (hi < 0) { *v = vlo; return true; }
    *v = vlo + (mu - t::kMu[lo]) / (t::kMu[hi] - t::kMu[lo]) * (vhi - vlo);
    return true;
}

} // namespace

double radiiReductionMin() { return std::max(0.35, t::kR[0]); }
double radiiReductionMax() { return t::kR[t::kRCount - 1] + snapStep(); }

bool feRMaxAt(double n, double mu, double reduction, double *rMaxMm)
{
    return feRadiusAt(FeRadius::Max, n, mu, reduction, rMaxMm);
}

bool feRadiusAt(FeRadius which, double n, double mu, double reduction, double *mm)
{
    const Table &tab = which == FeRadius::Inner ? t::kRi : which == FeRadius::Outer ? t::kRo : t::kRmax;
    if (reduction > radiiReductionMax() + 1e-9) return false;
    n = std::clamp(n, t::kN[0], t::kN[t::kNCount - 1]);
    int i = 0;
    while (i < t::kNCount - 2 && n > t::kN[i + 1]) ++i;
    const int i1 = std::min(i + 1, t::kNCount - 1);
    const double w = i1 > i ? (n - t::kN[i]) / (t::kN[i1] - t::kN[i]) : 0;
    double a, b;
    const bool okA = atRow(tab, i, mu, reduction, &a), okB = atRow(tab, i1, mu, reduction, &b);
    if (okA && okB) *mm = a + w * (b - a);
    else if (okA && w < 0.5) *mm = a; // a row without data: the nearer one, only if it is the nearer
    else if (okB && w >= 0.5) *mm = b;
    else return false;
    return true;
}

RadiiCheck checkRadii(double rMaxMm, double n, double mu, double d0Mm, double reduction, double h0Mm)
{
    RadiiCheck c;
    const double g = d0Mm > 0 ? d0Mm / t::kD0Mm : 1.0; // R_max scales with D0
    const double aspect = d0Mm > 0 && h0Mm > 0 ? h0Mm / d0Mm : AspectCorrectedModel::baseAspect();
    // The FE R_max of the specimen's own slenderness at reduction r.
    auto feAt = [&](double r, double *mm) {
        if (!feRMaxAt(n, mu, r, mm)) return false;
        if (std::fabs(aspect - AspectCorrectedModel::baseAspect()) > kAspectTolerance)
            *mm *= AspectCorrectedModel::rMaxRatio(aspect, n, r, mu);
        return true;
    };
    double fe;
    if (!(rMaxMm > 0) || !feAt(reduction, &fe)) return c;
    c.valid = true;
    c.rMaxFeMm = fe * g;
    const double sigma = c.rMaxFeMm * std::hypot(kFeRMaxRelSigma, kMeasuredRMaxRelSigma);
    c.z = (rMaxMm - c.rMaxFeMm) / sigma;
    // The reduction the silhouette implies: R_max rises with r (volume constancy), so bisect.
    double lo = radiiReductionMin(), hi = radiiReductionMax(), vlo, vhi;
    if (!feAt(lo, &vlo) || !feAt(hi, &vhi)) return c;
    const double target = rMaxMm / g;
    if (target < vlo || target > vhi) return c; // outside what the snapshots span
    for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        double v;
        if (!feAt(mid, &v)) return c;
        (v < target ? lo : hi) = mid;
    }
    c.reductionEst = 0.5 * (lo + hi);
    return c;
}

} // namespace icacam::vision
