#pragma once
// A scale that drifts along a recorded sequence or date (docs/loop-method.md, "A drift"):
// every length a record's image gives is off by a factor that moves linearly with the
// record's place in the run, s(x) = a + b·(x − x̄), so μ = model(u/s(x), n). The camera moved
// or warmed a little more with every specimen; the fix is a recalibration, and a check of
// the scale along the run.
#include <cmath>
#include <string>
#include <vector>

#include "friction/friction_model.h"
#include "host_tools/loop/loop_analysis.h"

namespace icacam::host::loop {

// A recorded condition that orders the records in time (sequence, date, time, run, …): its
// physical form is a drift of the scale along it.
bool ordersInTime(const std::string &name);

struct DriftFit {
    double xMean = 0, xMin = 0, xMax = 0;
    double level = 1, slope = 0;           // a and b of s(x) = a + b·(x − x̄)
    double levelSigma = 0, slopeSigma = 0; // standard uncertainties (1 σ, pooled scatter)
    double scatter = 0;                    // RMS of μ − μ_ref after the fit (per degree of freedom)
    double startFactor = 1, endFactor = 1; // s at the first and the last recorded x
    std::vector<double> muAfter;           // μ per record with the fit on every record
    std::vector<double> cvErrors;          // held-out μ − μ_ref, each fold fitted on the others
    bool drifts() const { return std::fabs(slope) > 2 * slopeSigma; }
};

// Least squares of model(u/s(x), n) − μ_ref over the records (Gauss–Newton), and per fold.
DriftFit fitDrift(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, const Candidate &x,
                  const std::vector<int> &fold, int folds);

// The drift's form for the ranking, against one scale for every record.
FittedForm driftForm(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, const Candidate &x,
                     const std::vector<int> &fold, int folds);

// Fits the drift on the records where `train` holds and divides every record's u by s(x).
void applyDrift(const friction::FrictionModel &model, std::vector<LoopRecord> *records, const Candidate &x,
                const std::vector<bool> &train);

} // namespace icacam::host::loop
