#pragma once
// A material's strain-rate sensitivity m from the press's force (docs/loop.md, "Press speed").
//
// Under σ = K ε^n (ε̇/ε̇₀)^m and Coulomb friction, a press speed λ times faster scales every
// strain rate by λ and every stress by λ^m, and friction (τ = μp) scales with the pressure: the
// same deformation solves the test at every speed. u, and so μ's reading, does not move with
// the speed (the FE's time-hardening form: 0 at m 0, +0.4 … +4.9 % per decade at m 0.05–0.1,
// the form's own memory of time, docs/fe.md); m shows as more n at any one speed. The force
// scales by λ^m: where records carry the load cell's force at the recorded height, ln of the
// force over the FE's rate-independent force at the record's n, μ and reduction against
// ln ε̇ (the press speed over the final height) is a line of slope m per material.
#include <ostream>
#include <string>
#include <vector>

#include "host_tools/fe/upsetting_force.h"
#include "host_tools/loop/loop_analysis.h"

namespace icacam::host::loop {

struct RateFit {
    std::string material;
    int records = 0;                   // with a force, a speed and the FE's force
    double speedMin = 0, speedMax = 0; // mm/s
    double m = 0, mSigma = 0;          // the slope and its standard uncertainty
    // The coverage factor for 95 % from Student's t at the fit's records − 2 degrees of
    // freedom (a few records: k 2.3–4.3, not 2): U = coverage · σ.
    double coverage = 2;
    // The flow curve's K at ε̇ 1 /s over the declared K (the intercept), and its σ.
    double kRatio = 0, kRatioSigma = 0;
    double scatter = 0; // RMS of ln(F/F_FE) about the line
    bool fitted = false;
    std::string why; // not fitted: why
};

struct RateSensitivity {
    std::string forceColumn, speedColumn, materialColumn; // empty forceColumn: no force recorded
    std::vector<RateFit> materials;
    int outsideFe = 0; // records outside the FE base (n, μ, reduction) or without a K
};

// The columns: force_kn (or peak_force_kn), the first recorded rate (isRate) with every value
// positive, and the material (material, alloy, grade; else the declared n). μ_ref is the
// record's μ (the FE's force barely depends on it); the height is the recorded one (50 %
// where none is). A material is fitted from 4 records over a speed range of 2:1 or more.
RateSensitivity fitRateSensitivity(const std::vector<LoopRecord> &usable, const fe::UpsettingForce &force);

// report.md's section and rate.csv (nothing where no force column was recorded).
void writeRateSection(std::ostream &md, const RateSensitivity &rate);
void writeRateCsv(const std::string &path, const RateSensitivity &rate);

} // namespace icacam::host::loop
