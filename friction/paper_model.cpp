#include "friction/paper_model.h"

#include <cmath>

namespace icacam::friction {

namespace {
double cubic(double x, double c3, double c2, double c1, double c0)
{
    return ((c3 * x + c2) * x + c1) * x + c0;
}
} // namespace

PaperModel::Coefficients PaperModel::coefficients(double n)
{
    // Eq. 3 of the paper.
    return {cubic(n, -9.78142, 11.32378, -4.23226, 0.60661), cubic(n, 18.01546, -20.67774, 7.38683, -0.92918),
            cubic(n, -8.26771, 9.20005, -2.88130, 0.49425), cubic(n, 0.78652, -0.91056, 0.35799, -0.00788)};
}

ModelEstimate PaperModel::estimate(const ModelInputs &in) const
{
    ModelEstimate e;
    // Geometric similarity: u scales with the specimen's size at the same H0/D0 (the
    // paper's study used D0 = 10 mm).
    const double scale = in.d0Mm > 0 ? 10.0 / in.d0Mm : 1.0;
    const double u = in.uMm * scale;
    const Coefficients c = coefficients(in.n);
    e.mu = cubic(u, c.a, c.b, c.c, c.d);
    e.dMuDu = ((3 * c.a * u + 2 * c.b) * u + c.c) * scale;
    // The paper reports 2 % mean and 10 % max deviation of the fit from its FE data: take
    // 3 % as one standard deviation of the model's own error.
    e.modelSigma = 0.03 * std::fabs(e.mu);

    if (in.n < 0.05 - 1e-9) e.range |= kModelNBelow;
    if (in.n > 0.5 + 1e-9) e.range |= kModelNAbove;
    if (in.kMpa > 0 && (in.kMpa < 250 - 1e-9 || in.kMpa > 1250 + 1e-9)) e.range |= kModelKOutside;
    if (e.mu < 0.05 - 0.0025) e.range |= kModelMuBelow;
    if (e.mu > 0.3 + 0.0025) e.range |= kModelMuAbove;
    // Beyond u ≈ 1.25 mm the cubic turns over at low n: the fit has no data there.
    if (u < 0 || u > 1.25 || e.dMuDu <= 0) e.range |= kModelUOutside;
    // The paper simulated one slenderness, H0/D0 = 1.5; u depends on it (docs/fe.md).
    if (in.d0Mm > 0 && in.h0Mm > 0 && std::fabs(in.h0Mm / in.d0Mm - 1.5) > kAspectTolerance)
        e.range |= kModelAspectOutside;
    return e;
}

} // namespace icacam::friction
