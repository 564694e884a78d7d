#pragma once
// The FE snapshots the reduction's du/dr stands on (the generated reduction table and `icacam
// loop`): one mesh and one K out of data/fe/*.csv, chosen as the FE model's table chooses its
// base (fe_rows.h, chooseBase at 50 % reduction); E 210 GPa, D0 10, H0 15 mm. Rows of runs that
// stopped later (status failed) count for the snapshots they reached: those are converged
// states. Columns are read by name; added columns are ignored.
#include <string>
#include <vector>

namespace icacam::host::fe {

struct FeSnapshot {
    double n = 0, mu = 0, reduction = 0;
    double uMm = 0, riMm = 0, roMm = 0, rMaxMm = 0; // scaled to D0 = 10 mm
};

struct FeBaseData {
    std::string mesh; // "CAX4R h0.2 c0": element, size, corner
    double kMpa = 0;
    std::vector<FeSnapshot> rows;
};

// paths: one or more sweep CSVs (e.g. data/fe/sweep.csv and a newer sweep_*.csv); the base
// mesh and K are chosen over all of them together.
bool readFeBaseData(const std::vector<std::string> &paths, FeBaseData *out, std::string *error);

} // namespace icacam::host::fe
