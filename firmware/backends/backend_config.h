#pragma once
// What the backend factories (one per seam, in this folder) share: paths in the config, and
// the words for a backend this build does not carry. The factories are the only code that
// knows which backends are compiled in (ICACAM_HAVE_<BACKEND>, set by firmware/CMakeLists.txt).
#include <string>

#include "firmware/config.h"

namespace icacam::fw {

// A path as the config gives it: relative to the config file's folder (Config::baseDir)
// unless absolute; "" stays "".
std::string pathFromConfig(const Config &cfg, const std::string &path);

// The config mistake of naming a backend this build does not carry: "KEY = VALUE: this
// icacam-fw is built with the ONLY backend only".
std::string notBuiltIssue(const char *key, const std::string &value, const char *only);

} // namespace icacam::fw
