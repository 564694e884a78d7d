#include "friction/aspect_corrected_model.h"

#include <array>
#include <cmath>

#include "friction/aspect_table.h"
#include "friction/grid.h"

namespace icacam::friction {

namespace t = aspect_table;

double AspectCorrectedModel::baseAspect()
{
    return t::kBaseAspect;
}
double AspectCorrectedModel::aspectMin()
{
    return t::kAspect[0];
}
double AspectCorrectedModel::aspectMax()
{
    return t::kAspect[t::kACount - 1];
}

namespace {
using RatioTable = double[t::kACount][t::kNCount][t::kRCount][t::kMuCount];

// Multilinear in (aspect, n, reduction, μ), held at the simulated box's faces (estimate flags
// a slenderness beyond them).
double lookup(const RatioTable &tab, double aspect, double n, double reduction, double mu)
{
    constexpr std::array<GridAxis, 4> axes{GridAxis{t::kAspect, t::kACount}, GridAxis{t::kN, t::kNCount},
                                           GridAxis{t::kR, t::kRCount}, GridAxis{t::kMu, t::kMuCount}};
    return gridValue(&tab[0][0][0][0], axes, {aspect, n, reduction, mu});
}
} // namespace

double AspectCorrectedModel::uRatio(double aspect, double n, double reduction, double mu)
{
    return lookup(t::kURatio, aspect, n, reduction, mu);
}

double AspectCorrectedModel::rMaxRatio(double aspect, double n, double reduction, double mu)
{
    return lookup(t::kRMaxRatio, aspect, n, reduction, mu);
}

ModelEstimate AspectCorrectedModel::estimate(const ModelInputs &in) const
{
    if (!(in.d0Mm > 0) || !(in.h0Mm > 0)) return base_.estimate(in);
    const double aspect = in.h0Mm / in.d0Mm;
    if (std::fabs(aspect - t::kBaseAspect) <= kAspectTolerance) return base_.estimate(in);
    // The same specimen as the base model knows it: 1.5 slender, same D0 and reduction.
    ModelInputs m = in;
    m.h0Mm = t::kBaseAspect * in.d0Mm;
    if (in.hFinalMm > 0) m.hFinalMm = in.hFinalMm * m.h0Mm / in.h0Mm;
    const double reduction = in.hFinalMm > 0 && in.hFinalMm < in.h0Mm ? 1.0 - in.hFinalMm / in.h0Mm : 0.5;
    ModelEstimate e = base_.estimate(m);
    double ratio = 1;
    // μ enters the ratio only weakly: a few damped steps settle it.
    for (int it = 0; it < 8; ++it) {
        const double next = uRatio(aspect, in.n, reduction, e.mu);
        if (!(next > 0)) break;
        ratio = it == 0 ? next : 0.5 * (ratio + next);
        m.uMm = in.uMm / ratio;
        e = base_.estimate(m);
        if (std::fabs(uRatio(aspect, in.n, reduction, e.mu) - ratio) < 1e-6) break;
    }
    e.dMuDu /= ratio;
    // The carry's own error: a quarter of the correction in u (the ratio's spread with n and
    // mesh, docs/fe.md), carried through the slope.
    const double carrySigmaU = 0.25 * std::fabs(in.uMm - m.uMm);
    e.modelSigma = std::hypot(e.modelSigma, e.dMuDu * carrySigmaU);
    if (aspect < t::kAspect[0] - kAspectTolerance || aspect > t::kAspect[t::kACount - 1] + kAspectTolerance)
        e.range |= kModelAspectOutside;
    return e;
}

} // namespace icacam::friction
