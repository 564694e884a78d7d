#pragma once
// A μ model that accounts for a declared final height (docs/loop.md, "In the product").
//
// The paper's model (and our FE model) hold at exactly 50 % height reduction, and u grows
// steeply with the reduction (3–6 mm per unit r near 50 %): a specimen pressed to 52 % shows
// a wider ring that the base model reads as more friction. This decorator carries the
// measured u back to 50 % with the FE slope du/dr(n, μ) from the generated table
// (friction/reduction_table.h, `icacam fe tables`) and evaluates the base model there:
//   u50 = u − (D0/10)·du/dr(n, μ)·(r − 0.5),  μ = base(u50, n),  r = 1 − h_final/h0,
// with du/dr taken at μ = base(u50, n) (fixed-point iteration). Without a declared final
// height it is the base model unchanged. A reduction outside what the FE snapshots cover
// sets kModelReductionOutside (μ is still computed, never silently).
// Pure C++20: no heap, no OS calls, no exceptions.
#include "friction/friction_model.h"

namespace icacam::friction {

class ReductionCorrectedModel final : public FrictionModel {
public:
    // name: what results report as the model (e.g. "paper_reduction"); must outlive this.
    constexpr ReductionCorrectedModel(const FrictionModel &base, const char *name) : base_(base), name_(name) {}

    const char *name() const override { return name_; }
    ModelEstimate estimate(const ModelInputs &in) const override;
    bool correctsReduction() const override { return true; }

    // du/dr at the base reduction, mm per unit reduction at D0 = 10 mm, evaluated inside the
    // simulated (n, μ) box (outside it the surface is not data).
    static double slopeAt(double n, double mu);
    // The reductions the table's linear carry covers.
    static double reductionMin();
    static double reductionMax();
    // u carried to the base reduction (used by estimate; exposed for tests and the synth).
    double uAtBaseReduction(const ModelInputs &in, double reduction) const;

private:
    const FrictionModel &base_;
    const char *name_;
};

} // namespace icacam::friction
