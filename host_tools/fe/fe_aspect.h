#pragma once
// The slenderness carry ("beyond the paper": H0/D0 1.0–2.0): how much wider the ICA
// of a specimen of another H0/D0 is than that of the paper's 10 x 15 mm one at the same n, μ
// and height reduction, from FE runs at other H0 (docs/fe.md). `icacam fe tables` writes it as
// friction/aspect_table.h for friction/aspect_corrected_model.h.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "host_tools/fe/fe_table_sources.h"

namespace icacam::host::fe {

// u(H0/D0) / u(1.5) at (H0/D0, n, reduction, μ), where both runs exist on the base mesh and
// K and u(1.5) > minU (a ratio of two small widths is noise). Key: (aspect, n, reduction, μ).
// R_max(H0/D0) / R_max(1.5) likewise, wherever both runs exist (the silhouette is resolved
// at any u): the scale and reduction check of a specimen of another slenderness.
struct AspectRatios {
    std::map<std::tuple<double, double, double, double>, double> ratio;
    std::map<std::tuple<double, double, double, double>, double> rMaxRatio;
    std::string mesh;
    bool tracked = false; // from the tracked contact edge (else the interpolated one)
};
AspectRatios aspectRatios(const std::vector<std::string> &in, double minU = 0.1);

// The header's text from src.aspect (repository names, read under sourceDir: "" or a path
// ending in '/'); summary: one line on what it holds. Throws without a usable ratio.
std::string aspectTableText(const TableSources &src, const std::string &sourceDir, std::string *summary);

} // namespace icacam::host::fe
