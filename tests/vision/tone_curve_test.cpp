// The tone curve's shift of a blurred edge's derivative peak, against the peak found by brute
// force on the encoded profile (std::erf, a fine grid, the smoothing done as a sum).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vision/tone_curve.h"

using namespace icacam::vision;

namespace {

// The encoded profile's slope (smoothed by a Gaussian of variance smooth2 where it is
// positive) over a 0.002 px grid: how far its peak lies on the dark side.
double bruteForceShift(double dark, double bright, double blur, double gamma, double smooth2)
{
    const double h = 0.002, span = 12;
    const int n = int(2 * span / h) + 1;
    const double d = std::pow(dark / bright, gamma);
    std::vector<double> e(n);
    for (int i = 0; i < n; ++i) {
        const double x = -span + i * h;
        e[i] = std::pow(d + (1 - d) * 0.5 * (1 + std::erf(x / (blur * std::sqrt(2.0)))), 1 / gamma);
    }
    std::vector<double> slope(n, 0);
    for (int i = 1; i + 1 < n; ++i) slope[i] = (e[i + 1] - e[i - 1]) / (2 * h);
    if (smooth2 > 0) {
        const int half = int(4 * std::sqrt(smooth2) / h);
        std::vector<double> out(n, 0);
        for (int i = half; i + half < n; ++i)
            for (int j = -half; j <= half; j += 5)
                out[i] += slope[i + j] * std::exp(-0.5 * (j * h) * (j * h) / smooth2);
        slope = out;
    }
    int best = 0;
    for (int i = 0; i < n; ++i)
        if (slope[i] > slope[best]) best = i;
    return -(-span + best * h);
}

} // namespace

TEST(ToneCurve, NoCurveOrNoStepMovesNothing)
{
    EXPECT_EQ(toneEdgeShiftPx(60, 180, 1.5, 1.0), 0);
    EXPECT_EQ(toneEdgeShiftPx(120, 120, 1.5, 2.2), 0);
    EXPECT_EQ(toneEdgeShiftPx(0, 180, 1.5, 2.2), 0);
    EXPECT_EQ(toneEdgeShiftPx(60, 180, 0, 2.2), 0);
}

TEST(ToneCurve, ThePeakLiesOnTheDarkSideAsTheEncodedProfileShows)
{
    struct Case {
        double dark, bright, blur, gamma, smooth2;
    };
    for (const Case c : {Case{120, 190, 1.5, 2.2, 0}, Case{40, 120, 1.5, 2.2, 0}, Case{100, 104, 1.35, 2.2, 0},
                         Case{40, 200, 0.8, 1.8, 0}, Case{120, 190, 1.5, 2.2, 0.92}, Case{40, 120, 1.0, 2.2, 0.92},
                         Case{60, 190, 2.5, 2.4, 0.92}}) {
        SCOPED_TRACE(testing::Message() << c.dark << "/" << c.bright << " blur " << c.blur << " gamma " << c.gamma
                                        << " smoothing " << c.smooth2);
        const double expected = bruteForceShift(c.dark, c.bright, c.blur, c.gamma, c.smooth2);
        EXPECT_GT(expected, 0);
        EXPECT_NEAR(toneEdgeShiftPx(c.dark, c.bright, c.blur, c.gamma, c.smooth2), expected, 0.01);
    }
}

TEST(ToneCurve, TheShiftGrowsWithTheBlurAndTheContrast)
{
    // Unsmoothed, the shift is a fixed fraction of the blur.
    EXPECT_NEAR(toneEdgeShiftPx(60, 180, 3.0, 2.2), 2 * toneEdgeShiftPx(60, 180, 1.5, 2.2), 1e-6);
    EXPECT_GT(toneEdgeShiftPx(30, 180, 1.5, 2.2), toneEdgeShiftPx(90, 180, 1.5, 2.2));
}
