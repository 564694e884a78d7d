#pragma once
// The paper's form on our FE points (part of `icacam fe report`): per n a cubic μ(u) (Eq. 2,
// Table 1), each coefficient a cubic in n (Eq. 3), their error against the points, and a
// Fig. 4-like plot of the coefficients over n.
#include <filesystem>
#include <ostream>

#include "host_tools/fe/fe_rows.h"

namespace icacam::host::fe {

void writeTable1Form(std::ostream &md, const std::filesystem::path &svgPath, const PointGrid &pts);

} // namespace icacam::host::fe
