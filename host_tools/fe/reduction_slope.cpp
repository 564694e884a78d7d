#include "host_tools/fe/reduction_slope.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "host_tools/fe/fe_base_data.h"
#include "host_tools/linear_system.h"

namespace icacam::host::fe {

bool ReductionSlope::load(const std::vector<std::string> &paths, std::string *error)
{
    FeBaseData base;
    if (!readFeBaseData(paths, &base, error)) return false;
    struct Case {
        double n = 0, mu = 0;
        std::vector<std::pair<double, double>> pts;
    };
    std::map<std::pair<long, long>, Case> cases; // by (n, μ): duplicates of a point average out in the fit
    std::vector<double> snapshots;               // every reduction a base run reached
    bool anyCase = false;
    for (const FeSnapshot &row : base.rows) {
        const double n = row.n, mu = row.mu, red = row.reduction, u = row.uMm;
        if (!anyCase) nMin_ = nMax_ = n, muMin_ = muMax_ = mu, anyCase = true;
        nMin_ = std::min(nMin_, n), nMax_ = std::max(nMax_, n);
        muMin_ = std::min(muMin_, mu), muMax_ = std::max(muMax_, mu);
        snapshots.push_back(red);
        if (red < 0.349 || u <= kFeUFloorMm) continue; // before the ICA opens the slope is not u's
        Case &c = cases[{std::lround(n * 1e4), std::lround(mu * 1e4)}];
        c.n = n;
        c.mu = mu;
        c.pts.emplace_back(red, u);
    }
    std::vector<double> ata(36, 0), atb(6, 0);
    cases_ = 0;
    maxCurvature_ = 0;
    double fitLo = 0.5;
    for (const auto &[name, c] : cases) {
        if (c.pts.size() < 3) continue;
        // u = a + b (r − 0.5) + c (r − 0.5)²: b is du/dr at the model's 50 % (u accelerates).
        std::vector<double> m3(9, 0), v3(3, 0), q;
        for (auto [x, y] : c.pts) {
            const double t[3] = {1, x - 0.5, (x - 0.5) * (x - 0.5)};
            for (int i = 0; i < 3; ++i) {
                v3[size_t(i)] += t[i] * y;
                for (int j = 0; j < 3; ++j) m3[size_t(i * 3 + j)] += t[i] * t[j];
            }
        }
        if (!solveLinearSystem(m3, v3, &q)) continue;
        const double s = q[1];
        maxCurvature_ = std::max(maxCurvature_, std::fabs(q[2]));
        for (auto [x, y] : c.pts) fitLo = std::min(fitLo, x);
        const double phi[6] = {1, c.n, c.mu, c.n * c.n, c.n * c.mu, c.mu * c.mu};
        for (int i = 0; i < 6; ++i) {
            atb[size_t(i)] += phi[i] * s;
            for (int j = 0; j < 6; ++j) ata[size_t(i * 6 + j)] += phi[i] * phi[j];
        }
        ++cases_;
    }
    for (int i = 0; i < 6; ++i) ata[size_t(i * 6 + i)] += 1e-9; // keeps a thin grid solvable
    if (cases_ < 6 || !solveLinearSystem(ata, atb, &coef_)) {
        *error = "too few FE cases (" + std::to_string(cases_) +
                 " of the 6 needed) with an open ICA over reductions >= 0.35 in the base data (" + base.mesh + ")";
        return false;
    }
    // Coverage of the linear carry about 50 %: the snapshots' span plus half their spacing,
    // cut where the largest curvature would make the neglected term exceed the u floor.
    std::sort(snapshots.begin(), snapshots.end());
    double spacing = 1;
    for (size_t i = 1; i < snapshots.size(); ++i)
        if (snapshots[i] - snapshots[i - 1] > 1e-3) spacing = std::min(spacing, snapshots[i] - snapshots[i - 1]);
    const double halfWidth = maxCurvature_ > 0 ? std::sqrt(kFeUFloorMm / maxCurvature_) : 1.0;
    reductionMin_ = std::max(fitLo, 0.5 - halfWidth);
    reductionMax_ = std::min(snapshots.back() + 0.5 * spacing, 0.5 + halfWidth);
    return true;
}

double ReductionSlope::slope(double n, double mu) const
{
    if (coef_.size() != 6) return 0;
    // Evaluate inside the simulated box only: outside it the quadratic is not data.
    n = std::clamp(n, nMin_, nMax_);
    mu = std::clamp(mu, muMin_, muMax_);
    return coef_[0] + coef_[1] * n + coef_[2] * mu + coef_[3] * n * n + coef_[4] * n * mu + coef_[5] * mu * mu;
}

double uAtModelReduction(const friction::FrictionModel &model, const ReductionSlope &slope,
                         const friction::ModelInputs &in, double reduction, double scaleFactor)
{
    if (reduction < 0) return in.uMm;
    const double geo = in.d0Mm > 0 ? in.d0Mm / 10.0 : 1.0;
    friction::ModelInputs m = in;
    double u50 = in.uMm;
    for (int it = 0; it < 20; ++it) {
        m.uMm = u50;
        const double mu = model.estimate(m).mu;
        const double next = in.uMm - scaleFactor * geo * slope.slope(in.n, mu) * (reduction - 0.5);
        if (std::fabs(next - u50) < 1e-9) {
            u50 = next;
            break;
        }
        u50 = 0.5 * (u50 + next);
    }
    return u50;
}
} // namespace icacam::host::fe
