#pragma once
#include <string>
#include <vector>

namespace icacam::host {
int measureCommand(const std::vector<std::string> &args);
} // namespace icacam::host
