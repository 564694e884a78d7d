#pragma once
// A μ model for specimens of another slenderness H0/D0 than the paper's 1.5 (docs/fe.md,
// "Slenderness").
//
// The ICA of a squat specimen is narrower, that of a slender one wider, at the same n, μ and
// height reduction (FE: at μ 0.1, 50 %, H0/D0 1.0 gives 0.69 of the 10 x 15 mm specimen's
// u). This decorator divides the measured u by the FE ratio u(H0/D0)/u(1.5) at (n, reduction,
// μ) from the generated table (friction/aspect_table.h, `icacam fe tables`) and evaluates the
// base model as if the specimen were 1.5 slender at the same reduction; μ enters the ratio,
// so it iterates. At H0/D0 = 1.5 it is the base model unchanged. Outside the simulated
// slenderness it sets kModelAspectOutside (μ still computed with the nearest ratio).
// Pure C++20: no heap, no OS calls, no exceptions.
#include "friction/friction_model.h"

namespace icacam::friction {

class AspectCorrectedModel final : public FrictionModel {
public:
    explicit constexpr AspectCorrectedModel(const FrictionModel &base) : base_(base) {}

    const char *name() const override { return base_.name(); }
    ModelEstimate estimate(const ModelInputs &in) const override;
    bool correctsReduction() const override { return base_.correctsReduction(); }

    // u(H0/D0) / u(1.5) from the table, multilinear, clamped to the simulated box.
    static double uRatio(double aspect, double n, double reduction, double mu);
    // R_max(H0/D0) / R_max(1.5), the silhouette's ratio (radii_consistency.h), the same way.
    static double rMaxRatio(double aspect, double n, double reduction, double mu);
    static double baseAspect(); // the paper's 1.5
    static double aspectMin();
    static double aspectMax();

private:
    const FrictionModel &base_;
};

} // namespace icacam::friction
