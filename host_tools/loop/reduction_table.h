#pragma once
// `icacam loop table`: writes vision/reduction_table.h from the FE sweep (data/fe/sweep.csv),
// so that the device can carry u to the model's 50 % reduction and check the radii without
// reading a CSV at run time. Columns are read by name; added columns are ignored.
#include <string>
#include <vector>

namespace icacam::host::loop {

// The table's text, exactly as committed (the test compares it byte for byte). Empty and
// *error set when the sweep cannot be read or is too thin.
std::string reductionTableText(const std::string &sweepCsv, const std::string &sweepName, std::string *error);

// `icacam loop table [--fe-sweep CSV] [--out FILE]` (default out: stdout).
int loopTableCommand(const std::vector<std::string> &args, const std::string &defaultSweep);

} // namespace icacam::host::loop
