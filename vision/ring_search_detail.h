#pragma once
// What the ring search's parts share (ring_search.cpp, ring_search_outline.cpp,
// ring_search_contact_edge.cpp, ring_search_original_face.cpp): the rays' and profiles' sizes,
// a profile's noise, two statistics of a derivative row, and the profile aligned on the
// contact edge. Private to the search: nothing outside vision/ includes it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "vision/radial_profile.h"
#include "vision/ray_capacity.h"
#include "vision/ring_search.h"

namespace icacam::vision::ring_search_detail {

constexpr int kRays = kFineRays; // the most fine rays a search casts
constexpr int kMaxFine = kMaxFineSamples;
constexpr int kMaxCoarse = kMaxCoarseSamples;
// The fine rays' sample spacing (pixels).
constexpr double kFineStepPx = 1.0;
// The blur (px²) the fine rays add to an edge before their derivative's peak locates it:
// bilinear sampling's (about 0.17) and the derivative kernel's (0.75).
constexpr double kLocatorBlurSq = 0.92;
// Seen obliquely, the contact edge's ramp is measured and its knee located on this many arcs
// of the ring apiece (16 or 32 fine rays each).
constexpr int kRampSectors = 8;
// A 3-grey-level step blurred to σ = 2 px gives a coarse derivative of about 1200.
constexpr int32_t kMinCoarseStrength = 1000;
// A faint outline is located on this many sectors of the coarse rays, each pooling its middle
// ray and the rays half a sector either side, and taken where this share of them shows it.
constexpr int kOutlineSectors = 16;
constexpr double kSectorOutlineCoverage = 0.5, kSectorOutlineSigmas = 3.0;
// A highlight line on the barrel rises this far (Q8 grey levels) above the levels either side;
// the barrel's outline beyond it is a step of at least this much.
constexpr double kMinLineRise = 4 * 256, kMinOutlineStep = 3 * 256;
// The original face's edge steps by at least this many times the face texture's σ.
constexpr double kTextureSigmas = 3.0;

// The robust σ (1.4826 × the median absolute value) of d[lo … hi].
inline double robustSigma(const int32_t *d, int lo, int hi)
{
    int32_t tmp[kMaxCoarse + kMaxFine];
    int n = 0;
    for (int i = lo; i <= hi; ++i) tmp[n++] = std::abs(d[i]);
    if (n == 0) return 0;
    std::nth_element(tmp, tmp + n / 2, tmp + n);
    return 1.4826 * tmp[n / 2];
}

// The noise of profileDerivative on a mean profile, from its second differences: a
// photograph's profile slopes over long stretches (the fixture's shadow, vignetting, a lit
// barrel), which the derivative's own spread would count as noise; the second difference
// sees only what changes from sample to sample. σ(s[j+1] − 2 s[j] + s[j−1]) = √6 σ, and the
// derivative's weights (1, 2, 2, 1) give √10 σ.
inline double derivativeNoise(const uint16_t *s, int count)
{
    int32_t tmp[kMaxCoarse];
    int n = 0;
    for (int j = 1; j + 1 < count; ++j)
        if (s[j - 1] != kOutsideFrame && s[j] != kOutsideFrame && s[j + 1] != kOutsideFrame)
            tmp[n++] = std::abs(int32_t(s[j + 1]) - 2 * int32_t(s[j]) + int32_t(s[j - 1]));
    if (n == 0) return 0;
    std::nth_element(tmp, tmp + n / 2, tmp + n);
    return 1.4826 * tmp[n / 2] * std::sqrt(10.0 / 6.0);
}

// Whether d[i] is a peak of |d| that keeps its sign across its neighbours.
inline bool isExtremum(const int32_t *d, int i)
{
    const int32_t a = std::abs(d[i]);
    return a > 0 && a >= std::abs(d[i - 1]) && a > std::abs(d[i + 1]) && (d[i] > 0) == (d[i - 1] >= 0) &&
           (d[i] > 0) == (d[i + 1] >= 0);
}

} // namespace icacam::vision::ring_search_detail

namespace icacam::vision {

// The profile across the ring, following the contact edge: sample K lies on it, K samples
// inside and M outside.
struct RingSearch::AlignedProfile {
    static constexpr int kSpan = ring_search_detail::kMaxCoarse;
    int K = 0, M = 10;
    // Only the first count() samples are written and read: nothing clears the rest.
    int32_t level[kSpan]; // mean grey level (0 where fewer than half the rays saw the frame)
    int32_t deriv[kSpan]; // its derivative, in the fine derivative rows' units
    int count() const { return K + M + 1; }
};

} // namespace icacam::vision
