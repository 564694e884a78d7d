#pragma once
// `icacam fe compare`: one FE data set against another (mesh study, independent models,
// K/E independence checks).
#include <string>
#include <vector>

namespace icacam::host::fe {

// Rows of the other files against the first (same K, n, μ, E, ν, D0, H0 and reduction,
// any mesh or solver setting): a markdown table of Δu and how many are within `bar`
// (relative) where the reference u > minU. For the mesh study and the independent model.
// tracked: compare u of the tracked contact edge (rows without it are skipped).
// acrossMaterial: match rows regardless of K and E, against the reference file's K 500 MPa,
// E 210 GPa rows (the independence checks).
int compareCommand(const std::vector<std::string> &in, const std::string &out, double minU, double bar,
                   bool tracked = false, bool acrossMaterial = false);

} // namespace icacam::host::fe
