#pragma once
// Where a sweep's cases are solved: this machine's cores (fe_local_executor.h) or a Slurm
// cluster (fe_slurm_executor.h). The sweep (fe_sweep.h) chooses the cases and keeps the CSV;
// an executor only solves and hands back each case's rows, in the order cases finish.
#include <functional>
#include <string>
#include <vector>

#include "host_tools/fe/fe_case.h"

namespace icacam::host::fe {

// One solved case: its csvRows() (fe_runner.h), and its status and message as in the rows.
struct SolvedCase {
    FeCase c; // as planned (a retry with the fallback stick slope shows in the rows only)
    std::vector<std::string> rows;
};
using GatherFn = std::function<void(const SolvedCase &)>;

class SweepExecutor {
public:
    virtual ~SweepExecutor() = default;
    // Solves the cases, calling gather once per case that has rows (from one thread at a
    // time). Returns the number of cases left without rows (the solver never reported back:
    // a task killed by the cluster, a lost node); a case the solver failed on has rows.
    virtual size_t solve(const std::vector<FeCase> &cases, const GatherFn &gather) = 0;
};

} // namespace icacam::host::fe
