#pragma once
// The effects `icacam loop` adds one after another (docs/loop-method.md, "Several effects"):
// each in its physical form, taken out of the records before the next is looked for, and the
// held-out error with every effect so far refitted on each fold's training records.
#include <string>
#include <vector>

#include "friction/friction_model.h"
#include "host_tools/fe/reduction_slope.h"
#include "host_tools/loop/loop_analysis.h"
#include "host_tools/loop/loop_drift.h"
#include "host_tools/loop/loop_physics.h"

namespace icacam::host::loop {

// One effect as added: what it is, its physical estimates and the error around it.
struct LoopEffectStep {
    std::string name, kind; // the candidate
    std::string via;        // the candidate that led, where it is read through another (a material's n)
    std::string form;       // the form it was ranked in
    std::string patchForm;  // its best plain regression's form
    // "fe_slope", "scale", "n", "drift", "process" (a numeric condition, or a slope per level
    // of a grouping), "patch" (docs/loop.md, "The chosen effect").
    std::string reading;
    double z = 0;
    double cvRmsBefore = 0; // held-out RMS with the effects before it
    double cvRmsPatch = 0;  // its regression patch on the residual it was chosen from (k-fold)
    double cvRmsAfter = 0;  // held-out RMS with it added (every effect refitted per fold)
    bool symptom = false, viaSymptom = false;
    std::vector<std::string> preferredOver, pointedBy, inseparable;
    std::string given; // significant only with this other effect taken out (RankedCandidate::given)
    double givenZ = 0;
    std::string subsumes; // RankedCandidate::subsumes, subsumesZ, subsumedZ, sameResidual
    double subsumesZ = 0, subsumedZ = 0;
    std::vector<std::string> sameResidual;
    PhysicalFit grouping;                  // scale, n
    LinearEffect linear;                   // process (numeric)
    std::vector<std::string> slopeLevels;  // process (a slope per level): the levels, with
    std::vector<LinearEffect> levelSlopes; // each level's slope
    DriftFit drift;                        // drift
    std::vector<RankedCandidate> ranking;  // the round it led (after the first: on the residual left)
    // A length factor the outline witnesses, taken out before the effects added ahead of it
    // (the held-out RMS with it so refitted): those had taken up part of it.
    bool takenFirst = false;
    double witnessZ = 0; // the outline's z of a length factor (RankedCandidate::witnessZ)
};

// μ of every record as its inputs and applied corrections now give it (μ = model + muOffset),
// with μ's sensitivities dμ/du·u and dμ/du.
void refreshRecords(const friction::FrictionModel &model, std::vector<LoopRecord> *records);

// The reduction a record is carried from: as recorded, else as its silhouette implies it, else
// -1 (left as measured).
double carriedReduction(const LoopRecord &r);

// Fits the effect's physical form on the records with fold != k (k < 0: every record) and
// applies it to every record: u carried to 50 % (fe_slope: nothing fitted), u/s per group
// (scale), n + Δn per material (n), u/s(x) (drift), the regression taken off μ (process,
// patch). slope: the FE du/dr, for fe_slope.
// onlyDiffering: a grouping's levels are taken relative to its typical level, and those
// consistent with the declared value stay declared (the anchor when several effects are
// fitted together: a scale common to every camera, a shift common to every material and a
// regression's global scale move μ alike).
void applyEffect(const friction::FrictionModel &model, const fe::ReductionSlope *slope, const LoopEffectStep &step,
                 const Candidate &candidate, std::vector<LoopRecord> *records, const std::vector<int> &fold, int k,
                 bool onlyDiffering = false);

// What one effect does to each record, fitted once: u divided by a factor (a length factor, a
// drift), n shifted, μ offset (a regression); the reduction's carry is no share (nothing
// fitted).
struct EffectShare {
    std::vector<double> uFactor, nShift, muShift;
    std::vector<double> outlineFactor; // a length factor's share of the outline (1: none)
};
// The share an effect took: records before and after applyEffect.
EffectShare shareOf(const std::vector<LoopRecord> &before, const std::vector<LoopRecord> &after);
// The records with every share but `skip` applied to the originals (skip ≥ shares.size():
// all), then u carried to 50 % with the FE du/dr where `carry`.
std::vector<LoopRecord> withShares(const friction::FrictionModel &model, const fe::ReductionSlope *slope,
                                   const std::vector<LoopRecord> &original, const std::vector<EffectShare> &shares,
                                   size_t skip, bool carry);

// The sensitivity vector of a linear form ("scale": dμ/du·u, "u": dμ/du, else none).
std::vector<double> sensitivityOf(const std::vector<LoopRecord> &records, const std::string &form);

} // namespace icacam::host::loop
