#pragma once
// An end face as a tilted camera sees it, drawn in memory for the vision stages' tests: the
// barrel's widest circle (its outline) is shifted from the end face's centre towards the side
// facing the camera, where the barrel shows as a wide band, and hides behind the end face on
// the far side, where only its shoulder shows, edge-on, as a thin dark line beyond the contact
// edge. Where the barrel shows, the shoulder's shading ramps from the ring's grey to the
// barrel's over a few pixels. Proportions and grey levels follow a rendered staircase
// photograph tilted 12.5° (data/photobench tilted-s1, record 6: face above ring above barrel,
// the background lighter than the ring).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "vision/luma_view.h"

namespace icacam::test {

struct ObliqueEndFace {
    int width = 640, height = 480;
    double cx = 330.4, cy = 236.7;                               // the end face's centre, pixels
    double r0 = 126.8;                                           // the specimen's initial radius, pixels
    double rInner = 154, rOuter = 165;                           // the original face's edge and the contact edge
    double rOutline = 172;                                       // the barrel's widest circle ...
    double outlineShift = 12;                                    // ... its centre this far from the end face's ...
    double facingDeg = 160;                                      // ... towards the side facing the camera (image angle)
    double shoulderEdgeOnPx = 2.5;                               // the shoulder's dark line on the far side
    double shoulderPx = 7;                                       // the shoulder's ramp where it faces the camera
    double face = 135, ring = 92, barrel = 48, background = 105; // grey levels
    double blurSigma = 0.8;                                      // of every step, pixels

    // 0 … 1: how far a point at signed distance d inside a blurred boundary is lit by it.
    double inside(double d) const { return 0.5 * (1 + std::erf(d / (std::sqrt(2.0) * blurSigma))); }
    // The same for a boundary that ramps down over w pixels outside it: the Gaussian's
    // integral of the ramp, (G(d + w) − G(d)) / w with G the integral of the step's.
    double insideRamp(double d, double w) const
    {
        if (w < 0.05) return inside(d);
        auto g = [&](double x) {
            const double z = x / blurSigma;
            return x * 0.5 * (1 + std::erf(z / std::sqrt(2.0))) +
                   blurSigma * std::exp(-0.5 * z * z) / std::sqrt(2 * std::numbers::pi);
        };
        return (g(d + w) - g(d)) / w;
    }

    std::vector<uint8_t> draw() const
    {
        std::vector<uint8_t> px(size_t(width) * height);
        const double facing = facingDeg * std::numbers::pi / 180;
        const double ox = cx + outlineShift * std::cos(facing), oy = cy + outlineShift * std::sin(facing);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const double r = std::hypot(x - cx, y - cy), theta = std::atan2(y - cy, x - cx);
                // The barrel where the camera sees it: inside its outline, or its shoulder's
                // edge-on line just beyond the contact edge.
                const double onBarrel =
                    std::max(inside(rOutline - std::hypot(x - ox, y - oy)), inside(rOuter + shoulderEdgeOnPx - r));
                const double ramp = shoulderPx * std::max(0.0, std::cos(theta - facing));
                const double g = background + (barrel - background) * onBarrel +
                                 (ring - barrel) * insideRamp(rOuter - r, ramp) + (face - ring) * inside(rInner - r);
                px[size_t(y) * width + x] = uint8_t(std::clamp(std::lround(g), 0L, 255L));
            }
        return px;
    }
    vision::LumaView view(const std::vector<uint8_t> &px) const
    {
        return vision::LumaView{px.data(), width, height, width, 1};
    }
};

} // namespace icacam::test
