#include "firmware/backends/backend_config.h"

#include <filesystem>

namespace icacam::fw {

std::string pathFromConfig(const Config &cfg, const std::string &path)
{
    if (path.empty() || path.front() == '/') return path;
    return (std::filesystem::path(cfg.baseDir) / path).lexically_normal().string();
}

std::string notBuiltIssue(const char *key, const std::string &value, const char *only)
{
    return std::string(key) + " = " + value + ": this icacam-fw is built with the " + only + " backend only";
}

} // namespace icacam::fw
