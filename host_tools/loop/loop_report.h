#pragma once
// The report folder of `icacam loop` (docs/loop.md, "The report"): ranking.csv, records.csv,
// physical.csv, the plots and report.md.
#include <string>
#include <vector>

#include "friction/friction_model.h"
#include "host_tools/loop/loop_analysis.h"
#include "host_tools/loop/loop_command.h"

namespace icacam::host::loop {

// The usable records as the loop analysed them: the residual μ_model − μ_ref with μ's
// sensitivities (dμ/du · u, dμ/du), the candidates, the folds, and μ with u carried to 50 %
// where the reduction was corrected physically.
struct ResidualSet {
    std::vector<LoopRecord> usable;
    std::vector<std::string> skipped; // "id: why"
    std::vector<double> residual, scaleSens, uSens;
    std::vector<Candidate> candidates;
    std::vector<int> fold;
    int folds = 0;
    std::vector<double> muPhysical; // NaN unless the reduction was carried (s.physical)
    int slopeCases = 0;             // FE cases of the du/dr surface, where it was loaded
};

// What the report says about where it ran: the source of the records, the model, the options
// and the FE sweeps of the reduction's du/dr.
struct ReportContext {
    std::string dir;
    std::string source; // the report's first words about where the records come from
    std::string modelName;
    const friction::FrictionModel *model = nullptr;
    RankingOptions options;
    std::vector<std::string> feSweeps;
};

void writeLoopReport(const ReportContext &context, const ResidualSet &set, const LoopSummary &s);

} // namespace icacam::host::loop
