#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "vision/boundary_fit.h"

using namespace icacam::vision;

TEST(BoundaryFit, AreaOfAWobblyCurveMatchesAnalytic)
{
    // r(θ) = R (1 + c2 cos 2θ + c3 sin 3θ): area = π R² (1 + (c2² + c3²)/2).
    const int n = 256;
    const double R = 400, c2 = 0.01, c3 = 0.006;
    double r[n];
    bool valid[n];
    std::mt19937 rng(2);
    std::normal_distribution<double> noise(0, 0.3);
    for (int i = 0; i < n; ++i) {
        const double t = 2 * std::numbers::pi * i / n;
        r[i] = R * (1 + c2 * std::cos(2 * t) + c3 * std::sin(3 * t)) + noise(rng);
        valid[i] = true;
    }
    BoundaryFit f;
    ASSERT_TRUE(fitBoundary(r, valid, n, 100, 200, FitOptions{}, &f));
    EXPECT_NEAR(f.rEqPx, R * std::sqrt(1 + 0.5 * (c2 * c2 + c3 * c3)), 0.08);
    EXPECT_NEAR(f.scatterPx, 0.3, 0.06);
    EXPECT_NEAR(f.ellipticity, 2 * c2 * R / (R + c2 * R), 0.002);
    EXPECT_GT(f.coverage, 0.95);
}

TEST(BoundaryFit, RejectsOutliersAndMissingRays)
{
    const int n = 256;
    double r[n];
    bool valid[n];
    for (int i = 0; i < n; ++i) {
        r[i] = 300 + ((i % 17 == 0) ? 25 : 0); // a stain edge every 17th ray
        valid[i] = (i % 5) != 0;               // and a fifth of the rays without an edge
    }
    BoundaryFit f;
    ASSERT_TRUE(fitBoundary(r, valid, n, 0, 0, FitOptions{}, &f));
    EXPECT_NEAR(f.rEqPx, 300, 0.01);
    EXPECT_NEAR(f.coverage, 0.75, 0.05);
}

TEST(BoundaryFit, CentreOffsetIsTheFirstHarmonic)
{
    // A circle of radius 200 about (13, -7), seen in polar form from the origin.
    const int n = 256;
    double r[n];
    bool valid[n];
    for (int i = 0; i < n; ++i) {
        const double t = 2 * std::numbers::pi * i / n;
        const double b = 13 * std::cos(t) - 7 * std::sin(t);
        r[i] = b + std::sqrt(b * b - (13 * 13 + 7 * 7) + 200 * 200);
        valid[i] = true;
    }
    BoundaryFit f;
    ASSERT_TRUE(fitBoundary(r, valid, n, 0, 0, FitOptions{}, &f));
    EXPECT_NEAR(f.centreX, 13, 0.5);
    EXPECT_NEAR(f.centreY, -7, 0.5);
    EXPECT_NEAR(f.rEqPx, 200, 0.5); // area is independent of the polar origin
}

TEST(BoundaryFit, TooFewPointsIsAnError)
{
    double r[16] = {};
    bool valid[16] = {};
    BoundaryFit f;
    EXPECT_FALSE(fitBoundary(r, valid, 16, 0, 0, FitOptions{}, &f));
}

// The curve in many directions at once is radiusAt in each, to the last bit (the ring search
// places its second pass's windows with it), for every harmonic count and ray count used.
TEST(BoundaryFit, RadiiAtManyDirectionsAreRadiusAtEach)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coef(-3, 3);
    for (int harmonics = 0; harmonics <= BoundaryFit::kMaxHarmonics; ++harmonics)
        for (int n : {16, 32, 64, 100, 128, 256}) {
            BoundaryFit f;
            f.a0 = 300 + coef(rng);
            f.harmonics = harmonics;
            for (int k = 1; k <= harmonics; ++k) f.a[k] = coef(rng), f.b[k] = coef(rng);
            double c[256], s[256], r[256];
            for (int i = 0; i < n; ++i) {
                const double t = 2 * std::numbers::pi * i / n + 0.1;
                c[i] = std::cos(t), s[i] = std::sin(t);
            }
            radiiAt(f, c, s, n, r);
            for (int i = 0; i < n; ++i)
                ASSERT_EQ(r[i], f.radiusAt(c[i], s[i])) << harmonics << " harmonics, ray " << i << " of " << n;
        }
}
