#pragma once
// Judges `icacam measure` results against a truth file, per condition: how many were
// measured, how many are right (|Δμ| within the tolerance) and of those how many say ok (a
// status that warns on right readings is ignored), how many are silent wrong answers (status
// ok and |Δμ| beyond the tolerance),
// and whether the reported uncertainty is honest (the fraction within k σ, the median
// |Δμ|/σ). PRODUCT.md §7; docs/uncertainty.md ("Coverage").
//
// σ per result: with the budget columns (sigma_edges, sigma_scale, sigma_reduction,
// sigma_n, sigma_model), the combination without the model's own fit error when the truth is
// the measuring model's own (a paper model measured against the paper's truth): sqrt(mu_sigma²
// − sigma_model²); otherwise mu_sigma as reported.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "host_tools/manifest.h"

namespace icacam::host {

enum class ModelSigma { Auto, Keep, Drop };

struct ScoreOptions {
    double toleranceAbs = 0.01; // a silent wrong answer: ok with |Δμ| > max(abs, rel · μ)
    double toleranceRel = 0.05;
    double k = 2; // the coverage interval: |Δμ| ≤ k σ
    // Auto: drop sigma_model when the results' model is one of the paper's (the truth files
    // of `icacam synth` and ../shared/data hold the paper's μ) and the column exists.
    ModelSigma modelSigma = ModelSigma::Auto;
};

// A measured reading is right when |Δμ| ≤ max(abs, rel · μ_true).
inline bool isRight(double dmu, double muTrue, const ScoreOptions &opt)
{
    return std::fabs(dmu) <= std::max(opt.toleranceAbs, opt.toleranceRel * muTrue);
}

struct ConditionScore {
    std::string condition;
    int total = 0;    // records in the truth
    int measured = 0; // with a μ (ok or warn)
    int ok = 0;
    int right = 0;   // measured with |Δμ| within the tolerance
    int okRight = 0; // right and status ok: the status means something when most of them are
    int silentWrong = 0;
    int withinK = 0;        // measured with |Δμ| ≤ k σ
    double medianRatio = 0; // median |Δμ| / σ over the measured
    double medianAbs = 0;   // median |Δμ|
    double worstDmu = 0;    // the largest |Δμ|, signed
    std::string worstId, worstStatus;
    double worstOkDmu = 0; // the largest |Δμ| among the ok, signed
    std::string worstOkId;
    double withinFraction() const { return measured ? double(withinK) / measured : 0; }
    double okFraction() const { return measured ? double(ok) / measured : 0; }
    double okOnRightFraction() const { return right ? double(okRight) / right : 0; }
};

struct ScoreReport {
    std::vector<ConditionScore> conditions; // in the truth's order of first appearance, then "all"
    std::string sigmaSource;                // how σ was taken, for the table's caption
    std::vector<std::string> notes;         // ids without truth, rows without σ, ...
    const ConditionScore *find(const std::string &condition) const;
};

// results: `icacam measure` CSV; truth: id, mu and optionally condition. False with a
// message when a file lacks the columns it needs.
bool scoreResults(const Manifest &results, const Manifest &truth, const ScoreOptions &opt, ScoreReport *out,
                  std::string *error);

// The table, plain text or Markdown.
std::string formatScore(const ScoreReport &r, const ScoreOptions &opt, bool markdown);

} // namespace icacam::host
