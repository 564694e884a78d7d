#pragma once
// μ(u, n): the map from ICA width to the Coulomb friction coefficient. The paper's fit is
// one implementation; models generated from our own finite-element runs sit beside it.
#include <cstdint>

namespace icacam::friction {

// Where an evaluation lies relative to what the model was built from.
enum ModelRangeFlag : uint32_t {
    kModelInRange = 0,
    kModelNBelow = 1u << 0, // n below the calibrated range
    kModelNAbove = 1u << 1,
    kModelKOutside = 1u << 2, // strength coefficient outside the simulated range
    kModelMuBelow = 1u << 3,  // the result lies below the simulated μ range
    kModelMuAbove = 1u << 4,
    kModelUOutside = 1u << 5,         // u outside the span the model's data covered at this n
    kModelReductionOutside = 1u << 6, // declared height reduction outside what the data cover
    kModelAspectOutside = 1u << 7,    // H0/D0 outside what the data cover (the paper: 1.5 only)
};

// H0/D0 within this of a model's simulated slenderness counts as that slenderness (1 %).
inline constexpr double kAspectTolerance = 0.015;

struct ModelEstimate {
    double mu = 0;
    double dMuDu = 0;      // slope at u (per mm): carries u's uncertainty into μ
    double modelSigma = 0; // the model's own error at this point (1 σ, absolute μ)
    uint32_t range = kModelInRange;
};

struct ModelInputs {
    double uMm = 0;
    double n = 0;
    double kMpa = 0;  // 0 when not given
    double d0Mm = 10; // initial diameter; u scales with it by geometric similarity
    double h0Mm = 15;
    double hFinalMm = 0; // final height when declared; 0: the model's own reduction (50 %)
};

class FrictionModel {
public:
    virtual ~FrictionModel() = default;
    virtual const char *name() const = 0;
    virtual ModelEstimate estimate(const ModelInputs &in) const = 0;
    // True when the model accounts for a declared final height itself (then it, not the
    // caller, says whether the reduction lies outside what it covers).
    virtual bool correctsReduction() const { return false; }
};

} // namespace icacam::friction
