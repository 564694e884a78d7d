#include "vision/level_end.h"

#include <algorithm>
#include <cmath>

#include "vision/normal_cdf.h"

namespace icacam::vision {

namespace {

constexpr int kMaxPoints = 40;
constexpr int kMaxBasis = 4;
// The quadratic beyond the edge must take at least this share of the plain step's residual
// away, and this many times the noise it leaves (two more parameters: χ²(2) exceeds 20 once
// in 22 000 on noise alone)…
constexpr double kEarnShare = 0.3;
constexpr double kEarnNoise = 20.0;
// …and the barrel must not be a level: beyond the edge it changes by at least half the jump
// onto it and 3 grey levels (a drawn band's texture and a rendered step's own shape give under
// a fifth of it).
constexpr double kMinChangeOfJump = 0.5, kMinChangeGrey = 3.0;
// Grid and refinement steps of the edge's search (pixels).
constexpr double kCoarseStepPx = 0.25, kFineStepPx = 0.025;

struct Points {
    double x[kMaxPoints], p[kMaxPoints];
    int n = 0;
    double mean = 0, sumP2 = 0; // p is kept about its mean (the sums stay well conditioned)
};

bool gather(const int32_t *profile, int count, int lo, int hi, Points *pts)
{
    lo = std::max(lo, 0);
    hi = std::min(hi, count - 1);
    if (hi - lo + 1 > kMaxPoints) return false;
    for (int k = lo; k <= hi; ++k) {
        pts->x[pts->n] = k;
        pts->p[pts->n] = profile[k] / 256.0;
        pts->mean += pts->p[pts->n];
        ++pts->n;
    }
    if (pts->n < 8) return false;
    pts->mean /= pts->n;
    for (int i = 0; i < pts->n; ++i) {
        pts->p[i] -= pts->mean;
        pts->sumP2 += pts->p[i] * pts->p[i];
    }
    return true;
}

// The residual sum of squares of p on the constant and `basis` columns of the blurred
// edge at e (Φ; then the ramp; then the quadratic); 1e300 for a singular system.
double residualAt(const Points &pts, double e, double sigma, int basis, double *coefOut = nullptr)
{
    const int m = basis + 1;
    double a[kMaxBasis + 1][kMaxBasis + 2] = {};
    for (int i = 0; i < pts.n; ++i) {
        const double z = (pts.x[i] - e) / sigma;
        const double cdf = normalCdf(z), pdf = normalPdf(z);
        const double f[kMaxBasis + 1] = {1.0, cdf, sigma * (z * cdf + pdf),
                                         sigma * sigma * ((z * z + 1) * cdf + z * pdf), 0.0};
        for (int r = 0; r < m; ++r) {
            for (int c = r; c < m; ++c) a[r][c] += f[r] * f[c];
            a[r][m] += f[r] * pts.p[i];
        }
    }
    double rhs[kMaxBasis + 1];
    for (int r = 0; r < m; ++r) {
        rhs[r] = a[r][m];
        for (int c = 0; c < r; ++c) a[r][c] = a[c][r];
    }
    // Gaussian elimination with partial pivoting on the normal equations.
    for (int c = 0; c < m; ++c) {
        int piv = c;
        for (int r = c + 1; r < m; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
        if (std::fabs(a[piv][c]) < 1e-9) return 1e300;
        if (piv != c)
            for (int k = 0; k <= m; ++k) std::swap(a[c][k], a[piv][k]);
        for (int r = c + 1; r < m; ++r) {
            const double g = a[r][c] / a[c][c];
            for (int k = c; k <= m; ++k) a[r][k] -= g * a[c][k];
        }
    }
    double coef[kMaxBasis + 1];
    for (int r = m - 1; r >= 0; --r) {
        double s = a[r][m];
        for (int k = r + 1; k < m; ++k) s -= a[r][k] * coef[k];
        coef[r] = s / a[r][r];
    }
    double fit = 0;
    for (int r = 0; r < m; ++r) fit += coef[r] * rhs[r];
    if (coefOut)
        for (int r = 0; r < m; ++r) coefOut[r] = coef[r];
    return std::max(0.0, pts.sumP2 - fit);
}

struct Best {
    double e = 0, ssr = 1e300;
};

// The edge's place with the least residual: a grid over [eLo, eHi], then finer about its best.
Best searchEdge(const Points &pts, double eLo, double eHi, double sigma, int basis)
{
    Best b;
    for (double e = eLo; e <= eHi + 1e-9; e += kCoarseStepPx) {
        const double s = residualAt(pts, e, sigma, basis);
        if (s < b.ssr) b = {e, s};
    }
    const double c = b.e;
    for (double e = c - kCoarseStepPx; e <= c + kCoarseStepPx + 1e-9; e += kFineStepPx) {
        if (e < eLo || e > eHi) continue;
        const double s = residualAt(pts, e, sigma, basis);
        if (s < b.ssr) b = {e, s};
    }
    return b;
}

} // namespace

LevelEnd fitLevelEnd(const int32_t *profile, int count, int lo, int hi, double eLo, double eHi, double sigma)
{
    LevelEnd out;
    Points pts;
    if (!(sigma > 0) || !(eHi > eLo) || !gather(profile, count, lo, hi, &pts) || pts.n < 10) return out;
    // The simplest model that earns its place: a step, a step and a ramp beyond, a step and a
    // quadratic beyond (a lit shoulder that turns into the dark).
    Best best = searchEdge(pts, eLo, eHi, sigma, 1);
    if (!(best.ssr < 1e299)) return out;
    out.found = true;
    int basis = 1;
    for (int more = 2; more <= 3; ++more) {
        const Best b = searchEdge(pts, eLo, eHi, sigma, more);
        const double noise = b.ssr / (pts.n - 2 - more);
        const double gain = best.ssr - b.ssr;
        if (gain > kEarnShare * best.ssr && gain > kEarnNoise * noise) best = b, basis = more;
    }
    if (basis == 1) return out;
    double c[kMaxBasis + 1] = {};
    residualAt(pts, best.e, sigma, basis, c);
    const double span = pts.x[pts.n - 1] - best.e;
    out.jump = c[1];
    out.barrelChange = c[2] * span + (basis == 3 ? c[3] * span * span : 0.0);
    out.stepSuffices = std::fabs(out.barrelChange) < std::max(kMinChangeGrey, kMinChangeOfJump * std::fabs(out.jump));
    if (!out.stepSuffices) out.edge = best.e;
    return out;
}

double fitStepBlur(const int32_t *profile, int count, int lo, int hi, double eLo, double eHi)
{
    Points pts;
    if (!(eHi > eLo) || !gather(profile, count, lo, hi, &pts)) return -1;
    // σ from 0.4 to 3 px by 0.1, each with its best place; then ±0.1 by 0.025 about the best.
    double bestSigma = -1, bestSsr = 1e300;
    for (int k = 4; k <= 30; ++k) {
        const Best b = searchEdge(pts, eLo, eHi, 0.1 * k, 1);
        if (b.ssr < bestSsr) bestSsr = b.ssr, bestSigma = 0.1 * k;
    }
    if (bestSigma < 0) return -1;
    const double c = bestSigma;
    for (double s = c - 0.1; s <= c + 0.1 + 1e-9; s += 0.025) {
        const Best b = searchEdge(pts, eLo, eHi, s, 1);
        if (b.ssr < bestSsr) bestSsr = b.ssr, bestSigma = s;
    }
    return bestSigma;
}

} // namespace icacam::vision
