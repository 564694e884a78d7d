#pragma once
// Per-ray edge location on a sampled profile: a smoothed derivative and a sub-pixel peak.
#include <cstdint>

#include "vision/fixed_point.h"

namespace icacam::vision {

// d[i] = s[i+2] + 2 s[i+1] − 2 s[i−1] − s[i−2] (the derivative of a [1 2 1]-smoothed
// profile; 8 × the slope in Q8 grey levels per sample). d is 0 where the kernel would
// touch a kOutsideFrame sample or the ends of the profile.
void profileDerivative(const uint16_t *s, int count, int32_t *d);

// A located extremum of sign·d within [lo, hi].
struct EdgePeak {
    Q16_16 position; // sample index with sub-sample offset
    int32_t value;   // sign·d at the peak (positive when found)
    bool found;
};

// The largest sign·d over [lo, hi] (clamped to the profile), refined by a parabola through
// the peak and its neighbours; the offset is clamped to ±0.5 sample. Exact integer
// arithmetic up to the final division (test-pinned against the double formula).
// With `interior`, a peak on the window's end is refused (it is the flank of an edge
// outside the window, not an edge inside it).
// Sub-sample vertex of a parabola through (−1, dm), (0, d0), (+1, dp), in Q16.16.
Q16_16 parabolaVertex(int32_t dm, int32_t d0, int32_t dp);

template <typename T> EdgePeak strongestEdge(const T *d, int count, int lo, int hi, int sign, bool interior = false)
{
    EdgePeak p{Q16_16::fromRaw(0), 0, false};
    if (lo < 1) lo = 1;
    if (hi > count - 2) hi = count - 2;
    int best = -1;
    int32_t bestV = 0;
    for (int i = lo; i <= hi; ++i) {
        const int32_t v = sign * int32_t(d[i]);
        if (v > bestV) {
            bestV = v;
            best = i;
        }
    }
    if (best < 0) return p;
    const int32_t vm = sign * int32_t(d[best - 1]), vp = sign * int32_t(d[best + 1]);
    if (interior && (vm > bestV || vp > bestV || best == lo || best == hi)) return p;
    p.found = true;
    p.value = bestV;
    p.position = Q16_16::fromInt(best) + parabolaVertex(vm, bestV, vp);
    return p;
}

// The stronger of strongestEdge(+1) and strongestEdge(−1) (the falling one on a tie), in one
// pass over the window.
template <typename T> EdgePeak strongestEdgeEitherSign(const T *d, int count, int lo, int hi)
{
    if (lo < 1) lo = 1;
    if (hi > count - 2) hi = count - 2;
    int bestUp = -1, bestDown = -1;
    int32_t up = 0, down = 0;
    for (int i = lo; i <= hi; ++i) {
        const int32_t v = int32_t(d[i]);
        if (v > up) {
            up = v;
            bestUp = i;
        }
        if (-v > down) {
            down = -v;
            bestDown = i;
        }
    }
    const int sign = up > down ? 1 : -1;
    const int best = sign > 0 ? bestUp : bestDown;
    if (best < 0) return EdgePeak{Q16_16::fromRaw(0), 0, false};
    const int32_t bestV = sign > 0 ? up : down;
    const int32_t vm = sign * int32_t(d[best - 1]), vp = sign * int32_t(d[best + 1]);
    return EdgePeak{Q16_16::fromInt(best) + parabolaVertex(vm, bestV, vp), bestV, true};
}

// The innermost peak of sign·d in [lo, hi] (of |d|, either sign, where sign is 0) at least
// 1/divisor as strong as the strongest; the strongest where none comes first. Walking out
// from inside the end face, the first clear step is the nearer of two edges of one kind (the
// contact edge before the outline stepping the same way beyond it; the original face's edge
// before a stronger outline).
EdgePeak innermostClearEdge(const int32_t *d, int count, int lo, int hi, int sign, int divisor);

} // namespace icacam::vision
