#pragma once
// The two setups `icacam fe` starts a case from. FeCase{} and RunOptions{} are the coarse
// setup of the first sweeps (CAX4R, uniform 0.2 mm, to 50 %: seconds a case), the defaults
// every committed sweep command in data/fe/ was written against. `--preset base` starts from
// the setup of the models' FE base instead (data/fe/README.md; friction/fe_model_table.h
// names the file), so a sweep with it adds cases of the base's kind under the base's labels.
#include "host_tools/fe/fe_case.h"
#include "host_tools/fe/fe_runner.h"

namespace icacam::host::fe {

inline FeCase baseSetupCase()
{
    FeCase c;
    c.element = "CAX8R"; // follows the fold-over at high μ where CAX4R diverges
    c.cornerMm = 0.05;   // the finest corner that covers the whole (n, μ) grid
    c.elemMm = 0.5;      // far field
    c.incMax = 0.02;
    c.reductionMax = 0.6; // snapshots to 60 %: the reduction carry's range
    c.stickSlope = 1e5;   // the converged stick slope (penalty study)
    c.trackStep = 0.01;   // output frames every 1 %: the tracked contact edge
    return c;
}

inline RunOptions baseSetupRun()
{
    RunOptions o;
    o.fallbackStickSlope = 0; // a case that stops is recorded as failed, not rerun softer
    return o;
}

} // namespace icacam::host::fe
