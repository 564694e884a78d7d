#pragma once
// The upsetting force the FE base computes (the platen's reaction at each snapshot), per MPa of
// K: what a press's load cell reads for a rate-independent specimen of the paper's geometry,
// for the loop's rate sensitivity (host_tools/loop/loop_rate.h).
#include <map>
#include <string>
#include <vector>

namespace icacam::host::fe {

class UpsettingForce {
public:
    // The FE base's snapshots (chooseBase, one per reduction) from one or more sweep CSVs.
    bool load(const std::vector<std::string> &sweepCsvs, std::string *error);
    // Force in kN at (n, μ, reduction) for K (MPa, the flow curve's K at the reference rate)
    // and D0 (mm, geometric similarity: force ∝ D0² at the paper's slenderness): bilinear in
    // (n, μ) over the base grid, linear in the reduction between snapshots. False outside the
    // grid or the snapshots.
    bool at(double n, double mu, double reduction, double kMpa, double d0Mm, double *kN) const;
    double reductionMin() const { return grids_.empty() ? 0 : grids_.begin()->first; }
    double reductionMax() const { return grids_.empty() ? 0 : grids_.rbegin()->first; }

private:
    struct Grid {
        std::vector<double> n, mu;
        std::vector<double> perK; // kN per MPa, row-major in (n, μ); NaN where the base has no point
    };
    bool atGrid(const Grid &g, double n, double mu, double *v) const;
    std::map<double, Grid> grids_; // reduction → grid
};

} // namespace icacam::host::fe
