#pragma once
// The linear fits the ranking scores a candidate with (loop_analysis.cpp), shared with the
// influence check (loop_influence.h), which repeats them on the records a few leave.
#include <cstddef>
#include <vector>

#include "host_tools/loop/loop_analysis.h"

namespace icacam::host::loop::fit {

// x with P(Z > x) = p for a standard normal Z.
double normalUpperQuantile(double p);

// Nested-model F test of an in-sample fit (sse1, p1 parameters) against its baseline (sse0,
// p0) on n records, as the normal z of its p-value.
double nestedZ(double sse0, int p0, double sse1, int p1, size_t n);

// Held-out errors of the residual y after the candidate's linear model (nullptr: the baseline)
// fitted on the other folds; sens: the form's sensitivity (nullptr: the form `mu`).
std::vector<double> cvErrors(const Candidate *c, const std::vector<double> &y, const std::vector<int> &fold, int folds,
                             const std::vector<double> *sens = nullptr);

// In-sample sum of squares and parameter count of the same model fitted on every record.
double inSample(const Candidate *c, const std::vector<double> &y, const std::vector<int> &fold,
                const std::vector<double> *sens, int *params, bool commonSlope = false);

} // namespace icacam::host::loop::fit
