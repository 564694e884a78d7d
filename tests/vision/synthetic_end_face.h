#pragma once
// End-face pictures drawn in memory for the vision stages' unit tests: concentric boundaries
// (original face R_i, contact edge R_o, silhouette R_max) with known radii and centre, each a
// Gaussian-blurred step, so a stage's answer can be checked against the truth it was drawn
// from. Proportions and grey levels follow the host renderer's nominal scene (the paper's
// specimen at 50 % reduction: R_i 1.12, R_o 1.24, R_max 1.454 initial radii; a bright ICA ring
// on a slightly darker face, a dark barrel, a dark background).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "vision/luma_view.h"

namespace icacam::test {

struct SyntheticEndFace {
    int width = 900, height = 880;
    double cx = 451.3, cy = 438.6;                                    // the drawn centre, pixels
    double r0 = 250;                                                  // the specimen's initial radius, pixels
    double rInner = 1.12 * r0, rOuter = 1.24 * r0, rMax = 1.454 * r0; // the drawn boundaries, pixels
    // Relative amplitude and phase of a second harmonic on the contact edge (0: a circle).
    double outerC2 = 0, outerPhase = 0;
    double face = 150, ica = 170, barrel = 30, background = 40; // grey levels
    double blurSigma = 1.0;                                     // of every step, pixels
    // A ring light's highlight on the barrel: a bright band of this amplitude (grey levels)
    // and Gaussian width, centred highlightGap pixels inside the silhouette.
    double highlight = 0, highlightGap = 0, highlightSigma = 1;
    int pixelStep = 1; // 2: the luma of a YUYV frame (chroma bytes set to 128)
    // The outline's centre from the end face's (a close camera draws it towards the optical
    // axis), pixels; and a second step beyond the outline, about the same centre (the
    // fixture's shadow edge: shadowGap pixels out, shadowStep grey levels).
    double outlineDx = 0, outlineDy = 0;
    double shadowGap = 0, shadowStep = 0;
    // A camera's tone curve: the grey levels above are the encoded zones', the steps are
    // blurred in linear light and each pixel encoded as linear^(1/toneGamma) (1: as drawn).
    double toneGamma = 1;

    // The same specimen at another initial radius.
    void scaleTo(double newR0)
    {
        const double k = newR0 / r0;
        r0 = newR0;
        rInner *= k;
        rOuter *= k;
        rMax *= k;
    }

    double outerAt(double theta) const { return rOuter * (1 + outerC2 * std::cos(2 * (theta - outerPhase))); }

    // 0 … 1: how far a point at signed distance d inside a blurred boundary is lit by it.
    double inside(double d) const { return 0.5 * (1 + std::erf(d / (std::sqrt(2.0) * blurSigma))); }

    // An encoded grey level in linear light, on the same 0–255 scale.
    double lin(double level) const { return toneGamma == 1 ? level : 255 * std::pow(level / 255, toneGamma); }

    std::vector<uint8_t> draw() const
    {
        std::vector<uint8_t> px(size_t(width) * height * pixelStep, 128);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const double dx = x - cx, dy = y - cy;
                const double r = std::hypot(dx, dy), theta = std::atan2(dy, dx);
                const double rs = std::hypot(dx - outlineDx, dy - outlineDy);
                const double g = lin(background) + shadowStep * (1 - inside(rMax + shadowGap - rs)) +
                                 (lin(barrel) - lin(background)) * inside(rMax - rs) +
                                 (lin(ica) - lin(barrel)) * inside(outerAt(theta) - r) +
                                 (lin(face) - lin(ica)) * inside(rInner - r) +
                                 highlight *
                                     std::exp(-0.5 * std::pow((rs - (rMax - highlightGap)) / highlightSigma, 2)) *
                                     (1 - inside(outerAt(theta) - r));
                const double encoded = toneGamma == 1 ? g : 255 * std::pow(std::max(0.0, g) / 255, 1 / toneGamma);
                px[(size_t(y) * width + x) * pixelStep] = uint8_t(std::clamp(std::lround(encoded), 0L, 255L));
            }
        return px;
    }
    vision::LumaView view(const std::vector<uint8_t> &px) const
    {
        return vision::LumaView{px.data(), width, height, width * pixelStep, pixelStep};
    }
};

} // namespace icacam::test
