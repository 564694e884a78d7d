#pragma once
// A length factor seen twice: a camera whose every length is off by s widens the ring by s
// (μ's residual shows it through dμ/du, against the reference method's scatter) and the
// barrel's outline by s as well, which the FE predicts from n, μ_ref and the height alone,
// nearly independently of μ. The outline is the sharper witness of the two: a group's R_max
// against the FE's R_max is known to a fraction of a per cent where μ's residual knows the
// factor to one or two. A grouping's factors are read from the outline relative to its
// typical group (loop_physics.cpp, factorsFromOutline), and μ's held-out error judges whether
// the scale is what moved the outline (not a camera's working distance, or a shadow taken
// for the outline: then applying the factors makes μ's error worse).
#include <map>
#include <string>
#include <vector>

#include "host_tools/loop/loop_analysis.h"

namespace icacam::host::loop {

// ln(R_max measured / FE R_max) of a record at its declared n, μ_ref and recorded reduction
// (else 50 %), D0 scaled; false where the record has no silhouette or the FE no data.
bool silhouetteLogRatio(const LoopRecord &r, double *y);

// The outline's log ratio per level of a grouping, on the records where `train` holds: the
// level's mean and its standard error from the scatter pooled over the levels (levels with
// fewer than 3 records with a silhouette left out), and the F test of the levels against one
// common mean, as a normal z (0 with fewer than two such levels).
struct OutlineLevels {
    std::map<std::string, double> mean, se;
    double z = 0;
};
OutlineLevels outlineLevels(const std::vector<LoopRecord> &usable, const Candidate &grouping,
                            const std::vector<bool> &train);

} // namespace icacam::host::loop
