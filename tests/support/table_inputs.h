#pragma once
// The CSVs a generated table names (e.g. fe_table::kBase, reduction_table::kFeSources: repository
// paths, space-separated) as paths in the source tree: the stale-table tests read the same files.
#include <sstream>
#include <string>
#include <vector>

namespace icacam::test {

inline std::vector<std::string> repositoryPaths(const char *spaceSeparated)
{
    std::vector<std::string> in;
    std::istringstream s(spaceSeparated);
    std::string word;
    while (s >> word) in.push_back(std::string(ICACAM_SOURCE_DIR) + "/" + word);
    return in;
}

} // namespace icacam::test
