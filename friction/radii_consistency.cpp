#include "friction/radii_consistency.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "friction/aspect_corrected_model.h"
#include "friction/fe_model_table.h"
#include "friction/grid.h"

namespace icacam::friction {

namespace t = fe_table; // the base's radii at every snapshot (K: the base's)

namespace {

double snapStep()
{
    return t::kRCount > 1 ? t::kR[t::kRCount - 1] - t::kR[t::kRCount - 2] : 0.05;
}

} // namespace

double radiiReductionMin()
{
    return std::max(0.35, t::kR[0]);
}
double radiiReductionMax()
{
    return t::kR[t::kRCount - 1] + snapStep();
}

double feRMaxOverSpecimen(double n, double mu)
{
    // data/fe/rmax_offset.py's fit over the development set (docs/uncertainty.md, "The silhouette").
    constexpr double c0 = -0.0019522, cLnN = -0.0069575, cMu = 0.0069456, cLnNMu = 0.0169174;
    const double ln = std::log(std::clamp(n, 0.075, 0.475)), m = std::clamp(mu, 0.065, 0.275);
    return c0 + cLnN * ln + cMu * m + cLnNMu * ln * m;
}

bool feRMaxAt(double n, double mu, double reduction, double *rMaxMm)
{
    return feRadiusAt(FeRadius::Max, n, mu, reduction, rMaxMm);
}

bool feRadiusAt(FeRadius which, double n, double mu, double reduction, double *mm)
{
    const auto &tab = which == FeRadius::Inner ? t::kRi : which == FeRadius::Outer ? t::kRo : t::kRmax;
    if (reduction > radiiReductionMax() + 1e-9) return false;
    // n and μ held at the simulated ends (R_max saturates at high μ), the reduction continued
    // past the last snapshot (up to radiiReductionMax) but not before the first.
    constexpr std::array<GridAxis, 3> axes{GridAxis{t::kR, t::kRCount, Beyond::Nothing, Beyond::Extend},
                                           GridAxis{t::kN, t::kNCount}, GridAxis{t::kMu, t::kMuCount}};
    const double v = gridValue(&tab[0][0][0], axes, {reduction, n, mu});
    if (!(v == v)) return false; // no data there
    *mm = v;
    return true;
}

RadiiCheck checkRadii(double rMaxMm, double n, double mu, double d0Mm, double reduction, double h0Mm,
                      bool estimateReduction, double measuredRelSigma)
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
    const double sigma = c.rMaxFeMm * std::hypot(kFeRMaxRelSigma, measuredRelSigma);
    c.z = (rMaxMm - c.rMaxFeMm) / sigma;
    if (!estimateReduction) return c;
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

} // namespace icacam::friction
