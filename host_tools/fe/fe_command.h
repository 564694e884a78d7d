#pragma once
#include <string>
#include <vector>

namespace icacam::host {
// `icacam fe run|sweep|fit|report`: our own μ model from CalculiX (docs/fe.md).
int feCommand(const std::vector<std::string> &args);
} // namespace icacam::host
