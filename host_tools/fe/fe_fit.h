#pragma once
// The FE model's generated table (friction/fe_model_table.h), part of `icacam fe tables`.
#include <string>
#include <vector>

#include "host_tools/fe/fe_rows.h"
#include "host_tools/fe/fe_table_sources.h"

namespace icacam::host::fe {

// u, R_i, R_o, R_max over [reduction 30–60 %][n][μ] from the runs of src.base (chosen among
// them as chooseBase does), and the K carry from the runs of src.kFamily (kCarry over base and
// family); files by their repository names, read under sourceDir ("" or a path ending in
// '/'). `reduction` is the model's own when none is given (must have base data). The header's
// text; summary: one line on what it holds. Throws when a file cannot be read or the base has
// no usable rows.
std::string feModelTableText(const TableSources &src, const std::string &sourceDir, double reduction,
                             std::string *summary);

} // namespace icacam::host::fe
