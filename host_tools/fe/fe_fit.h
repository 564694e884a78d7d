#pragma once
// `icacam fe fit`: the generated model table (vision/model/fe_model_table.h) from the FE base data.
#include <string>
#include <vector>

#include "fe_rows.h"

namespace icacam::host::fe {

// Tables of u, R_i, R_o, R_max over [reduction 30–60 %][n][μ] from the base points of `in`;
// `reduction` is the model's own when none is given (must have base data).
int fitCommand(const std::vector<std::string> &in, const std::string &out, double reduction);

} // namespace icacam::host::fe
