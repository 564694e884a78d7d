#pragma once
// `icacam loop table`: writes vision/model/reduction_table.h from the FE sweep (data/fe/sweep.csv),
// so that the device can carry u to the model's 50 % reduction and check the radii without
// reading a CSV at run time. Columns are read by name; added columns are ignored.
#include <string>
#include <vector>

namespace icacam::host::loop {

// The table's text, exactly as committed (the test compares it byte for byte). csvs: the
// sweep files read; names: the same as the repository names them (written into the table as
// kFeSources, which the test and `icacam loop` read back). Empty and *error set when a sweep
// cannot be read or is too thin.
std::string reductionTableText(const std::vector<std::string> &csvs, const std::vector<std::string> &names,
                               std::string *error);

// `icacam loop table [--fe-sweep CSV]... [--out FILE]` (default: the repository's
// data/fe/sweep.csv; out: stdout).
int loopTableCommand(const std::vector<std::string> &args, const std::string &defaultSweep);

} // namespace icacam::host::loop
