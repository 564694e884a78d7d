#include "friction/fe_model.h"

#include <array>
#include <cmath>

#include "friction/fe_model_table.h"
#include "friction/grid.h"

namespace icacam::friction {

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
        if (!(u >= 0)) continue; // no data
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

// The table's axes as the grid reads them. Held at the ends: estimate and radii flag what
// lies beyond (an n, μ, reduction or K outside the runs), the value is the nearest edge's.
constexpr GridAxis kRAxis{t::kR, t::kRCount}, kNAxis{t::kN, t::kNCount}, kMuAxis{t::kMu, t::kMuCount},
    kKAxis{t::kK, t::kKCount};
constexpr std::array<GridAxis, 3> kGrid{kRAxis, kNAxis, kMuAxis};
using Index = std::array<int, 3>;

// How a table's value at grid point (reduction, n, μ) moves from the base's K to kMpa (<= 0:
// not given, the base's K): the generated K carry, linear in K between the carried K.
double carryAt(const double *carry, const Index &p, double kMpa)
{
    if (kMpa <= 0 || t::kKCount < 2) return 0;
    return gridValue<4>(carry, {kKAxis, kRAxis, kNAxis, kMuAxis}, {kMpa, t::kR[p[0]], t::kN[p[1]], t::kMu[p[2]]});
}

// The tables at K on a grid point: u (never below 0: no fold-over is no fold-over), R_i, R_o,
// R_max; NaN where the base has no data.
double uAtK(const Index &p, double k)
{
    const double v = t::kU[p[0]][p[1]][p[2]] + carryAt(&t::kDU[0][0][0][0], p, k);
    return v > 0 ? v : v == v ? 0 : kNoData;
}
double riAtK(const Index &p, double k)
{
    return t::kRi[p[0]][p[1]][p[2]] + carryAt(&t::kDRi[0][0][0][0], p, k);
}
double roAtK(const Index &p, double k)
{
    return t::kRo[p[0]][p[1]][p[2]] + carryAt(&t::kDRi[0][0][0][0], p, k) + carryAt(&t::kDU[0][0][0][0], p, k);
}
double rMaxAtK(const Index &p, double k)
{
    return t::kRmax[p[0]][p[1]][p[2]] + carryAt(&t::kDRmax[0][0][0][0], p, k);
}

// The row of one (reduction, n) grid point at K: its (u, μ) points.
Row rowAt(int ri, int ni, double kMpa)
{
    double us[t::kMuCount];
    for (int j = 0; j < t::kMuCount; ++j) us[j] = uAtK({ri, ni, j}, kMpa);
    return rowFrom(us, t::kMu, t::kMuCount);
}

// Monotone cubic Hermite (Fritsch–Carlson) through the row's points; clamps outside.
void pchip(const Row &r, double x, double &y, double &dy, bool &outside)
{
    outside = r.count < 2 || x < r.u[0] - 1e-9 || x > r.u[r.count - 1] + 1e-9;
    if (r.count == 0) {
        y = 0;
        dy = 0;
        return;
    }
    if (r.count == 1) {
        y = r.mu[0];
        dy = 0;
        return;
    }
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
    if (s < 0) {
        y = r.mu[k] + (x - r.u[k]) * tangent(k);
        dy = tangent(k);
        return;
    }
    if (s > 1) {
        y = r.mu[k + 1] + (x - r.u[k + 1]) * tangent(k + 1);
        dy = tangent(k + 1);
        return;
    }
    const double m0 = tangent(k) * h, m1 = tangent(k + 1) * h;
    const double s2 = s * s, s3 = s2 * s;
    y = (2 * s3 - 3 * s2 + 1) * r.mu[k] + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * r.mu[k + 1] + (s3 - s2) * m1;
    dy = ((6 * s2 - 6 * s) * r.mu[k] + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * r.mu[k + 1] +
          (3 * s2 - 2 * s) * m1) /
         h;
}

// A table at K over (reduction, n, μ): multilinear on the grid (NaN where a weighted grid
// point has no data).
template <class AtK> double lookup(AtK atK, double k, double red, double n, double mu)
{
    return blendCorners(locateOnGrid(kGrid, {red, n, mu}), [&](const Index &p) { return atK(p, k); });
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
        if (in.h0Mm > 0 && in.hFinalMm < in.h0Mm)
            red = 1.0 - in.hFinalMm / in.h0Mm;
        else
            e.range |= kModelReductionOutside;
    }
    if (red < t::kR[0] - 1e-9 || red > t::kR[t::kRCount - 1] + 1e-9) e.range |= kModelReductionOutside;
    // u(μ) at the specimen's K: the base plus the K carry (the fold-over's onset moves with
    // the elastic strain K/E; docs/fe.md, the factorial). Along u the monotone cubic of each
    // simulated (reduction, n) row: the model's choice, not a lookup; between the rows the
    // grid's corners, linear.
    bool outside = false;
    forEachCorner(locateOnGrid<2>({kRAxis, kNAxis}, {red, in.n}), [&](const std::array<int, 2> &p, double w) {
        double mu = 0, dMu = 0;
        bool out = false;
        pchip(rowAt(p[0], p[1], in.kMpa), u, mu, dMu, out);
        e.mu += w * mu;
        e.dMuDu += w * dMu * scale;
        outside = outside || out;
    });
    if (outside) e.range |= kModelUOutside;
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
    const double u = lookup(uAtK, kMpa, reduction > 0 ? reduction : t::kReduction, n, mu);
    return u == u ? u : -1;
}

FeRadii FeModel::radii(double n, double mu, double d0Mm, double reduction, double kMpa) const
{
    FeRadii r;
    const double s = d0Mm / t::kD0Mm;
    const double red = reduction > 0 ? reduction : t::kReduction;
    auto scaled = [&](double v) { return v == v ? v * s : -1.0; }; // -1: no data
    r.riMm = scaled(lookup(riAtK, kMpa, red, n, mu));
    r.roMm = scaled(lookup(roAtK, kMpa, red, n, mu));
    r.rMaxMm = scaled(lookup(rMaxAtK, kMpa, red, n, mu));
    if (kMpa > 0 && (kMpa < t::kKMinMpa - 1e-9 || kMpa > t::kKMaxMpa + 1e-9)) r.range |= kModelKOutside;
    if (red < t::kR[0] - 1e-9 || red > t::kR[t::kRCount - 1] + 1e-9) r.range |= kModelReductionOutside;
    if (n < t::kN[0] - 1e-9) r.range |= kModelNBelow;
    if (n > t::kN[t::kNCount - 1] + 1e-9) r.range |= kModelNAbove;
    if (mu < t::kMu[0] - 1e-9) r.range |= kModelMuBelow;
    if (mu > t::kMu[t::kMuCount - 1] + 1e-9) r.range |= kModelMuAbove;
    if (r.riMm < 0) r.range |= kModelUOutside;
    return r;
}

} // namespace icacam::friction
