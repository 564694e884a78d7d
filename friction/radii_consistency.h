#pragma once
// Do the measured radii fit the physics? (docs/loop.md, "Consistency of the radii")
//
// The barrel silhouette R_max of an upset specimen is fixed by the height reduction r (volume
// constancy) and, less, by the friction μ and the hardening n (barrelling). The FE snapshots
// (friction/fe_model_table.h, every 5 % of reduction from 30 %) give R_max over (n, μ, r); R_max is the
// FE's best-resolved radius (it moves by < 0.015 mm between meshes, docs/fe.md). With μ from
// the measured u, R_max checks the declared scale and reduction: a scale error of a few percent
// moves R_max by as much, a reduction off by 0.01 moves it by ≈ 1 %. Without a declared final
// height the same relation, solved for r, gives the reduction the image implies.
//
// R_i and R_o are not used: the FE's contact edge is the least converged radius (its mesh
// study and independent models agree to a few per cent of u at μ ≥ 0.1 but by tens of per
// cent near the fold-over's onset at μ 0.05, docs/fe.md), while R_max moves by < 0.015 mm.
// With a converged edge they would add the check of n (R_i against R_o), which R_max alone
// resolves only weakly.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <cmath>

namespace icacam::friction {

// FE R_max at (n, μ, r) for D0 = 10 mm, read with the grid (grid.h): linear in r
// (extrapolated up to one snapshot step past the last, nothing before the first), linear in
// μ (held beyond the simulated μ: R_max saturates at high μ) and in n (held at the simulated
// n). False when there is no data (a weighted snapshot the runs did not reach).
bool feRMaxAt(double n, double mu, double reduction, double *rMaxMm);

// The same interpolation for any of the three radii (synthetic record sets place the contact
// edge with it; the check itself uses R_max only, see above).
enum class FeRadius { Inner, Outer, Max };
bool feRadiusAt(FeRadius which, double n, double mu, double reduction, double *mm);

// The reductions the table can speak for: 0.35 (or the first snapshot) to one step past the last.
double radiiReductionMin();
double radiiReductionMax();

// R_max's relative 1-σ errors: the FE against specimens and the measurement. The FE's R_max
// lies 0.2–1.1 % above the reference specimens' widest radius (the development set's 40
// records), by an offset that falls with n and with μ; feRMaxOverSpecimen models it, and what
// it leaves is 0.04 % RMS (0.11 % at most) on those records and 0.02 % RMS (0.04 % at most)
// on the reference photographs' 8, which it was not fitted to. kFeRMaxRelSigma keeps the
// 0.3 % that the offset's spread spans (1 %/√12): the reference specimens are drawn, and a
// lab's own may depart from them as far. On the development set's photographs the pipeline's
// silhouette radius lies within 0.1 % of the drawn one where the per-ray points agree (robust
// RMS 0.1–0.2 % of R_max about their fit); where a highlight band on the barrel merges into
// the outline on some rays the points scatter by 0.4–3 % and the radius reads up to 1.9 %
// short, within about twice that scatter. The measurement's σ is therefore the per-ray
// scatter (relative) with a 0.1 % floor; 0.5 % (the set's 1 σ over all photographs) where no
// per-ray fit gave one.
inline constexpr double kFeRMaxRelSigma = 0.003;
// The FE's R_max over a specimen's, less one, at (n, μ): a specimen's silhouette, multiplied
// by 1 + this, is held against the FE on the FE's own terms (a known systematic effect
// corrected). A plane in ln n and μ with their product, least squares over the development
// set's records at their true μ; n and μ are held at the records' span (0.075–0.475,
// 0.065–0.275) beyond it. Left out (a mean of 0.47 % instead), it reads silhouettes of low n
// up to 0.006 of reduction low and of high n and μ up to 0.003 high.
double feRMaxOverSpecimen(double n, double mu);
inline constexpr double kMeasuredRMaxRelFloor = 0.001;
inline constexpr double kMeasuredRMaxRelSigma = 0.005;
inline double measuredRMaxRelSigma(double scatterRel)
{
    return scatterRel > 0 ? std::hypot(kMeasuredRMaxRelFloor, scatterRel) : kMeasuredRMaxRelSigma;
}
// |z| beyond which R_max contradicts the declared scale and reduction: 3.5 σ ≈ 2.5 % of
// R_max, i.e. a scale error of about 2.5–3 % or a reduction off by about 0.025 (R_max grows by
// ≈ 1 % per 0.01 of reduction near 50 %). Smaller errors hide in the silhouette's scatter.
inline constexpr double kRadiiZLimit = 3.5;

struct RadiiCheck {
    bool valid = false;       // the FE had data at (n, μ)
    double rMaxFeMm = 0;      // FE R_max at the declared (or assumed 50 %) reduction, scaled to D0
    double z = 0;             // (measured − FE) / σ at that reduction
    double reductionEst = -1; // the reduction R_max implies at this μ and n; -1 if none in range
    bool inconsistent() const { return valid && (z > kRadiiZLimit || z < -kRadiiZLimit); }
};

// reduction: the declared one, or 0.5 when none was declared (the model's assumption).
// h0Mm: the specimen's initial height; at another slenderness than 1.5 the FE R_max is carried
// by the FE ratio R_max(H0/D0)/R_max(1.5) (friction/aspect_table.h: up to 1.8 % smaller at
// H0/D0 1.0, within ±1 % at 2.0); 0: the paper's 1.5.
// estimateReduction: also solve for reductionEst (a bisection: most of the cost); false where
// only the FE R_max at the given reduction is wanted. measuredRelSigma: the silhouette's own
// relative error (measuredRMaxRelSigma).
RadiiCheck checkRadii(double rMaxMm, double n, double mu, double d0Mm, double reduction, double h0Mm = 0,
                      bool estimateReduction = true, double measuredRelSigma = kMeasuredRMaxRelSigma);

} // namespace icacam::friction
