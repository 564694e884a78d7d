#include "vision/radial_profile.h"

#include <cmath>
#include <numbers>
#include <type_traits>

#include "vision/angle_table.h"

namespace icacam::vision {

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
    if (step == 1)
        loop(std::integral_constant<size_t, 1>{});
    else
        loop(step);
    return count;
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
