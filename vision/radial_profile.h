#pragma once
// Sampling the frame along rays from a centre: the only stage that reads pixels besides
// the coarse locator, and it reads only the pixels under the rays.
#include <cstdint>

#include "vision/fixed_point.h"
#include "vision/luma_view.h"

namespace icacam::vision {

// Profile samples are luma in Q24.8 stored in 16 bits (0 … 65280); this marks a sample
// whose bilinear footprint is not inside the frame.
constexpr uint16_t kOutsideFrame = 0xFFFF;
constexpr int32_t kFullScaleQ8 = 255 * 256;

// Whether any of s[0 … count) is kOutsideFrame: only that value plus one carries into bit
// 16, so an OR of the samples plus one tells (a loop the compiler vectorises; a per-sample
// comparison into a bool it does not).
inline bool anyOutsideFrame(const uint16_t *s, int count)
{
    static_assert(kOutsideFrame == 0xFFFF, "the carry test needs the largest 16-bit value");
    uint32_t any = 0;
    for (int j = 0; j < count; ++j) any |= uint32_t(s[j]) + 1;
    return (any >> 16) != 0;
}

// Adds one ray's samples to per-sample sums over rays. A ray inside the frame throughout
// adds to every sample (a loop the compiler vectorises) and is counted once, in *whole, for
// all of them; one that leaves it adds only its samples inside, each counted in seen[j].
// A sample's ray count is then seen[j] + *whole.
inline void addRaySamples(const uint16_t *row, int count, bool insideThroughout, uint32_t *sum, uint32_t *seen,
                          uint32_t *whole)
{
    if (insideThroughout) {
        for (int j = 0; j < count; ++j) sum[j] += row[j];
        ++*whole;
        return;
    }
    for (int j = 0; j < count; ++j)
        if (row[j] != kOutsideFrame) sum[j] += row[j], ++seen[j];
}

struct RaySpec {
    Q16_16 cx, cy;    // centre in pixels
    Q2_14 cosT, sinT; // direction
    Q16_16 r0;        // radius of the first sample
    Q16_16 step;      // radial step between samples
};

// Bilinear sample of the luma at a Q16.16 position; kOutsideFrame if the 2×2 footprint
// leaves the frame. Weights are quantised to 1/256 px, so the result differs from an
// exact bilinear interpolation by at most 0.5/256 px × the local gradient (test-pinned).
uint16_t sampleBilinear(const LumaView &v, Q16_16 x, Q16_16 y);

// Fills `count` samples along the ray; returns how many lie inside the frame.
int sampleRay(const LumaView &v, const RaySpec &ray, int count, uint16_t *out);

// Unit vector for ray i of n, evenly spaced from angle 0, in Q2.14 (exact table-free
// rounding of cos/sin; computed in double once per ray, not per pixel).
void rayDirection(int i, int n, Q2_14 *cosT, Q2_14 *sinT);

} // namespace icacam::vision
