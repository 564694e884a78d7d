// Fixed-point stages against double references, with the stated bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "vision/edge_profile.h"
#include "vision/radial_profile.h"

using namespace icacam::vision;

namespace {
double bilinearRef(const std::vector<uint8_t> &img, int w, double x, double y)
{
    const int xi = int(std::floor(x)), yi = int(std::floor(y));
    const double fx = x - xi, fy = y - yi;
    auto p = [&](int X, int Y) { return double(img[size_t(Y) * w + X]); };
    return (p(xi, yi) * (1 - fx) + p(xi + 1, yi) * fx) * (1 - fy) +
           (p(xi, yi + 1) * (1 - fx) + p(xi + 1, yi + 1) * fx) * fy;
}

// A w × h image of uniform noise, every pixel drawn from rng: every weight and pixel matters.
std::vector<uint8_t> noiseImage(int w, int h, std::mt19937 &rng)
{
    std::vector<uint8_t> img(size_t(w) * h);
    for (auto &p : img) p = uint8_t(rng() & 255);
    return img;
}
} // namespace

TEST(RadialProfile, BilinearMatchesDoubleWithinStatedBound)
{
    // Bound: weights at 1/256 px → |error| ≤ 0.5/256 px × (sum of the two local slopes)
    // + 0.5/256 grey of output rounding. Random images have slopes up to 255 per px.
    const int w = 64, h = 48;
    std::mt19937 rng(3);
    const std::vector<uint8_t> img = noiseImage(w, h, rng);
    const LumaView v{img.data(), w, h, w, 1};
    std::uniform_real_distribution<double> X(0, w - 1.01), Y(0, h - 1.01);
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        const double x = X(rng), y = Y(rng);
        const uint16_t s = sampleBilinear(v, Q16_16::fromDouble(x), Q16_16::fromDouble(y));
        ASSERT_NE(s, kOutsideFrame);
        worst = std::max(worst, std::fabs(s / 256.0 - bilinearRef(img, w, x, y)));
    }
    EXPECT_LE(worst, 2 * 255 * (0.5 / 256 + 1.0 / 65536) + 0.5 / 256);
    // On smooth images (slope ≤ 4 grey/px, like a blurred edge) the bound is 1/30 grey.
    std::vector<uint8_t> ramp(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ramp[size_t(y) * w + x] = uint8_t(std::min(255, 3 * x + y));
    const LumaView r{ramp.data(), w, h, w, 1};
    worst = 0;
    for (int i = 0; i < 20000; ++i) {
        const double x = X(rng), y = Y(rng);
        const uint16_t s = sampleBilinear(r, Q16_16::fromDouble(x), Q16_16::fromDouble(y));
        worst = std::max(worst, std::fabs(s / 256.0 - bilinearRef(ramp, w, x, y)));
    }
    EXPECT_LE(worst, 4 * 0.5 / 256 + 0.5 / 256 + 1e-9);
}

TEST(RadialProfile, OutsideFootprintIsMarked)
{
    std::vector<uint8_t> img(16, 100);
    const LumaView v{img.data(), 4, 4, 4, 1};
    EXPECT_EQ(sampleBilinear(v, Q16_16::fromDouble(-0.5), Q16_16::fromDouble(1)), kOutsideFrame);
    EXPECT_EQ(sampleBilinear(v, Q16_16::fromDouble(3.0), Q16_16::fromDouble(1)), kOutsideFrame);
    EXPECT_EQ(sampleBilinear(v, Q16_16::fromDouble(2.5), Q16_16::fromDouble(2.5)), 100 * 256);
}

TEST(RadialProfile, RayPositionsDriftLessThanStated)
{
    // A vertical ramp (value = x): the sample at step i must equal x0 + i·cosθ to within the
    // accumulated Q16.16 rounding (≤ 1024 × 2^-16 px) plus the 1/256 px weight quantisation.
    const int w = 256, h = 256;
    std::vector<uint8_t> img(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img[size_t(y) * w + x] = uint8_t(x);
    const LumaView v{img.data(), w, h, w, 1};
    RaySpec ray{Q16_16::fromDouble(10.3), Q16_16::fromDouble(20.7), {}, {},
                Q16_16::fromDouble(0),    Q16_16::fromDouble(0.25)};
    rayDirection(1, 16, &ray.cosT, &ray.sinT); // 22.5°
    std::vector<uint16_t> out(900);
    ASSERT_EQ(sampleRay(v, ray, 900, out.data()), 900);
    for (int i = 0; i < 900; ++i) {
        const double x = 10.3 + i * 0.25 * ray.cosT.toDouble();
        EXPECT_NEAR(out[i] / 256.0, x, 900 * 2.0 / 65536 + 1.0 / 256 + 1e-3) << i;
    }
}

TEST(RadialProfile, RayEqualsBilinearSamplesAtEveryAngleAndLength)
{
    // The ray's fast paths (four samples at a time where the platform has them, then one at
    // a time) must give sampleBilinear's integers exactly at the accumulated positions: a
    // noise image, so that every weight and every pixel matters.
    const int w = 203, h = 171;
    std::mt19937 rng(11);
    const std::vector<uint8_t> img = noiseImage(w, h, rng);
    const LumaView v{img.data(), w, h, w, 1};
    std::uniform_real_distribution<double> U(0, 1);
    for (int trial = 0; trial < 400; ++trial) {
        RaySpec ray{Q16_16::fromDouble(60 + 80 * U(rng)), Q16_16::fromDouble(50 + 70 * U(rng)),  {}, {},
                    Q16_16::fromDouble(3 * U(rng)),       Q16_16::fromDouble(0.3 + 1.8 * U(rng))};
        rayDirection(trial % 256, 256, &ray.cosT, &ray.sinT);
        const int count = 1 + trial % 29;
        std::vector<uint16_t> out(static_cast<size_t>(count));
        const int inside = sampleRay(v, ray, count, out.data());
        const Q16_16 dx = ray.step.mul(ray.cosT), dy = ray.step.mul(ray.sinT);
        Q16_16 x = ray.cx + ray.r0.mul(ray.cosT), y = ray.cy + ray.r0.mul(ray.sinT);
        int expectInside = 0;
        for (int i = 0; i < count; ++i, x = x + dx, y = y + dy) {
            const uint16_t s = sampleBilinear(v, x, y);
            expectInside += s != kOutsideFrame;
            ASSERT_EQ(out[size_t(i)], s) << "trial " << trial << " sample " << i;
        }
        EXPECT_EQ(inside, expectInside);
    }
}

TEST(EdgeProfile, EitherSignIsTheStrongerOfBothSearches)
{
    // Random rows with ties, flat stretches and all-zero windows: the one-pass search must
    // return what the two single-sign searches and the comparison between them return.
    std::mt19937 rng(3);
    std::uniform_int_distribution<int32_t> D(-6, 6);
    for (int trial = 0; trial < 2000; ++trial) {
        const int count = 5 + trial % 40;
        std::vector<int32_t> d(static_cast<size_t>(count));
        for (auto &v : d) v = trial % 7 == 0 ? 0 : D(rng) * (1 + trial % 3);
        const int lo = trial % 4, hi = count - 1 - trial % 3;
        const EdgePeak up = strongestEdge(d.data(), count, lo, hi, +1);
        const EdgePeak down = strongestEdge(d.data(), count, lo, hi, -1);
        const EdgePeak &want = up.value > down.value ? up : down;
        const EdgePeak got = strongestEdgeEitherSign(d.data(), count, lo, hi);
        ASSERT_EQ(got.found, want.found) << trial;
        ASSERT_EQ(got.value, want.value) << trial;
        ASSERT_EQ(got.position.raw(), want.position.raw()) << trial;
    }
}

TEST(EdgeProfile, ParabolaVertexMatchesDouble)
{
    std::mt19937 rng(5);
    std::uniform_int_distribution<int32_t> D(0, 30000);
    for (int i = 0; i < 10000; ++i) {
        const int32_t d0 = D(rng) + 1000;
        const int32_t dm = D(rng) % d0, dp = D(rng) % d0;
        const double den = dm - 2.0 * d0 + dp;
        double ref = 0.5 * (dm - dp) / den;
        ref = std::clamp(ref, -0.5, 0.5);
        EXPECT_NEAR(parabolaVertex(dm, d0, dp).toDouble(), ref, 2.0 / 65536);
    }
    EXPECT_EQ(parabolaVertex(5, 5, 5).raw(), 0); // flat: no refinement
}

TEST(EdgeProfile, LocatesABlurredStepToASmallFractionOfAPixel)
{
    // A Gaussian-blurred step at a known sub-pixel position, sampled at 1 px.
    for (double edge : {40.0, 40.25, 40.5, 40.8}) {
        std::vector<uint16_t> s(80);
        for (int i = 0; i < 80; ++i)
            s[i] = uint16_t(256 * (60 + 80 * 0.5 * (1 + std::erf((i - edge) / (1.6 * std::sqrt(2.0))))));
        std::vector<int32_t> d(80);
        profileDerivative(s.data(), 80, d.data());
        const EdgePeak p = strongestEdge(d.data(), 80, 30, 50, +1, true);
        ASSERT_TRUE(p.found);
        EXPECT_NEAR(p.position.toDouble(), edge, 0.06) << edge;
        EXPECT_FALSE(strongestEdge(d.data(), 80, 30, 50, -1).found); // no falling edge
    }
}

TEST(EdgeProfile, InteriorRefusesAWindowEndFlank)
{
    std::vector<int32_t> d = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    EXPECT_FALSE(strongestEdge(d.data(), 10, 2, 6, +1, true).found);
    EXPECT_TRUE(strongestEdge(d.data(), 10, 2, 6, +1, false).found);
}

// The innermost clear edge: a rising edge at 5 (30) before a falling one at 12 (−80). Of
// either sign, a quarter of the strongest is clear and the inner one is taken; half is not,
// and the strongest stands. Of one sign only, the other sign's edges do not count.
TEST(EdgePeakTest, InnermostClearEdgeTakesTheFirstStepStrongEnough)
{
    std::vector<int32_t> d(20, 0);
    d[4] = 10, d[5] = 30, d[6] = 10;
    d[11] = -40, d[12] = -80, d[13] = -40;
    const EdgePeak quarter = innermostClearEdge(d.data(), 20, 1, 18, 0, 4);
    ASSERT_TRUE(quarter.found);
    EXPECT_EQ(quarter.position.toDouble(), 5.0);
    EXPECT_EQ(quarter.value, 30);
    const EdgePeak half = innermostClearEdge(d.data(), 20, 1, 18, 0, 2);
    EXPECT_EQ(half.position.toDouble(), 12.0);
    EXPECT_EQ(half.value, 80);
    const EdgePeak falling = innermostClearEdge(d.data(), 20, 1, 18, -1, 4);
    EXPECT_EQ(falling.position.toDouble(), 12.0);
    const EdgePeak rising = innermostClearEdge(d.data(), 20, 1, 18, +1, 4);
    EXPECT_EQ(rising.position.toDouble(), 5.0);
}
