#pragma once
// `icacam fe outline-table`: the outline a pinhole camera sees of the upset specimen, as a
// ratio to R_max, over (n, μ, reduction, D0/W), from the FE's deformed sides
// (data/photobench/fe_profiles.csv) → friction/outline_table.h (friction/outline_ratio.h).
#include <string>
#include <vector>

namespace icacam::host {

// The header's text from the barrel profiles at sourceDir + profilesPath (named in it as
// profilesPath; sourceDir "" or ending in '/'). Throws when the profiles cannot be read.
std::string outlineTableText(const std::string &profilesPath, const std::string &sourceDir, std::string *summary);

int outlineTableCommand(const std::vector<std::string> &args);

} // namespace icacam::host
