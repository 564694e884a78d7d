#include "vision/edge_profile.h"

#include <algorithm>
#include <cstdlib>

#include "vision/radial_profile.h"

namespace icacam::vision {

void profileDerivative(const uint16_t *s, int count, int32_t *d)
{
    if (count >= 5 && !anyOutsideFrame(s, count)) {
        // Every sample inside the frame (the usual profile): the same sums without the
        // per-sample checks, in a loop the compiler vectorises.
        d[0] = d[1] = d[count - 2] = d[count - 1] = 0;
        for (int i = 2; i + 2 < count; ++i)
            d[i] = int32_t(s[i + 2]) + 2 * int32_t(s[i + 1]) - 2 * int32_t(s[i - 1]) - int32_t(s[i - 2]);
        return;
    }
    for (int i = 0; i < count; ++i) {
        if (i < 2 || i + 2 >= count) {
            d[i] = 0;
            continue;
        }
        if (s[i - 2] == kOutsideFrame || s[i - 1] == kOutsideFrame || s[i + 1] == kOutsideFrame ||
            s[i + 2] == kOutsideFrame) {
            d[i] = 0;
            continue;
        }
        d[i] = int32_t(s[i + 2]) + 2 * int32_t(s[i + 1]) - 2 * int32_t(s[i - 1]) - int32_t(s[i - 2]);
    }
}

Q16_16 parabolaVertex(int32_t dm, int32_t d0, int32_t dp)
{
    const int64_t den = int64_t(dm) - 2 * int64_t(d0) + int64_t(dp);
    if (den >= 0) return Q16_16::fromRaw(0); // not a maximum: no refinement
    const int64_t num = (int64_t(dm) - int64_t(dp)) * 65536 / 2;
    int64_t off = num / den; // truncation towards zero: below 2^-16 sample
    if (off > 32768) off = 32768;
    if (off < -32768) off = -32768;
    return Q16_16::fromRaw(off);
}

EdgePeak innermostClearEdge(const int32_t *d, int count, int lo, int hi, int sign, int divisor)
{
    const EdgePeak strongest = sign ? strongestEdge(d, count, lo, hi, sign) : strongestEdgeEitherSign(d, count, lo, hi);
    if (!strongest.found) return strongest;
    for (int i = std::max(lo, 1); i <= std::min(hi, count - 2); ++i) {
        const int s = sign ? sign : d[i] > 0 ? 1 : -1;
        const int32_t v = s * d[i], vm = s * d[i - 1], vp = s * d[i + 1];
        // Of either sign, a neighbour of the other sign counts by its size.
        const bool peak = sign ? v >= vm && v >= vp : v >= std::abs(d[i - 1]) && v >= std::abs(d[i + 1]);
        if (divisor * v >= strongest.value && peak) return {Q16_16::fromInt(i) + parabolaVertex(vm, v, vp), v, true};
    }
    return strongest;
}

} // namespace icacam::vision
