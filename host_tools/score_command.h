#pragma once
// `icacam score`: judge `icacam measure` results against a truth file, per condition
// (coverage_score.h, docs/uncertainty.md).
#include <string>
#include <vector>

namespace icacam::host {

// Returns the process exit code; throws std::runtime_error with a message for the user.
int scoreCommand(const std::vector<std::string> &args);

} // namespace icacam::host
