#include "friction/reduction_corrected_model.h"

#include <algorithm>
#include <cmath>

#include "friction/reduction_table.h"

namespace icacam::friction {

namespace t = reduction_table;

double ReductionCorrectedModel::slopeAt(double n, double mu)
{
    n = std::clamp(n, t::kSlopeNMin, t::kSlopeNMax);
    mu = std::clamp(mu, t::kSlopeMuMin, t::kSlopeMuMax);
    const double *c = t::kSlope;
    return c[0] + c[1] * n + c[2] * mu + c[3] * n * n + c[4] * n * mu + c[5] * mu * mu;
}

double ReductionCorrectedModel::reductionMin()
{
    return t::kReductionMin;
}
double ReductionCorrectedModel::reductionMax()
{
    return t::kReductionMax;
}

double ReductionCorrectedModel::uAtBaseReduction(const ModelInputs &in, double reduction) const
{
    const double geo = in.d0Mm > 0 ? in.d0Mm / t::kD0Mm : 1.0; // u scales with D0
    ModelInputs m = in;
    m.hFinalMm = 0;
    double u50 = in.uMm;
    // Damped fixed point: du/dr depends on μ, which depends on u50. The slope changes
    // slowly with μ, so this settles in a few steps; 30 bounds the work.
    for (int it = 0; it < 30; ++it) {
        m.uMm = u50;
        const double mu = base_.estimate(m).mu;
        const double next = in.uMm - geo * slopeAt(in.n, mu) * (reduction - t::kBaseReduction);
        if (std::fabs(next - u50) < 1e-9) return next;
        u50 = 0.5 * (u50 + next);
    }
    return u50;
}

ModelEstimate ReductionCorrectedModel::estimate(const ModelInputs &in) const
{
    if (!(in.hFinalMm > 0)) return base_.estimate(in); // the model's own 50 %: nothing to carry
    ModelEstimate e;
    if (!(in.h0Mm > 0) || in.hFinalMm >= in.h0Mm) {
        // Not an upset specimen: no reduction to carry; report the base value, flagged.
        e = base_.estimate(in);
        e.range |= kModelReductionOutside;
        return e;
    }
    const double r = 1.0 - in.hFinalMm / in.h0Mm;
    ModelInputs m = in;
    m.hFinalMm = 0;
    m.uMm = uAtBaseReduction(in, r);
    e = base_.estimate(m);
    // The carry's own error: the FE slope is resolution-limited (docs/fe.md, "Stated error and
    // what limits it"); a quarter of the correction as one σ covers that spread.
    const double geo = in.d0Mm > 0 ? in.d0Mm / t::kD0Mm : 1.0;
    const double carrySigmaU = 0.25 * std::fabs(geo * slopeAt(in.n, e.mu) * (r - t::kBaseReduction));
    e.modelSigma = std::hypot(e.modelSigma, e.dMuDu * carrySigmaU);
    if (r < t::kReductionMin - 1e-9 || r > t::kReductionMax + 1e-9) e.range |= kModelReductionOutside;
    return e;
}

} // namespace icacam::friction
