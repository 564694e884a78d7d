#pragma once
// The model fit (generated C++ table for vision/) and the report against the paper.
#include <map>
#include <string>
#include <vector>

namespace icacam::host::fe {

struct FeRow {
    std::string caseId, status;
    std::string element = "CAX4R"; // column absent in the first sweeps: they were all CAX4R
    double cornerMm = 0;
    double stickSlope = 0, nu = 0.3;
    double kMpa = 0, n = 0, mu = 0, eMpa = 0, d0 = 0, h0 = 0, reductionMax = 0, reduction = 0, elem = 0;
    double ri = 0, ro = 0, roInterp = 0, rMax = 0, u = 0, uInterp = 0, force = 0, wallS = 0;
    double uTrack = -1; // tracked contact edge (runs with --track-step); -1: not tracked
};
std::vector<FeRow> readSweepCsv(const std::string &path);

// The mesh of a row as one comparable key ("CAX8R h0.5 c0.1"): rows of different meshes
// are never mixed in one model.
std::string meshKey(const FeRow &r);

// One (n, μ) point of the model's base data: the snapshot rows at one reduction of the
// paper's specimen (D0 10, H0 15 mm, E 210 GPa) on the most common mesh and K, averaged.
struct Point {
    double n = 0, mu = 0, u = 0, ri = 0, ro = 0, rMax = 0, force = 0, elem = 0;
    std::string mesh;
    int count = 0;
    int tracked = 0; // rows with the tracked contact edge (u is theirs)
    double kMin = 1e9, kMax = 0;
};
std::map<std::pair<double, double>, Point> basePoints(const std::vector<std::string> &in, double reduction);

int fitCommand(const std::vector<std::string> &in, const std::string &out, double reduction);
// Rows of the other files against the first (same K, n, μ, E, ν, D0, H0 and reduction,
// any mesh or solver setting): a markdown table of Δu and how many are within `bar`
// (relative) where the reference u > minU. For the mesh study and the independent model.
// tracked: compare u of the tracked contact edge (rows without it are skipped).
// acrossMaterial: match rows regardless of K and E, against the reference file's K 500 MPa,
// E 210 GPa rows (the independence checks).
int compareCommand(const std::vector<std::string> &in, const std::string &out, double minU, double bar,
                   bool tracked = false, bool acrossMaterial = false);
int reportCommand(const std::vector<std::string> &in, const std::string &outDir, double reduction);

} // namespace icacam::host::fe
