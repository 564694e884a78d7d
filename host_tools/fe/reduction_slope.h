#pragma once
// The reduction carry's FE slope: du/dr at 50 % from the FE base's snapshots, the slope the
// generated table (friction/reduction_table.h) holds and `icacam loop` carries u with.
#include <string>
#include <vector>

#include "friction/friction_model.h"

namespace icacam::host::fe {

// du/dr (mm per unit height reduction, D0 = 10 mm) from the FE base's snapshots: per (n, μ)
// case, the slope at 50 % of a least-squares quadratic in r of u over the reductions >= 0.35
// where u is above the FE's u floor; then a smooth quadratic surface in (n, μ) through those
// slopes.
class ReductionSlope {
public:
    bool load(const std::string &sweepCsv, std::string *error)
    {
        return load(std::vector<std::string>{sweepCsv}, error);
    }
    // One or more sweep CSVs: the base data are chosen over all of them (fe_base_data.h).
    bool load(const std::vector<std::string> &sweepCsvs, std::string *error);
    // Direct construction (tests): slope = c0 + c1 n + c2 μ + c3 n² + c4 nμ + c5 μ².
    double slope(double n, double mu) const;
    const std::vector<double> &coefficients() const { return coef_; }
    int cases() const { return cases_; }
    // The (n, μ) box the sweep spans (the surface is evaluated inside it only).
    double nMin() const { return nMin_; }
    double nMax() const { return nMax_; }
    double muMin() const { return muMin_; }
    double muMax() const { return muMax_; }
    // The reductions over which the linear carry u50 = u − (du/dr)(r − 0.5) stands on data:
    // within the snapshots (plus half their spacing), and where the largest per-case
    // curvature of u(r) keeps the neglected quadratic term below the FE's u floor (0.02 mm).
    double reductionMin() const { return reductionMin_; }
    double reductionMax() const { return reductionMax_; }
    double maxCurvature() const { return maxCurvature_; } // |d²u/dr²|/2, mm

private:
    std::vector<double> coef_;
    int cases_ = 0;
    double nMin_ = 0.05, nMax_ = 0.5, muMin_ = 0.05, muMax_ = 0.3;
    double reductionMin_ = 0.5, reductionMax_ = 0.5, maxCurvature_ = 0;
};

// The FE u floor: below it the contact edge is not resolved (the slope fit ignores such
// points); also the tolerance for the neglected curvature of the linear carry.
constexpr double kFeUFloorMm = 0.02;

// u at the model's 50 % reduction: u50 = u − (du/dr)(r − 0.5), du/dr at (n, μ(u50)) found by
// fixed-point iteration, scaled with D0 by geometric similarity.
double uAtModelReduction(const friction::FrictionModel &model, const ReductionSlope &slope,
                         const friction::ModelInputs &in, double reduction, double scaleFactor = 1.0);

} // namespace icacam::host::fe
