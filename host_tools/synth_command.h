#pragma once
#include <string>
#include <vector>

namespace icacam::host {
int synthCommand(const std::vector<std::string> &args);
// The ICA width the paper's model gives for μ at n (bisection on the monotonic part).
double uForMu(double mu, double n);
} // namespace icacam::host
