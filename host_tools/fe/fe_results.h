#pragma once
// Readers for CalculiX result files: the .frd (ASCII) node coordinates and displacement
// blocks, and the .dat totals of *NODE PRINT (reaction forces).
#include <string>
#include <vector>

#include "host_tools/fe/fe_case.h"

namespace icacam::host::fe {

struct FrdStep {
    double time = 0;
    NodeXY disp;
};

struct FrdResults {
    NodeXY coords;
    std::vector<FrdStep> steps;
};

// Parses the ASCII .frd text; throws std::runtime_error on a malformed file.
FrdResults parseFrd(const std::string &text);
// The same for the .frd file at path (an absent file reads as empty text and throws as such).
FrdResults readFrd(const std::string &path);

struct ForcePoint {
    double time = 0;
    double fx = 0, fy = 0; // as printed (axisymmetric: per 2° segment)
};
std::vector<ForcePoint> parseDatTotals(const std::string &text);

} // namespace icacam::host::fe
