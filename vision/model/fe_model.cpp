#include "fe_model.h"

#include <cmath>

#include "fe_model_table.h"
#include "table_axis.h"

namespace icacam::vision {

namespace t = fe_table;
static_assert(t::kMuCount <= kMaxRowPoints, "a row of the table must fit the interpolation's buffer");

namespace {

// One n row: the points (u, μ) with data where u rises strictly with μ (the invertible part).
struct Row {
    double u[kMaxRowPoints] = {};
    double mu[kMaxRowPoints] = {};
    int count = 0;
};

Row rowFrom(const double *us, const double *mus, int count)
{
    Row r;
    for (int j = 0; j < count && j < kMaxRowPoints; ++j) {
        const double u = us[j];
        if (u < 0) continue;
        if (r.count > 0 && u <= r.u[r.count - 1] + 1e-6) {
            // u did not grow (no fold-over yet at this μ): u cannot tell these μ apart; keep
            // the largest, so that u just above it interpolates from the end of the plateau.
            r.mu[r.count - 1] = mus[j];
            continue;
        }
        r.u[r.count] = u;
        r.mu[r.count] = mus[j];
        ++r.count;
    }
    return r;
}

using Carry = double[t::kKCount][t::kRCount][t::kNCount][t::kMuCount];

// How the value at grid point (ri, ni, mj) moves from the base's K to kMpa (≤ 0: not given,
// the base's K): the generated K carry, linear in K between the carried K, held at the ends
// (estimate flags a K outside them).
double carryAt(const Carry &d, int ri, int ni, int mj, double kMpa)
{
    if (kMpa <= 0 || t::kKCount < 2) return 0;
    int i = 0;
    double w = 0;
    bracketAxis(t::kK, t::kKCount, kMpa, i, w);
    return (1 - w) * d[i][ri][ni][mj] + w * d[i + 1][ri][ni][mj];
}

// The tables at K: u (never below 0: no fold-over is no fold-over), R_i, R_o, R_max; -1 where
// the base has no data.
double uAtK(int ri, int ni, int mj, double k)
{
    const double u = t::kU[ri][ni][mj];
    if (u < 0) return -1;
    const double v = u + carryAt(t::kDU, ri, ni, mj, k);
    return v > 0 ? v : 0;
}
double riAtK(int ri, int ni, int mj, double k)
{
    const double v = t::kRi[ri][ni][mj];
    return v < 0 ? -1 : v + carryAt(t::kDRi, ri, ni, mj, k);
}
double roAtK(int ri, int ni, int mj, double k)
{
    const double v = t::kRo[ri][ni][mj];
    return v < 0 ? -1 : v + carryAt(t::kDRi, ri, ni, mj, k) + carryAt(t::kDU, ri, ni, mj, k);
}
double rMaxAtK(int ri, int ni, int mj, double k)
{
    const double v = t::kRmax[ri][ni][mj];
    return v < 0 ? -1 : v + carryAt(t::kDRmax, ri, ni, mj, k);
}

Row rowAt(int ri, int ni, double kMpa)
{
    double us[t::kMuCount];
    for (int j = 0; j < t::kMuCount; ++j) us[j] = uAtK(ri, ni, j, kMpa);
    return rowFrom(us, t::kMu, t::kMuCount);
}

// Monotone cubic Hermite (Fritsch–Carlson) through the row's points; clamps outside.
void pchip(const Row &r, double x, double &y, double &dy, bool &outside)
{
    outside = r.count < 2 || x < r.u[0] - 1e-9 || x > r.u[r.count - 1] + 1e-9;
    if (r.count == 0) { y = 0; dy = 0; return; }
    if (r.count == 1) { y = r.mu[0]; dy = 0; return; }
    int k = 0;
    while (k < r.count - 2 && x > r.u[k + 1]) ++k;
    auto slope = [&](int i) { return (r.mu[i + 1] - r.mu[i]) / (r.u[i + 1] - r.u[i]); };
    auto tangent = [&](int i) {
        if (i == 0) return slope(0);
        if (i == r.count - 1) return slope(i - 1);
        const double a = slope(i - 1), b = slope(i);
        if (a * b <= 0) return 0.0;
        return 2 / (1 / a + 1 / b); // harmonic mean keeps it monotone
    };
    const double h = r.u[k + 1] - r.u[k];
    double s = (x - r.u[k]) / h;
    if (s < 0) { y = r.mu[k] + (x - r.u[k]) * tangent(k); dy = tangent(k); return; }
    if (s > 1) { y = r.mu[k + 1] + (x - r.u[k + 1]) * tangent(k + 1); dy = tangent(k + 1); return; }
    const double m0 = tangent(k) * h, m1 = tangent(k + 1) * h;
    const double s2 = s * s, s3 = s2 * s;
    y = (2 * s3 - 3 * s2 + 1) * r.mu[k] + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * r.mu[k + 1] +
        (s3 - s2) * m1;
    dy = ((6 * s2 - 6 * s) * r.mu[k] + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * r.mu[k + 1] +
          (3 * s2 - 2 * s) * m1) / h;
}


// at(ri, i, j): a table's value at grid point (reduction ri, n i, μ j), < 0 without data.
using GridValue = double (*)(int, int, int, double);

double lerp2(GridValue at, int ri, double k, double n, double mu)
{
    int i = 0, j = 0;
    double wn = 0, wm = 0;
    bracketAxis(t::kN, t::kNCount, n, i, wn);
    bracketAxis(t::kMu, t::kMuCount, mu, j, wm);
    auto value = [&](int a, int b) {
        a = a < t::kNCount ? a : t::kNCount - 1;
        b = b < t::kMuCount ? b : t::kMuCount - 1;
        return at(ri, a, b, k);
    };
    // A grid point without data (-1) only matters when it carries weight: on a simulated
    // (n, μ) the neighbours' holes do not.
    const double w[4] = {(1 - wn) * (1 - wm), (1 - wn) * wm, wn * (1 - wm), wn * wm};
    const int ai[4] = {i, i, i + 1, i + 1}, bj[4] = {j, j + 1, j, j + 1};
    double sum = 0;
    for (int q = 0; q < 4; ++q) {
        if (w[q] == 0) continue;
        const double v = value(ai[q], bj[q]);
        if (v < 0) return -1;
        sum += w[q] * v;
    }
    return sum;
}

// Bilinear in (n, μ) at the two snapshot reductions around r, linear between them.
double lerp3(GridValue at, double k, double n, double mu, double r)
{
    int ri = 0;
    double w = 0;
    bracketAxis(t::kR, t::kRCount, r, ri, w);
    const double a = lerp2(at, ri, k, n, mu);
    if (w == 0 || t::kRCount == 1) return a;
    const double b = lerp2(at, ri + 1, k, n, mu);
    if (w == 1) return b;
    return a < 0 || b < 0 ? -1 : (1 - w) * a + w * b;
}

// μ from u at snapshot reduction index ri: PCHIP along the two simulated n around n.
ModelEstimate atReduction(int ri, double n, double u, double scale, double kMpa)
{
    ModelEstimate e;
    int i = 0;
    double w = 0;
    bracketAxis(t::kN, t::kNCount, n, i, w);
    const int i1 = t::kNCount > 1 ? i + 1 : i;
    double mu0 = 0, d0 = 0, mu1 = 0, d1 = 0;
    bool out0 = false, out1 = false;
    const Row r0 = rowAt(ri, i, kMpa), r1 = rowAt(ri, i1, kMpa);
    pchip(r0, u, mu0, d0, out0);
    pchip(r1, u, mu1, d1, out1);
    e.mu = (1 - w) * mu0 + w * mu1;
    e.dMuDu = ((1 - w) * d0 + w * d1) * scale;
    if ((w < 1 && out0) || (w > 0 && out1)) e.range |= kModelUOutside;
    return e;
}

} // namespace

double feMuAlongU(const double *u, const double *mu, int count, double uMm, bool *outside)
{
    double y = 0, dy = 0;
    bool out = true;
    pchip(rowFrom(u, mu, count), uMm, y, dy, out);
    if (outside) *outside = out;
    return y;
}

ModelEstimate FeModel::estimate(const ModelInputs &in) const
{
    ModelEstimate e;
    const double scale = in.d0Mm > 0 ? t::kD0Mm / in.d0Mm : 1.0;
    const double u = in.uMm * scale;
    if (in.n < t::kN[0] - 1e-9) e.range |= kModelNBelow;
    if (in.n > t::kN[t::kNCount - 1] + 1e-9) e.range |= kModelNAbove;
    if (in.kMpa > 0 && (in.kMpa < t::kKMinMpa - 1e-9 || in.kMpa > t::kKMaxMpa + 1e-9)) e.range |= kModelKOutside;
    if (in.d0Mm > 0 && in.h0Mm > 0 && std::fabs(in.h0Mm / in.d0Mm - t::kH0Mm / t::kD0Mm) > kAspectTolerance)
        e.range |= kModelAspectOutside;
    // The reduction: the declared final height's, else the model's own (50 %).
    double red = t::kReduction;
    if (in.hFinalMm > 0) {
        if (in.h0Mm > 0 && in.hFinalMm < in.h0Mm) red = 1.0 - in.hFinalMm / in.h0Mm;
        else e.range |= kModelReductionOutside;
    }
    if (red < t::kR[0] - 1e-9 || red > t::kR[t::kRCount - 1] + 1e-9) e.range |= kModelReductionOutside;
    int k = 0;
    double wr = 0;
    bracketAxis(t::kR, t::kRCount, red, k, wr);
    // u(μ) at the specimen's K: the base plus the K carry (the fold-over's onset moves with
    // the elastic strain K/E; docs/fe.md, the factorial).
    const ModelEstimate a = atReduction(k, in.n, u, scale, in.kMpa);
    const ModelEstimate b = t::kRCount > 1 ? atReduction(k + 1, in.n, u, scale, in.kMpa) : a;
    e.mu = (1 - wr) * a.mu + wr * b.mu;
    e.dMuDu = (1 - wr) * a.dMuDu + wr * b.dMuDu;
    if (wr < 1) e.range |= a.range;
    if (wr > 0) e.range |= b.range;
    const double muLo = t::kMu[0], muHi = t::kMu[t::kMuCount - 1];
    if (e.mu < muLo - 1e-9 || (u <= 0 && muLo > 0)) e.range |= kModelMuBelow;
    if (e.mu > muHi + 1e-9) e.range |= kModelMuAbove;
    if (e.dMuDu <= 0) e.range |= kModelUOutside;
    // The model's own error: the FE's own spread in u (independent model and mesh study,
    // docs/fe.md: a few per cent where the side has rolled far, tens of per cent near the
    // fold-over's onset), 0.03 u + 0.02 mm at D0 = 10, through the slope; plus 0.003 for the
    // interpolation between simulated n and μ.
    const double sigmaU10 = 0.03 * u + 0.02;
    e.modelSigma = std::hypot(std::fabs(e.dMuDu / scale) * sigmaU10, 0.003);
    return e;
}

double FeModel::uAt(double n, double mu, double reduction, double kMpa) const
{
    return lerp3(uAtK, kMpa, n, mu, reduction > 0 ? reduction : t::kReduction);
}

FeRadii FeModel::radii(double n, double mu, double d0Mm, double reduction, double kMpa) const
{
    FeRadii r;
    const double s = d0Mm / t::kD0Mm;
    const double red = reduction > 0 ? reduction : t::kReduction;
    r.riMm = lerp3(riAtK, kMpa, n, mu, red) * s;
    r.roMm = lerp3(roAtK, kMpa, n, mu, red) * s;
    r.rMaxMm = lerp3(rMaxAtK, kMpa, n, mu, red) * s;
    if (kMpa > 0 && (kMpa < t::kKMinMpa - 1e-9 || kMpa > t::kKMaxMpa + 1e-9)) r.range |= kModelKOutside;
    if (red < t::kR[0] - 1e-9 || red > t::kR[t::kRCount - 1] + 1e-9) r.range |= kModelReductionOutside;
    if (n < t::kN[0] - 1e-9) r.range |= kModelNBelow;
    if (n > t::kN[t::kNCount - 1] + 1e-9) r.range |= kModelNAbove;
    if (mu < t::kMu[0] - 1e-9) r.range |= kModelMuBelow;
    if (mu > t::kMu[t::kMuCount - 1] + 1e-9) r.range |= kModelMuAbove;
    if (r.riMm < 0) r.range |= kModelUOutside;
    return r;
}

} // namespace icacam::vision
