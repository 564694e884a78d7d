#include "vision/edge_profile.h"

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

} // namespace icacam::vision
