#pragma once
// The generated model's error against its FE data (part of `icacam fe report`): between the
// grid points (leave one out) and against each run it averages (each K of the factorial).
#include <ostream>
#include <vector>

#include "host_tools/fe/fe_rows.h"

namespace icacam::host::fe {

void writeLeaveOneOut(std::ostream &md, const std::vector<FeRow> &rows);
void writeRunResiduals(std::ostream &md, const std::vector<FeRow> &rows);

} // namespace icacam::host::fe
