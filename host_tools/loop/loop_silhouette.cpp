#include "host_tools/loop/loop_silhouette.h"

#include <cmath>

#include "friction/radii_consistency.h"
#include "host_tools/loop/loop_fit.h"

namespace icacam::host::loop {

namespace {

// Records with a silhouette a level needs before its mean is read.
constexpr int kMinOutlineRecords = 3;

} // namespace

bool silhouetteLogRatio(const LoopRecord &r, double *y)
{
    const auto it = r.diagnostics.find("diag_rmax_over_r0");
    double fe = 0;
    if (it == r.diagnostics.end() || !(it->second > 0) ||
        !friction::feRadiusAt(friction::FeRadius::Max, r.n, r.muRef, r.reduction >= 0 ? r.reduction : 0.5, &fe) ||
        !(fe > 0))
        return false;
    *y = std::log(it->second * 5.0 / fe); // R_max/R0 · 5 mm against the D0 = 10 FE
    return true;
}

OutlineLevels outlineLevels(const std::vector<LoopRecord> &usable, const Candidate &grouping,
                            const std::vector<bool> &train)
{
    std::map<std::string, std::vector<double>> ys;
    for (size_t i = 0; i < usable.size(); ++i) {
        double y = 0;
        if (train[i] && silhouetteLogRatio(usable[i], &y)) ys[grouping.levels[i]].push_back(y);
    }
    OutlineLevels out;
    double all = 0, sse1 = 0;
    size_t n = 0;
    int levels = 0;
    for (const auto &[level, v] : ys) {
        if (int(v.size()) < kMinOutlineRecords) continue;
        double m = 0;
        for (double y : v) m += y;
        m /= double(v.size());
        for (double y : v) sse1 += (y - m) * (y - m);
        out.mean[level] = m;
        all += m * double(v.size());
        n += v.size();
        ++levels;
    }
    if (levels < 2 || n <= size_t(levels)) return OutlineLevels{};
    all /= double(n);
    double sse0 = 0;
    for (const auto &[level, m] : out.mean)
        for (double y : ys[level]) sse0 += (y - all) * (y - all);
    const double pooled = std::sqrt(sse1 / double(n - size_t(levels)));
    for (const auto &[level, m] : out.mean) out.se[level] = pooled / std::sqrt(double(ys[level].size()));
    out.z = fit::nestedZ(sse0, 1, sse1, levels, n);
    return out;
}

} // namespace icacam::host::loop
