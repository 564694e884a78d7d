#pragma once
// The rows of `icacam fe sweep` CSVs (data/fe/*.csv) and the base data chosen from them: one
// reader for `fe fit`, `fe report`, `fe compare`, `fe aspect` and the loop's reduction table.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace icacam::host::fe {

struct FeRow {
    std::string caseId, status;
    std::string message;                             // the runner's note: why ccx stopped, a broken contact zone, …
    std::string element = "CAX4R";                   // column absent in the first sweeps: they were all CAX4R
    std::string contact = "node-to-surface penalty"; // as the CSV's contact column says
    double cornerMm = 0;
    double contactSlope = 0, stickSlope = 0, nu = 0.3; // slopes in N/mm³; 0: column absent
    double kMpa = 0, n = 0, mu = 0, eMpa = 0, d0 = 0, h0 = 0, reductionMax = 0, reduction = 0, elem = 0;
    double ri = 0, ro = 0, roInterp = 0, rMax = 0, u = 0, uInterp = 0, force = 0, wallS = 0;
    double uTrack = -1; // tracked contact edge (runs with --track-step); -1: not tracked
    // u of the contact edge the models use: tracked where the run has it, else interpolated.
    double uBest() const { return uTrack >= 0 ? uTrack : uInterp; }
};
// Columns by name; columns added later may be absent (defaults above). Throws on a missing
// file or a missing required column.
std::vector<FeRow> readSweepCsv(const std::string &path);
std::vector<FeRow> readSweepCsvs(const std::vector<std::string> &paths);

// The mesh of a row as one comparable key ("CAX8R h0.5 c0.1", "… s2s" with surface-to-surface
// contact): rows of different meshes or contact discretisations are never mixed in one model.
std::string meshKey(const FeRow &r);

// A converged snapshot at this reduction. A run that stopped later (status failed, e.g. at
// 57 % of a run to 60 %) still reached it: its snapshots are converged states (the runner
// keeps only snapshot times, never the diverged last block).
bool reachedSnapshot(const FeRow &r, double reduction);

// The paper's specimen and material: D0 10, H0 15 mm, E 210 GPa.
bool isPaperSpecimen(const FeRow &r);

// The base of the models: among the paper-specimen snapshots at `reduction`, the finest mesh
// that covers the whole (n, μ) grid at one K, with the stiffest regularisation (stick slope,
// then contact penalty, per K) that covers it there (ties, or nothing complete: the most
// rows), then the most common K in that family. Other meshes and regularisations — coarser
// complete ones, the mesh study's finer points, the penalty studies, the independent models —
// are checks; none is mixed into the base. Other K join the base — averaged, as the paper's
// fit runs through all its K — only where they cover every (n, μ) of that K with the same
// slopes per K (the factorial, docs/fe.md); runs with other slopes per K (the absolute-penalty
// runs) or partial grids stay checks.
struct BaseChoice {
    std::string mesh;
    double contactPerK = 0, stickPerK = 0; // the base's slopes, N/mm³ per MPa of K
    double kMpa = 0;                       // the most common K (ties: the lowest)
    std::vector<double> kAveraged;         // every K of the base, kMpa included
    // Every K of a family (one mesh, one set of slopes per K) that covers the base grid both
    // at that K and at the base's K — the averaged ones and the factorial that checked
    // K-independence: the K range the model answers for.
    std::vector<double> kCovered;
    bool found = false;
    bool hasK(double k) const;
    bool sameRegularisation(const FeRow &r) const; // the row's slopes per K are the base's
    // The row is one of the base's snapshots at `reduction` (what basePoints averages).
    bool includes(const FeRow &r, double reduction) const;
};
BaseChoice chooseBase(const std::vector<FeRow> &rows, double reduction);

// One (n, μ) point of the model's base data at one reduction: the base rows, averaged.
struct Point {
    double n = 0, mu = 0, u = 0, ri = 0, ro = 0, rMax = 0, force = 0, elem = 0;
    std::string mesh;
    int count = 0;
    int tracked = 0; // rows with the tracked contact edge (u is theirs)
    double kMin = 1e9, kMax = 0;
};
using PointGrid = std::map<std::pair<double, double>, Point>; // (n, μ) → point
PointGrid basePoints(const std::vector<std::string> &in, double reduction);
PointGrid basePoints(const std::vector<FeRow> &rows, double reduction);
// The same with the base already chosen (chooseBase(rows, reduction)).
PointGrid basePoints(const std::vector<FeRow> &rows, double reduction, const BaseChoice &base);

// How u and the radii move with K where the base has one K: the runs of one family (one mesh,
// one set of slopes per K) that cover the base's grid at several K — the factorial — as
// differences from that family's own value at the base's K (the mean over the base's averaged
// K). Differences, not the family's values: the family may be a coarser mesh or another
// regularisation, and what it says reliably is how u changes with K (elasticity: the elastic
// strain K/E at yield moves the fold-over's onset), not u itself (docs/fe.md, the factorial).
// Chosen as the family with the most such K, then the finest mesh, then the stiffest stick.
struct KCarry {
    std::string mesh; // the carry family's mesh (meshKey)
    double contactPerK = 0, stickPerK = 0;
    std::vector<double> k; // every K of the carry, the base's among them; rising
    // K → (n, μ) → (u, R_i, R_o, R_max) at K minus at the base's K; force unused.
    std::map<double, PointGrid> delta;
    bool found = false; // at least two K
};
KCarry kCarry(const std::vector<FeRow> &rows, double reduction, const BaseChoice &base);

} // namespace icacam::host::fe
