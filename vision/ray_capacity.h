#pragma once
// How many rays the pipeline casts and how many samples each holds: the working memory's
// shape, shared by the analyzer that sizes it and the ring search that fills it.
#include <algorithm>

namespace icacam::vision {

inline constexpr int kCoarseRays = 64;
inline constexpr int kFineRays = 256;
inline constexpr int kMaxCoarseSamples = 1024;
inline constexpr int kMaxFineSamples = 640;
// Radial span of the coarse rays, in initial radii: from inside the widest ICA's outer edge
// to beyond the silhouette at 60 % reduction (R0·1.58·1.04 ≈ 1.65 R0).
inline constexpr double kCoarseStart = 0.88, kCoarseEnd = 1.72;

// Radial step of the coarse rays: 2 px is fine enough to name the edges (the fine stage
// locates them) and to find the silhouette to a quarter of a percent.
inline double coarseStep(double r0Px)
{
    const double span = (kCoarseEnd - kCoarseStart) * r0Px;
    return span / 2 > kMaxCoarseSamples ? span / kMaxCoarseSamples : 2.0;
}

// How many samples each coarse ray holds from kCoarseStart to kCoarseEnd initial radii.
inline int coarseCount(double r0Px)
{
    const double rA = kCoarseStart * r0Px, rB = kCoarseEnd * r0Px;
    return std::min(kMaxCoarseSamples, int((rB - rA) / coarseStep(r0Px)));
}

} // namespace icacam::vision
