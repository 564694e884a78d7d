#pragma once
// Closing the loop (PRODUCT.md §5, docs/loop-method.md): residuals of the μ model against
// measured records and a cross-validated ranking of candidate explanations.
//
// Pure computation (no image I/O): the command (loop_command.cpp) measures the records and
// fills LoopRecord; the tests build record sets directly.
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace icacam::host::loop {

struct LoopRecord {
    std::string id;
    std::map<std::string, std::string> columns; // every recorded column, as text
    std::map<std::string, double> diagnostics;  // measured by the pipeline (or derived)
    double n = 0, kMpa = 0, d0Mm = 10, h0Mm = 15;
    double uMm = 0;        // measured ICA width
    double muModel = 0;    // the model's μ at the measured u
    double muRef = 0;      // reference μ (independent method)
    double scaleSens = 0;  // dμ/du · u: μ's change per unit relative scale error of u
    double uSens = 0;      // dμ/du: μ's change per mm of u
    double reduction = -1; // 1 - h_final/h0 when recorded, else -1
    double muOffset = 0;   // a correction in μ the loop applied (a process variable's regression)
    std::string flags;     // the pipeline's flags, ';'-separated (what is odd about the image)
    bool usable = false;   // measured and with a reference
};

// Candidate explanation of the residual: one recorded column or one diagnostic.
struct Candidate {
    std::string name;
    // "numeric", "categorical", "diagnostic", or "interaction": a numeric condition with a
    // slope per level of a grouping (x and levels both set; named <x>_by_<grouping>).
    std::string kind;
    std::vector<double> x;           // numeric value per usable record (NaN: missing)
    std::vector<std::string> levels; // categorical level per usable record
    bool symptom = false;            // a measured quantity (isSymptom), not a recorded condition
    // x is the natural logarithm of the recorded value (a rate: isRate).
    bool logarithmic = false;
};

// A measured quantity (a symptom) rather than a recorded condition (a cause): every
// pipeline diagnostic (diag_*), what a device measured (device_*, from its journal), the radii of a radii record set
// (r_inner_mm, r_outer_mm, r_bulge_mm), what a device measured (mu, u_mm, reduction_est, status, flags, ...), and any
// column named after one of them (r_outer_px, u_over_r0, ...).
bool isSymptom(const std::string &name);

// A recorded rate (press speed, strain rate, velocity: a word of the name): it enters as its
// logarithm where every recorded value is positive, as rate effects go (a lubricant's regime,
// heating). Not the flow curve's (ε̇/ε̇₀)^m: that leaves u as it is (docs/fe.md).
bool isRate(const std::string &name);

// The specimen's height reduction as a candidate: recorded (h_final_mm, the derived
// reduction) or as the silhouette implies it (diag_reduction_est).
bool isReductionCandidate(const std::string &name);

// A grouping of materials: named so (material, alloy, grade), or every level declaring one n
// (and at least two levels differing).
bool isMaterialGrouping(const std::vector<LoopRecord> &usable, const Candidate &grouping);

struct RankedCandidate {
    std::string name, kind;
    // "mu": an offset in μ (per level, or linear in the value); "scale": a relative scale of
    // u (per level, or linear in the value), i.e. residual = (dμ/du · u) · (a + b x) — how an
    // optical scale error acts.
    std::string form = "mu";
    double cvRmsBefore = 0; // k-fold RMS of the residual with a constant offset only
    double cvRmsAfter = 0;  // k-fold RMS with the one-candidate model
    // The best plain regression of the residual (forms mu, scale, u): the patch the physical
    // forms are compared with.
    std::string patchForm = "mu";
    double cvRmsPatch = 0;
    double gain = 0;        // cvRmsBefore - cvRmsAfter
    double z = 0;           // nested F test of the form against its baseline, as a normal z
    double correlation = 0; // numeric: Pearson r with the residual (for reading only)
    bool significant = false;
    // Its form's z is an independent witness's (FittedForm::witnessZ: a length factor the
    // barrel's outline shows), μ's held-out error confirming it.
    bool witnessed = false;
    double witnessZ = std::numeric_limits<double>::quiet_NaN(); // FittedForm::witnessZ, taken or not
    double zFamily = 0; // the critical z of its round's family (Bonferroni over every try)
    bool symptom = false;
    // Significant through a significant symptom it cannot be told from (rankCandidates): on its
    // own only at the level of a single comparison.
    bool viaSymptom = false;
    // On a recorded condition moved ahead of measured quantities that ranked above it by a
    // margin within the noise (see rankCandidates): those symptoms, best first.
    std::vector<std::string> preferredOver;
    // On a significant recorded condition: the significant symptoms, best first: the
    // measurements that point to a cause.
    std::vector<std::string> pointedBy;
    // On a significant leading recorded condition: the significant recorded conditions that
    // group the records the same way and explain them as well (paired z < 2): these records
    // cannot tell them apart.
    std::vector<std::string> inseparable;
    // On a significant recorded condition put first although symptoms explain the residual
    // significantly better: those symptoms (they see more than it; the next round looks again).
    std::vector<std::string> aheadOfBetter;
    // Significant only with another recorded condition taken out (the two hid each other): that
    // condition, and this one's z on the records it leaves.
    std::string given;
    double givenZ = 0;
    // Put first over a significant recorded condition that ranked ahead of it and is not
    // significant with this one taken out, while this one is with it taken out: that condition
    // (this one explains what it did and more), and the two z's on what the other leaves.
    std::string subsumes;
    double subsumesZ = 0, subsumedZ = 0;
    // Significant recorded conditions that explain the same part of the residual as this one:
    // with either taken out the other is not significant. These records cannot say which it
    // is; they are not added after it.
    std::vector<std::string> sameResidual;
    // The influence check (loop_influence.h) on a candidate significant over the family: the
    // records whose leaving out lowers its z the most (indices into the round's records), and
    // its z and k-fold figures without them. carried: its z falls below a single comparison's
    // without them, so it is not significant here: these records carry it, not the population.
    std::vector<size_t> influential;
    double zWithout = 0, gainWithout = 0, cvRmsAfterWithout = 0;
    bool carried = false;
};

// A candidate's physical form fitted outside the ranking: held-out errors per record under it
// and under its own baseline.
struct FittedForm {
    std::string form;
    std::vector<double> baseline, errors;       // held out (k-fold)
    std::vector<double> baselineFit, errorsFit; // fitted on every record (the nested F test)
    int params0 = 1, params1 = 1;               // parameters of the baseline and of the form
    // An independent witness's test of the same effect, as a normal z (a length factor's
    // outline: loop_silhouette.h); NaN where none agreed with the form. The form's z is then
    // the two's combined (Stouffer's) z.
    double witnessZ = std::numeric_limits<double>::quiet_NaN();
};

struct RankingOptions {
    int folds = 5;
    uint32_t seed = 1;
    double alpha = 0.01;           // family-wise, Bonferroni over the candidates and forms
    double minRelativeGain = 0.05; // a chosen effect must cut the CV RMS by at least 5 %
    // The influence check leaves out this share of the records (at least one), the most
    // influential first; a candidate's z must stay above a single comparison's without them.
    double influentialShare = 0.02;
};

// The test of a single comparison: a gain, z above the one-sided α quantile, and the minimum
// relative gain.
bool passesSingleComparison(const RankedCandidate &c, const RankingOptions &opt);

// Fold index per record: a seeded permutation dealt round-robin (reproducible everywhere).
std::vector<int> foldAssignment(size_t count, int folds, uint32_t seed);

// Candidates from the records: every recorded column except id/image/mu_ref and identifier
// columns (a distinct text in every record), a derived `reduction` when h_final_mm is
// recorded, and every diagnostic.
std::vector<Candidate> buildCandidates(const std::vector<LoopRecord> &usable);

// Ranks candidates by k-fold CV RMS of the residual (μ_model − μ_ref) after the candidate's
// model, best first; significance is the gain over the form's own baseline. A symptom (a
// measured quantity: the radii answer to any cause that moves the geometry) never outranks a
// significant recorded condition it cannot be told from (the condition's held-out |errors|
// not significantly larger, paired z < 2): the condition moves ahead of it. With
// scaleSensitivity (dμ/du · u per record) each candidate is tried in both forms (the better
// one counts; the Bonferroni count doubles).
// uSensitivity (dμ/du per record) adds the form "u": an additive shift of u linear in the
// candidate (how a process that widens the ring acts).
std::vector<RankedCandidate> rankCandidates(const std::vector<Candidate> &candidates,
                                            const std::vector<double> &residual, const RankingOptions &opt,
                                            const std::vector<double> *scaleSensitivity = nullptr,
                                            const std::vector<double> *uSensitivity = nullptr,
                                            const std::map<std::string, std::vector<double>> *physicalForms = nullptr,
                                            const std::map<std::string, FittedForm> *fittedForms = nullptr);
// physicalForms: per candidate name, the change in μ a physical model of that candidate makes
// per record (the reduction: μ(u) − μ(u carried to 50 % with the FE du/dr)); tried as the form
// "fe": residual = a + b·change, a and b fitted per fold (b = 1: the physics as it is).
// fittedForms: per candidate name, a physical form fitted elsewhere (loop_physics.h: a length
// factor or an n per group), tried against its own baseline like the other forms.

// A date (YYYY-MM-DD, optionally with a time after it) as its day number; NaN otherwise.
double dayNumber(const std::string &text);

// Two candidates that group the records the same way: each one's value follows from the
// other's on at least 95 % of the records (a camera always used with one lens; a material
// and its declared n).
bool sameRecords(const Candidate &a, const Candidate &b);

// The residual predicted for every record by one candidate fitted on the records with
// fold != k (k < 0: on all): sensitivity nullptr for the mu form, dμ/du·u for scale, dμ/du for u.
std::vector<double> predictFrom(const Candidate &c, const std::vector<double> &residual, const std::vector<int> &fold,
                                int k, const std::vector<double> *sensitivity);

// Cross-validated predictions of the residual by one candidate (for before/after plots).
std::vector<double> cvPredict(const Candidate &c, const std::vector<double> &residual, const std::vector<int> &fold,
                              int folds, const std::vector<double> *scaleSensitivity = nullptr);

double rms(const std::vector<double> &v);

} // namespace icacam::host::loop
