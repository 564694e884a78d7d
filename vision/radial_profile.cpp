#include "radial_profile.h"

#include <cmath>
#include <numbers>

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
    Q16_16 x = ray.cx + ray.r0.mul(ray.cosT);
    Q16_16 y = ray.cy + ray.r0.mul(ray.sinT);
    int inside = 0;
    for (int i = 0; i < count; ++i) {
        const uint16_t s = sampleBilinear(v, x, y);
        inside += s != kOutsideFrame;
        out[i] = s;
        x = x + dx;
        y = y + dy;
    }
    return inside;
}

void rayDirection(int i, int n, Q2_14 *cosT, Q2_14 *sinT)
{
    const double t = 2.0 * std::numbers::pi * double(i) / double(n);
    *cosT = Q2_14::fromDouble(std::cos(t));
    *sinT = Q2_14::fromDouble(std::sin(t));
}

} // namespace icacam::vision
