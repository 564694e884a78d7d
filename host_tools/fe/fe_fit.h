#pragma once
// The model fit (generated C++ table for vision/) and the report against the paper.
#include <string>
#include <vector>

namespace icacam::host::fe {

struct FeRow {
    std::string caseId, status;
    std::string element = "CAX4R"; // column absent in the first sweeps: they were all CAX4R
    double cornerMm = 0;
    double kMpa = 0, n = 0, mu = 0, eMpa = 0, d0 = 0, h0 = 0, reductionMax = 0, reduction = 0, elem = 0;
    double ri = 0, ro = 0, roInterp = 0, rMax = 0, u = 0, uInterp = 0, force = 0, wallS = 0;
};
std::vector<FeRow> readSweepCsv(const std::string &path);

// The mesh of a row as one comparable key ("CAX8R h0.5 c0.1"): rows of different meshes
// are never mixed in one model.
std::string meshKey(const FeRow &r);

int fitCommand(const std::vector<std::string> &in, const std::string &out, double reduction);
int reportCommand(const std::vector<std::string> &in, const std::string &outDir, double reduction);

} // namespace icacam::host::fe
