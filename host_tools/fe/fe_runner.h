#pragma once
// Running one case through ccx and collecting its results.
#include <string>
#include <vector>

#include "host_tools/fe/fe_case.h"
#include "host_tools/fe/fe_results.h"

namespace icacam::host::fe {

struct RunOptions {
    std::string workDir = "/tmp/icacam-fe";
    std::string ccx = "ccx";
    int timeoutS = 3600;
    bool keep = true; // keep the work files (deck, .frd, .dat, log)
    // When ccx stops early (too many cutbacks: the folding corner with a stiff stick
    // slope), the case is rerun with this stick slope; 0 = no retry. The row records it.
    double fallbackStickSlope = 1e3;
    // Post-process the results already in the work directory instead of running ccx again,
    // when they were made from the same deck (new post-processing, no new FE solution).
    bool reuse = false;
    // With reuse: a case without such results is left out instead of run (a sweep then only
    // re-post-processes what was solved).
    bool reuseOnly = false;
};

struct RunResult {
    std::string status; // ok | failed (ccx stopped before the last snapshot) | error
    std::string message;
    double wallS = 0;
    std::vector<Radii> radii;      // one per snapshot reached
    std::vector<ForcePoint> force; // total force in kN over the whole 360°, per snapshot
    std::string dir;
};

// The snapshot reductions of a case: every 0.05 and the requested ones, up to reductionMax.
std::vector<double> snapshotReductions(const FeCase &c);

// Runs c (retrying with the fallback stick slope, which is then written into c).
RunResult runCase(FeCase &c, const RunOptions &o);

// True when the work directory holds results of c's deck that `reuse` would post-process.
bool hasReusableResults(const FeCase &c, const RunOptions &o);

// The result on stdout: status, wall time, message and one line per snapshot.
void printRunResult(const FeCase &c, const RunResult &r);

// The CSV header and rows of a result (one row per snapshot).
std::string csvHeader();
std::vector<std::string> csvRows(const FeCase &c, const RunResult &r);

} // namespace icacam::host::fe
