#pragma once
// The batch script of one sweep submission: array task i runs case i with `icacam fe run`
// and moves its rows into results/<case label>.csv when they are complete.
#include <string>
#include <vector>

#include "host_tools/fe/fe_case.h"
#include "host_tools/fe/fe_runner.h"

namespace icacam::host::fe {

// `--key value` options of `icacam fe run` that make exactly this case (the numbers written
// so they read back to the same double).
std::vector<std::string> caseOptions(const FeCase &c);
// The same for the run options that reach a case's rows (solver, time-out, fallback, reuse).
std::vector<std::string> runOptionArgs(const RunOptions &o);

struct JobScript {
    std::string icacam;        // the program on the nodes
    std::string setup;         // a shell line before the case (module load …); may be empty
    std::string resultsDir;    // absolute, on the shared filesystem
    std::vector<FeCase> cases; // task i solves cases[i]
    RunOptions run;
};
std::string jobScriptText(const JobScript &s);

// The file that holds a case's rows once its task has finished.
std::string resultFile(const std::string &resultsDir, const FeCase &c);

} // namespace icacam::host::fe
