#pragma once
#include <string>
#include <vector>

namespace icacam::host {
int synthCommand(const std::vector<std::string> &args);
} // namespace icacam::host
