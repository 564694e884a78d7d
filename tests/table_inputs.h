#pragma once
// The CSVs a generated table was made from, as its provenance names them ("icacam fe fit
// --in A --in B"), as paths in the source tree: the stale-table tests read the same files.
#include <sstream>
#include <string>
#include <vector>

namespace icacam::test {

inline std::vector<std::string> provenanceInputs(const char *provenance)
{
    std::vector<std::string> in;
    std::istringstream s(provenance);
    std::string word;
    while (s >> word)
        if (word == "--in" && s >> word) in.push_back(std::string(ICACAM_SOURCE_DIR) + "/" + word);
    return in;
}

// The same for a space-separated list of repository paths (e.g. reduction_table::kFeSources).
inline std::vector<std::string> repositoryPaths(const char *spaceSeparated)
{
    std::vector<std::string> in;
    std::istringstream s(spaceSeparated);
    std::string word;
    while (s >> word) in.push_back(std::string(ICACAM_SOURCE_DIR) + "/" + word);
    return in;
}

} // namespace icacam::test
