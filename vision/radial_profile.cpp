#include "vision/radial_profile.h"

#include <cmath>
#include <cstring>
#include <numbers>
#include <type_traits>

#include "vision/angle_table.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace icacam::vision {

namespace {

#if defined(__SSE2__)
// Four samples at a time, n a multiple of 4, for a pixel step of 1: the scalar loop's
// integers, not an approximation of them. x, y: the first sample's position (Q16.16, the
// 1/256 px rounding folded in), all positions below 2^31; sx, sy: the step (mod 2^32).
// stride below 2^15, so that row·stride + column is one 16-bit multiply-add per lane.
void sampleFour(const uint8_t *base, int32_t stride, uint32_t x, uint32_t y, uint32_t sx, uint32_t sy, int n,
                uint16_t *out)
{
    __m128i vx = _mm_setr_epi32(int32_t(x), int32_t(x + sx), int32_t(x + 2 * sx), int32_t(x + 3 * sx));
    __m128i vy = _mm_setr_epi32(int32_t(y), int32_t(y + sy), int32_t(y + 2 * sy), int32_t(y + 3 * sy));
    const __m128i stepX = _mm_set1_epi32(int32_t(4 * sx)), stepY = _mm_set1_epi32(int32_t(4 * sy));
    const __m128i byte = _mm_set1_epi32(255), high = _mm_set1_epi32(int32_t(0xFFFF0000u));
    const __m128i rowCol = _mm_set1_epi32(stride | (1 << 16)); // words (stride, 1)
    const __m128i full = _mm_set1_epi32(256), half = _mm_set1_epi32(128), bias = _mm_set1_epi32(32768);
    const __m128i flip = _mm_set1_epi16(int16_t(0x8000)), zero = _mm_setzero_si128();
    alignas(16) int32_t at[4];
    auto pair = [](const uint8_t *p) { // p[0] in the low byte, p[1] in the high one (x86)
        uint16_t two;
        std::memcpy(&two, p, sizeof two);
        return int(two);
    };
    for (int i = 0; i < n; i += 4) {
        const __m128i fx = _mm_and_si128(_mm_srli_epi32(vx, 8), byte);
        const __m128i fy = _mm_and_si128(_mm_srli_epi32(vy, 8), byte);
        // Row in the low word, column in the high word: one multiply-add gives the offset.
        const __m128i rc = _mm_or_si128(_mm_srli_epi32(vy, 16), _mm_and_si128(vx, high));
        _mm_store_si128(reinterpret_cast<__m128i *>(at), _mm_madd_epi16(rc, rowCol));
        vx = _mm_add_epi32(vx, stepX);
        vy = _mm_add_epi32(vy, stepY);
        // Words: (a b) and (c d) of each sample, the footprint's top and bottom pairs.
        __m128i px = zero;
        px = _mm_insert_epi16(px, pair(base + at[0]), 0);
        px = _mm_insert_epi16(px, pair(base + at[0] + stride), 1);
        px = _mm_insert_epi16(px, pair(base + at[1]), 2);
        px = _mm_insert_epi16(px, pair(base + at[1] + stride), 3);
        px = _mm_insert_epi16(px, pair(base + at[2]), 4);
        px = _mm_insert_epi16(px, pair(base + at[2] + stride), 5);
        px = _mm_insert_epi16(px, pair(base + at[3]), 6);
        px = _mm_insert_epi16(px, pair(base + at[3] + stride), 7);
        // Horizontal blends a(256 − fx) + b·fx: (top, bottom) of samples 0, 1 and of 2, 3.
        const __m128i wx = _mm_or_si128(_mm_sub_epi32(full, fx), _mm_slli_epi32(fx, 16));
        const __m128i v01 = _mm_madd_epi16(_mm_unpacklo_epi8(px, zero), _mm_unpacklo_epi32(wx, wx));
        const __m128i v23 = _mm_madd_epi16(_mm_unpackhi_epi8(px, zero), _mm_unpackhi_epi32(wx, wx));
        // The vertical blend top(256 − fy) + bottom·fy of values up to 65280, taken as
        // 256·(high bytes' blend) + (low bytes' blend) so that every factor fits 16 bits.
        const __m128i wy = _mm_or_si128(_mm_sub_epi32(full, fy), _mm_slli_epi32(fy, 16));
        const __m128i hi = _mm_madd_epi16(_mm_packs_epi32(_mm_srli_epi32(v01, 8), _mm_srli_epi32(v23, 8)), wy);
        const __m128i lo = _mm_madd_epi16(_mm_packs_epi32(_mm_and_si128(v01, byte), _mm_and_si128(v23, byte)), wy);
        const __m128i q8 = _mm_srli_epi32(_mm_add_epi32(_mm_add_epi32(_mm_slli_epi32(hi, 8), lo), half), 8);
        // 0 … 65280 to unsigned words (a signed pack of the value − 32768, sign bit flipped).
        const __m128i words = _mm_xor_si128(_mm_packs_epi32(_mm_sub_epi32(q8, bias), zero), flip);
        _mm_storel_epi64(reinterpret_cast<__m128i *>(out + i), words);
    }
}
#endif

} // namespace

uint16_t sampleBilinear(const LumaView &v, Q16_16 x, Q16_16 y)
{
    // Round the position to 1/256 px first: weights are 8-bit.
    const int32_t xq = (x.raw() + 128) >> 8;
    const int32_t yq = (y.raw() + 128) >> 8;
    const int32_t xi = xq >> 8, yi = yq >> 8;
    if (xi < 0 || yi < 0 || xi + 1 >= v.width || yi + 1 >= v.height) return kOutsideFrame;
    const uint32_t fx = uint32_t(xq & 255), fy = uint32_t(yq & 255);
    const uint8_t *p = v.data + size_t(yi) * size_t(v.stride) + size_t(xi) * size_t(v.pixelStep);
    const uint8_t *q = p + v.stride;
    const uint32_t top = p[0] * (256 - fx) + p[v.pixelStep] * fx; // Q8, 0 … 65280
    const uint32_t bot = q[0] * (256 - fx) + q[v.pixelStep] * fx;
    return uint16_t((top * (256 - fy) + bot * fy + 128) >> 8);
}

int sampleRay(const LumaView &v, const RaySpec &ray, int count, uint16_t *out)
{
    // Positions advance by a constant Q16.16 increment; the accumulated rounding over
    // 1024 steps stays below 1024 × 2^-16 px ≈ 0.016 px.
    const Q16_16 dx = ray.step.mul(ray.cosT), dy = ray.step.mul(ray.sinT);
    const Q16_16 x0 = ray.cx + ray.r0.mul(ray.cosT), y0 = ray.cy + ray.r0.mul(ray.sinT);
    if (count <= 0) return 0;
    const int64_t xEnd = int64_t(x0.raw()) + int64_t(dx.raw()) * (count - 1);
    const int64_t yEnd = int64_t(y0.raw()) + int64_t(dy.raw()) * (count - 1);
    const int64_t limX = int64_t(v.width - 2) << 16, limY = int64_t(v.height - 2) << 16;
    const bool allInside = x0.raw() >= 0 && y0.raw() >= 0 && xEnd >= 0 && yEnd >= 0 && x0.raw() < limX &&
                           y0.raw() < limY && xEnd < limX && yEnd < limY;
    if (!allInside) { // slow path: per-sample checks (the ray leaves the frame)
        Q16_16 x = x0, y = y0;
        int inside = 0;
        for (int i = 0; i < count; ++i) {
            out[i] = sampleBilinear(v, x, y);
            inside += out[i] != kOutsideFrame;
            x = x + dx;
            y = y + dy;
        }
        return inside;
    }
    // Fast path: the segment is inside (a convex frame contains it once both ends are),
    // so no bounds checks; same arithmetic as sampleBilinear (test-pinned equal).
    // Positions stay non-negative on this path, so they run as unsigned 64-bit values (no
    // sign extension per sample); a negative step wraps modulo 2^64 to the same sums.
    uint64_t x = uint64_t(int64_t(x0.raw())), y = uint64_t(int64_t(y0.raw()));
    const uint64_t sx = uint64_t(int64_t(dx.raw())), sy = uint64_t(int64_t(dy.raw()));
    const uint8_t *base = v.data;
    const size_t stride = size_t(v.stride), step = size_t(v.pixelStep);
    // Rounding to 1/256 px is folded into the start position (+128 in Q16.16).
    x += 128;
    y += 128;
    const int total = count;
    auto loop = [&](auto pixelStep) {
        for (int i = 0; i < count; ++i, x += sx, y += sy) {
            const int32_t fx = int32_t((x >> 8) & 255), fy = int32_t((y >> 8) & 255);
            const uint8_t *p = base + (y >> 16) * stride + (x >> 16) * pixelStep;
            const uint8_t *q = p + stride;
            // a(256 − f) + b·f = 256a + f(b − a): the same integers with one multiply
            // fewer per blend (the identity is exact, so the result is bit-identical).
            const int32_t top = (int32_t(p[0]) << 8) + (int32_t(p[pixelStep]) - int32_t(p[0])) * fx;
            const int32_t bot = (int32_t(q[0]) << 8) + (int32_t(q[pixelStep]) - int32_t(q[0])) * fx;
            out[i] = uint16_t(((top << 8) + (bot - top) * fy + 128) >> 8);
        }
    };
    // A compile-time pixel step of 1 (grey, NV12, YUV420) saves a multiply per sample.
    if (step == 1) {
#if defined(__SSE2__)
        // Positions below 2^31 (a frame under 2^15 px a side) and rows under 2^15 bytes.
        if (v.width < 32768 && v.height < 32768 && stride < 32768 && count >= 4) {
            const int n4 = count & ~3;
            sampleFour(base, int32_t(stride), uint32_t(x), uint32_t(y), uint32_t(sx), uint32_t(sy), n4, out);
            x += sx * uint64_t(n4);
            y += sy * uint64_t(n4);
            out += n4;
            count -= n4;
        }
#endif
        loop(std::integral_constant<size_t, 1>{});
    } else
        loop(step);
    return total;
}

void rayDirection(int i, int n, Q2_14 *cosT, Q2_14 *sinT)
{
    const AngleTable &a = angleTable();
    if (n > 0 && AngleTable::kSize % n == 0 && i >= 0 && i < n) {
        const int j = i * (AngleTable::kSize / n);
        *cosT = a.cosQ[j];
        *sinT = a.sinQ[j];
        return;
    }
    const double t = 2.0 * std::numbers::pi * double(i) / double(n);
    *cosT = Q2_14::fromDouble(std::cos(t));
    *sinT = Q2_14::fromDouble(std::sin(t));
}

} // namespace icacam::vision
