#pragma once
// The sweep on this machine: `jobs` ccx runs at a time, each case's result printed and
// gathered as it finishes.
#include "host_tools/fe/fe_executor.h"
#include "host_tools/fe/fe_runner.h"

namespace icacam::host::fe {

class LocalExecutor : public SweepExecutor {
public:
    LocalExecutor(const RunOptions &run, int jobs) : run_(run), jobs_(jobs) {}
    size_t solve(const std::vector<FeCase> &cases, const GatherFn &gather) override;

private:
    RunOptions run_;
    int jobs_;
};

} // namespace icacam::host::fe
