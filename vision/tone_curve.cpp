#include "vision/tone_curve.h"

#include <algorithm>
#include <cmath>

#include "vision/normal_cdf.h"

namespace icacam::vision {

namespace {

// The smoothing kernel's taps (a Gaussian sampled over ±3.5 σ).
constexpr int kTaps = 29;
// Golden-section steps on the peak's position: the bracket shrinks to 1e-5 of its width.
constexpr int kSteps = 24;

} // namespace

double toneEdgeShiftPx(double darkLevel, double brightLevel, double blurPx, double gamma, double smoothPx2)
{
    if (!(gamma > 1) || !(darkLevel > 0) || !(brightLevel > darkLevel) || !(blurPx > 0)) return 0;
    // The step in linear light from d to 1 (the bright side's level), d = (dark/bright)^γ,
    // encoded E(x) = (d + (1 − d)·Φ(x/σ))^(1/γ): its slope is
    // E'(x) = (1/γ)(d + (1 − d)Φ)^(1/γ − 1)·(1 − d)·φ(x/σ)/σ, the dark side at x < 0.
    const double d = std::pow(darkLevel / brightLevel, gamma), k = 1 / gamma - 1;
    auto slope = [&](double x) {
        const double z = x / blurPx;
        return std::exp(k * std::log(d + (1 - d) * normalCdf(z))) * normalPdf(z);
    };
    // The slope convolved with the locator's Gaussian (one tap where it does not smooth), its
    // peak found by golden section between the step's centre and 4 blurs on the dark side
    // (the smoothed slope is unimodal there).
    const int taps = smoothPx2 > 0 ? kTaps : 1;
    const double s = std::sqrt(std::max(0.0, smoothPx2));
    double tap[kTaps], weight[kTaps], sum = 0;
    for (int j = 0; j < taps; ++j) {
        tap[j] = (j - (taps - 1) / 2) * (7.0 * s / (kTaps - 1));
        weight[j] = taps > 1 ? std::exp(-0.5 * tap[j] * tap[j] / smoothPx2) : 1;
        sum += weight[j];
    }
    auto smoothed = [&](double x) {
        double v = 0;
        for (int j = 0; j < taps; ++j) v += weight[j] * slope(x - tap[j]);
        return v / sum;
    };
    constexpr double kInvPhi = 0.6180339887498949;
    double a = -4 * blurPx, b = 0;
    double x1 = b - kInvPhi * (b - a), x2 = a + kInvPhi * (b - a);
    double f1 = smoothed(x1), f2 = smoothed(x2);
    for (int i = 0; i < kSteps; ++i) {
        if (f1 < f2) {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + kInvPhi * (b - a), f2 = smoothed(x2);
        } else {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - kInvPhi * (b - a), f1 = smoothed(x1);
        }
    }
    return -0.5 * (a + b);
}

} // namespace icacam::vision
