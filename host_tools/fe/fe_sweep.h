#pragma once
// `icacam fe sweep`: the cases of a grid not yet in the CSV, solved by an executor (this
// machine or Slurm), their rows appended to the CSV as each case finishes.
#include <map>
#include <string>
#include <vector>

#include "host_tools/fe/fe_case.h"
#include "host_tools/fe/fe_runner.h"

namespace icacam::host::fe {

struct SweepOptions {
    std::string executor = "local";           // local | slurm
    int jobs = 1;                             // local: ccx runs at a time
    bool resubmitFailed = false;              // run the cases whose rows say failed/error again (only those)
    bool cancel = false;                      // slurm: scancel this sweep's queued tasks, nothing else
    std::string slurmConfig;                  // slurm: a key = value file (fe_slurm_options.h)
    std::map<std::string, std::string> slurm; // slurm: options given on the command line
};

// Takes the sweep's own options (executor, resubmit-failed, cancel, slurm-config and the
// Slurm keys); false for any other key.
bool setSweepOption(SweepOptions &o, const std::string &key, const std::string &value);

// Returns 0 when every case of the grid has rows in out (failed solves included; they are
// listed), 1 when some were left without (a lost Slurm task: the same command submits them again).
int runSweep(const std::vector<FeCase> &cases, const std::string &out, const RunOptions &run, const SweepOptions &o);

} // namespace icacam::host::fe
