#pragma once
// μ(u, n) and the radii R_i, R_o, R_max from our own CalculiX runs (docs/fe.md).
// The table is generated: friction/fe_model_table.h, by `icacam fe tables` from one FE base.
// Pure C++20: no heap, no OS calls, no exceptions.
#include "friction/friction_model.h"

namespace icacam::friction {

struct FeRadii {
    double riMm = 0, roMm = 0, rMaxMm = 0;
    uint32_t range = kModelInRange;
};

// μ at uMm along one n from that n's (u, μ) points in rising μ (u < 0: no data): the
// interpolation FeModel uses (a μ plateau where u does not grow keeps its largest μ, then a
// monotone cubic); outside: uMm beyond the points. Exposed for the leave-one-out check of
// `icacam fe report`. At most kMaxRowPoints points are read.
inline constexpr int kMaxRowPoints = 10;
double feMuAlongU(const double *u, const double *mu, int count, double uMm, bool *outside);

class FeModel final : public FrictionModel {
public:
    const char *name() const override { return "fe"; }
    // μ from u (scaled to D0 = 10 mm by geometric similarity) and n: monotone cubic (PCHIP)
    // in u along each simulated n, linear between the simulated n, at the declared final
    // height's reduction (snapshots 30-60 %, linear between them), else at 50 %; at the given
    // K through the K carry (linear in K between the factorial's K), else at the base's K.
    ModelEstimate estimate(const ModelInputs &in) const override;
    bool correctsReduction() const override { return true; }
    // The FE's u at (n, μ, reduction; 0: 50 %) (D0 = 10 mm), linear between grid points, at
    // K (MPa; 0: the base's K) through the generated K carry.
    double uAt(double n, double mu, double reduction = 0, double kMpa = 0) const;
    // The radii the FE predicts at (n, μ, reduction; 0: 50 %, K; 0: the base's), scaled to d0Mm.
    FeRadii radii(double n, double mu, double d0Mm = 10, double reduction = 0, double kMpa = 0) const;
};

} // namespace icacam::friction
