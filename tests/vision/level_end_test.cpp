// Where the ring's level ends, on drawn profiles: a blurred step (the fit must leave it to the
// derivative's peak), a step followed by a barrel that falls away or is lit on its shoulder
// (the edge where the level ends, not where the profile is steepest), and the blur of a step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

#include "vision/level_end.h"

namespace icacam::vision {
namespace {

constexpr int kCount = 30;
constexpr double kEdge = 17.3; // the contact edge, samples

// The unblurred profile f(x) blurred by a Gaussian of `blur` (a sum over 1/50 px, independent
// of the fit's closed forms), plus Gaussian noise, in Q8 grey.
void draw(int32_t *p, const std::function<double(double)> &f, double blur, double noise, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> N(0, noise);
    for (int k = 0; k < kCount; ++k) {
        double s = 0, w = 0;
        for (double t = -6 * blur; t <= 6 * blur; t += 0.02) {
            const double g = std::exp(-0.5 * t * t / (blur * blur));
            s += g * f(k - t);
            w += g;
        }
        p[k] = int32_t(std::lround(256 * (s / w + N(rng))));
    }
}

// Where the profile is steepest (what the per-ray search takes for the edge), sub-sample.
double steepest(const int32_t *p)
{
    int best = 1;
    for (int k = 1; k + 1 < kCount; ++k)
        if (std::abs(p[k + 1] - p[k - 1]) > std::abs(p[best + 1] - p[best - 1])) best = k;
    return best;
}

TEST(LevelEnd, ABlurredStepIsLeftToTheDerivative)
{
    int32_t p[kCount];
    for (uint32_t seed = 1; seed <= 5; ++seed) {
        draw(
            p, [](double x) { return x < kEdge ? 120.0 : 60.0; }, 1.2, 0.3, seed);
        const LevelEnd e = fitLevelEnd(p, kCount, 6, 22, 9, 20, 1.2);
        ASSERT_TRUE(e.found);
        EXPECT_TRUE(e.stepSuffices) << "seed " << seed;
    }
}

TEST(LevelEnd, ABarrelFallingAwayEndsTheLevelAtTheEdge)
{
    int32_t p[kCount];
    // A jump of 12 grey levels, then 4 a pixel: steepest 1–3 px beyond the edge.
    draw(
        p, [](double x) { return x < kEdge ? 83.0 : 71.0 - 4.0 * (x - kEdge); }, 1.35, 0.2, 7);
    ASSERT_GT(steepest(p) - kEdge, 0.6);
    LevelEnd e = fitLevelEnd(p, kCount, 6, 22, 9, 20, 1.35);
    ASSERT_TRUE(e.found);
    EXPECT_FALSE(e.stepSuffices);
    EXPECT_NEAR(e.edge, kEdge, 0.3);
    // No jump at all: the barrel's slope changes at the edge.
    draw(
        p, [](double x) { return x < kEdge ? 200.0 : 200.0 - 9.0 * (x - kEdge); }, 0.9, 0.3, 8);
    e = fitLevelEnd(p, kCount, 6, 22, 9, 20, 0.9);
    ASSERT_TRUE(e.found);
    EXPECT_FALSE(e.stepSuffices);
    EXPECT_NEAR(e.edge, kEdge, 0.3);
}

TEST(LevelEnd, ALitShoulderEndsTheLevelAtTheEdge)
{
    int32_t p[kCount];
    // The barrel lit just beyond the edge (20 grey levels over the ring), then turning into
    // the dark.
    for (uint32_t seed = 1; seed <= 5; ++seed) {
        draw(
            p, [](double x) { return x < kEdge ? 96.0 : 116.0 - 2.0 * (x - kEdge) * (x - kEdge); }, 1.35, 0.2, seed);
        ASSERT_GT(steepest(p) - kEdge, 1.5);
        const LevelEnd e = fitLevelEnd(p, kCount, 6, 22, 9, 20, 1.35);
        ASSERT_TRUE(e.found);
        EXPECT_FALSE(e.stepSuffices);
        EXPECT_NEAR(e.edge, kEdge, 0.3) << "seed " << seed;
    }
}

TEST(LevelEnd, TheBlurOfAStepBetweenTwoLevels)
{
    int32_t p[kCount];
    for (double blur : {0.7, 1.0, 1.6, 2.2}) {
        draw(
            p, [](double x) { return x < kEdge ? 110.0 : 80.0; }, blur, 0.3, 3);
        EXPECT_NEAR(fitStepBlur(p, kCount, 8, 26, kEdge - 2, kEdge + 2), blur, 0.1) << blur;
    }
}

} // namespace
} // namespace icacam::vision
