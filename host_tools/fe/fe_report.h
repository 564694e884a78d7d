#pragma once
// `icacam fe report`: our FE against the paper (Table 1, Eq. 2/3, Fig. 3 and 4 alike).
#include <string>
#include <vector>

namespace icacam::host::fe {

// Writes outDir/comparison.md, mu_vs_u.svg and coefficients_vs_n.svg from the base points
// of `in` at `reduction`.
int reportCommand(const std::vector<std::string> &in, const std::string &outDir, double reduction);

} // namespace icacam::host::fe
