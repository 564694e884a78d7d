#pragma once
// The reduction carry's generated table (friction/reduction_table.h), part of `icacam fe
// tables`: the FE du/dr at 50 % from the base's snapshots, so that the device can carry u to
// the model's 50 % reduction without reading a CSV at run time. Columns are read by name;
// added columns are ignored.
#include <string>
#include <vector>

#include "host_tools/fe/fe_table_sources.h"

namespace icacam::host::fe {

// The table's text, exactly as committed (the test compares it byte for byte) from src.base
// (its repository name, read under sourceDir: "" or a path ending in '/'; written into the
// table as kFeSources, which `icacam loop` reads by default). Empty and *error set when the
// base cannot be read or is too thin.
std::string reductionTableText(const TableSources &src, const std::string &sourceDir, std::string *error);

} // namespace icacam::host::fe
