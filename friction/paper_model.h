#pragma once
#include "friction/friction_model.h"

namespace icacam::friction {

// Duran & Karadogan (2016): μ = a_n u³ + b_n u² + c_n u + d_n (Eq. 2), each coefficient a
// cubic in n (Eq. 3), with d_n's constant corrected to −0.00788 (PRODUCT.md §1: Table 1,
// the appendix script and Table 2 all agree with the minus sign). Valid for the paper's
// study: n 0.05–0.5, K 250–1250 MPa, μ 0.05–0.3, D0 = 10 mm, H0 = 15 mm, 50 % reduction.
class PaperModel final : public FrictionModel {
public:
    struct Coefficients {
        double a, b, c, d;
    };
    static Coefficients coefficients(double n);

    const char *name() const override { return "paper"; }
    ModelEstimate estimate(const ModelInputs &in) const override;
};

} // namespace icacam::friction
