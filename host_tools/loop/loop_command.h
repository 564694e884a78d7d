#pragma once
#include <string>
#include <vector>

#include "host_tools/loop/journal_records.h"
#include "host_tools/loop/loop_analysis.h"
#include "host_tools/loop/loop_effects.h"
#include "host_tools/loop/loop_influence.h"
#include "host_tools/loop/loop_physics.h"
#include "host_tools/loop/loop_rate.h"

namespace icacam::host {
// `icacam loop --manifest FILE --report DIR [--model paper] [--folds 5] [--seed S] [--fe-sweep CSV]`
int loopCommand(const std::vector<std::string> &args);
} // namespace icacam::host

namespace icacam::host::loop {

struct LoopSummary {
    int records = 0, usable = 0;
    std::vector<RankedCandidate> ranking; // the first round's: on the residual as the model reads it
    // The effects added, in order, each chosen on the residual the ones before it left
    // (loop_effects.h); the loop stops when no candidate is significant or the held-out
    // error would not drop. The fields below describe the first.
    std::vector<LoopEffectStep> effects;
    std::string stopped;                      // why no further effect was added
    std::vector<RankedCandidate> lastRanking; // the round that added nothing (after the first)
    std::string chosen;             // the first effect; empty: nothing significant, the model is left as it is
    double rmsBefore = 0;           // RMS of μ_model − μ_ref (no correction)
    double cvRmsOffset = 0;         // k-fold, constant offset only
    double cvRmsAfter = 0;          // k-fold, after every effect added (= rmsBefore if none)
    bool physical = false;          // the chosen effect was corrected through FE du/dr
    double rmsPhysical = 0;         // RMS after the physical reduction correction (no fitted parameter)
    double slopeScale = 0;          // least-squares scale of the FE du/dr on all records (1: FE as is)
    double cvRmsPhysicalScaled = 0; // k-fold with that scale fitted per fold
    // The chosen effect in its physical form (docs/loop-method.md): "fe_slope" (the reduction through
    // the FE du/dr), "scale" (a length factor per group of images: a recalibration), "n" (an n
    // per material), "process" (a recorded variable the FE does not model: its best linear
    // form and size, the FE study that would add it), "patch" (a symptom with no recorded
    // cause, or a reduction a reduction-aware model left: the regression only), "" (none).
    std::string reading;
    double cvRmsPatch = 0; // the chosen candidate's best regression of the residual (k-fold)
    PhysicalFit grouping;  // reading "scale" or "n"
    LinearEffect linear;   // reading "process"
    DriftFit drift;        // reading "drift"
    JournalJoin journal;   // runJournalLoop: what the join found
    // Candidates significant over the family only through a few records (the influence check,
    // loop_influence.h), from every round the loop ranked: not added; the records are named.
    std::vector<RecordFinding> carried;
    // Where the records carry the press's force: each material's m (loop_rate.h).
    RateSensitivity rate;
};

// Runs the whole analysis on a manifest and writes the report folder. feSweeps: the FE sweep
// CSV(s) for du/dr (base data chosen over all of them, host_tools/fe/fe_base_data.h).
LoopSummary runLoop(const std::string &manifestPath, const std::string &reportDir, const std::string &modelName,
                    const RankingOptions &opt, const std::vector<std::string> &feSweeps);

// The same on an icacam-fw journal folder joined with a CSV of reference values by record id
// (journal_records.h): the saved frames are re-measured with the current pipeline.
// calibrationDir: where the calibration files the journal names are (empty: the journal folder).
LoopSummary runJournalLoop(const std::string &journalDir, const std::string &referenceCsv, const std::string &reportDir,
                           const std::string &modelName, const RankingOptions &opt,
                           const std::vector<std::string> &feSweeps, const std::string &calibrationDir = "");

// On records already read; source: the report's first words about where they come from;
// skippedBefore: records left out before measuring, with why.
LoopSummary runLoopOn(const Manifest &manifest, const std::string &source,
                      const std::vector<std::string> &skippedBefore, const std::string &reportDir,
                      const std::string &modelName, const RankingOptions &opt,
                      const std::vector<std::string> &feSweeps);

} // namespace icacam::host::loop
