#pragma once
// Helpers shared by the host tests: temporary folders, CSV reading, running a command.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "host_tools/manifest.h"

namespace icacam::test {

inline std::filesystem::path tempDir(const std::string &name)
{
    auto p = std::filesystem::temp_directory_path() / ("icacam-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

inline std::map<std::string, std::map<std::string, std::string>> readCsvById(const std::string &path)
{
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    host::Manifest m;
    std::string err;
    std::map<std::string, std::map<std::string, std::string>> out;
    if (!host::parseManifest(ss.str(), &m, &err)) return out;
    for (auto &r : m.rows) out[r.get("id")] = r.cells;
    return out;
}

inline std::string sharedData()
{
    return ICACAM_SHARED_DATA;
}

} // namespace icacam::test
