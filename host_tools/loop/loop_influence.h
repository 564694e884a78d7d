#pragma once
// An effect the records carry, or a record that carries an effect (docs/loop-method.md,
// "Records that carry an effect"): a candidate's gain and z again with its most influential
// records left out. One odd image (a blurred end face, a ring off centre) with a large residual
// and an extreme value of a diagnostic makes that diagnostic's regression significant over the
// family; without that image nothing is left. Such a finding is about the records, not the
// population: the loop names the records and adds no effect.
#include <cstddef>
#include <string>
#include <vector>

#include "host_tools/loop/loop_analysis.h"

namespace icacam::host::loop {

// How many records the check leaves out of n: the stated share, at least one.
size_t influentialCount(size_t n, double share);

struct InfluenceCheck {
    std::vector<size_t> records;                      // the most influential records, in the order they were left out
    double z = 0;                                     // the form's nested F test without them, as a normal z
    double cvRmsBefore = 0, cvRmsAfter = 0, gain = 0; // k-fold without them
    bool stands = true;                               // z still above zNeeded without them
};

// The candidate c in a linear form (c: nullptr for a physical change such as the form `fe`,
// whose change in μ is `sens`) against its baseline (nullptr, baseSens) on the residual y:
// the record whose leaving out lowers the form's z the most is left out, then the next on the
// records left, `count` in all; then z and the k-fold gain on the records left (each keeps its
// fold). It stands where z stays above zNeeded (a single comparison's: the one-sided α
// quantile); the gain is reported, not tested (one record less moves a k-fold gain by chance).
InfluenceCheck checkInfluence(const Candidate *c, const std::vector<double> *sens, const std::vector<double> *baseSens,
                              const std::vector<double> &y, const std::vector<int> &fold, int folds, size_t count,
                              double zNeeded);

// One record named by a finding: its residual, the candidate's value there, its flags and the
// diagnostics in which it lies far from the other records.
struct CarryingRecord {
    std::string id;
    double residual = 0;
    std::string value;                                    // the candidate's value at the record (a number or a level)
    std::string flags;                                    // the pipeline's flags, ';'-separated ("" for radii)
    std::vector<std::pair<std::string, double>> outlying; // diagnostics far from the rest, farthest first
};

// A candidate significant over the family only through a few records: not added, the records
// named instead.
struct RecordFinding {
    std::string candidate, form;
    int round = 1;              // 1: the model's residual; k: after k − 1 effects
    double z = 0, zWithout = 0; // with every record, and without the records below
    double zFamily = 0;         // the family's critical z
    double zNeeded = 0;         // what it needed without them: a single comparison's
    double cvRmsAfter = 0, cvRmsAfterWithout = 0, gain = 0, gainWithout = 0;
    std::vector<CarryingRecord> records;
};

// The finding of a ranked candidate the check turned down (RankedCandidate::carried), on the
// round's records and residual.
RecordFinding recordFinding(const RankedCandidate &r, const Candidate *c, const std::vector<LoopRecord> &records,
                            const std::vector<double> &residual, int round, double zNeeded);

// "loopset-023 (residual -0.0120, diag_outer_coverage 0.625, flags blurred;centre_offset)".
std::string describe(const CarryingRecord &r, const std::string &candidate);

} // namespace icacam::host::loop
