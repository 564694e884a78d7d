// The contact edge's knee against profiles drawn from the model it stands for: a ring's level,
// then a barrel whose shading drops a little at the edge and falls faster beyond (no straight
// ramp), blurred by a Gaussian and sampled at 1 px in the aligned profile's Q8 grey levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "vision/contact_knee.h"
#include "vision/edge_profile.h"

using namespace icacam::vision;

namespace {

struct Barrel {
    double ring = 180;    // the ring's level, grey
    double step = 0;      // a drop at the edge itself, grey
    double kink = 8;      // the barrel's fall just beyond the edge, grey per px
    double steepest = 14; // its fall where it is steepest, grey per px
    double length = 2.5;  // how far out that is, px; the fall ends 3 × as far out
};

// The barrel's slope at x ≥ 0 px from the contact edge: from `kink` up to `steepest` at
// `length`, where the free surface has turned past the light, then down to none.
double fall(const Barrel &b, double x)
{
    if (x < b.length) return b.kink + (b.steepest - b.kink) * x / b.length;
    return std::max(0.0, b.steepest * (1 - (x - b.length) / (2 * b.length)));
}

// Sample k at (k − at − edge) px from the contact edge: the level, the step and the fall,
// blurred by σ (numerically, 1/64 px), in 1/256 grey levels.
std::vector<int32_t> profile(const Barrel &b, int count, int at, double edge, double sigma)
{
    constexpr int kPerPx = 64;
    const double from = -at - edge - 8 * sigma - 1;
    const int fine = (count + int(16 * sigma) + 2) * kPerPx;
    std::vector<double> shade(size_t(fine) + 1);
    double level = b.ring;
    for (int j = 0; j <= fine; ++j) {
        const double x = from + double(j) / kPerPx;
        if (x >= 0) level -= fall(b, x) / kPerPx;
        shade[size_t(j)] = x < 0 ? b.ring : level - b.step;
    }
    std::vector<int32_t> out(count);
    const int reach = int(6 * sigma * kPerPx);
    for (int k = 0; k < count; ++k) {
        const int c = int(std::lround((k - at - edge - from) * kPerPx));
        double sum = 0, wsum = 0;
        for (int j = -reach; j <= reach; ++j) {
            const double dx = double(j) / kPerPx / sigma;
            const double w = std::exp(-0.5 * dx * dx);
            sum += w * shade[size_t(c + j)];
            wsum += w;
        }
        out[k] = int32_t(std::lround(256 * sum / wsum));
    }
    return out;
}

// Where the derivative's peak reads the edge (the pipeline's per-ray estimator), in samples.
double derivativePeak(const std::vector<int32_t> &level, int sign)
{
    std::vector<uint16_t> s(level.size());
    for (size_t k = 0; k < level.size(); ++k) s[k] = uint16_t(level[k]);
    std::vector<int32_t> d(level.size());
    profileDerivative(s.data(), int(s.size()), d.data());
    return strongestEdge(d.data(), int(d.size()), 2, int(d.size()) - 3, sign).position.toDouble();
}

} // namespace

TEST(ContactKnee, FindsWhereTheLevelEndsNotWhereTheFallIsSteepest)
{
    // Blurs and sub-pixel positions across the range the bench's photographs show, a partial
    // step at the edge and a fall that steepens over 1.5–3.5 px; the window is placed where
    // the pipeline puts it, on the derivative's peak, and searched as far in as it searches a
    // ramp of 2.5 px.
    const int count = 40, at = 20;
    int cases = 0;
    for (double sigma : {0.8, 1.1, 1.5})
        for (double edge : {-0.4, 0.0, 0.3})
            for (double length : {1.5, 2.5, 3.5})
                for (double kink : {8.4, 14.0}) {
                    Barrel b;
                    b.step = 15, b.kink = kink, b.length = length;
                    const std::vector<int32_t> level = profile(b, count, at, edge, sigma);
                    const double peak = derivativePeak(level, -1) - at - edge;
                    // The derivative reads the edge outside, where the fall is steepest.
                    EXPECT_GT(peak, 0.8) << "sigma " << sigma << " length " << length;
                    ContactKneeWindow w;
                    w.blurPx = sigma;
                    w.searchInPx = 5;
                    const int peakAt = int(std::lround(peak + at + edge));
                    const ContactKnee knee = locateContactKnee(level.data(), count, peakAt, -1, w);
                    ASSERT_TRUE(knee.found) << "sigma " << sigma << " edge " << edge << " length " << length;
                    const double error = peakAt + knee.offsetPx - (at + edge);
                    // Within 0.6 px, and nearer than the derivative's peak by 0.3 px at least.
                    EXPECT_LT(std::fabs(error), std::min(0.6, peak - 0.3))
                        << "sigma " << sigma << " edge " << edge << " length " << length;
                    EXPECT_LT(knee.slope, 0);
                    ++cases;
                }
    EXPECT_EQ(cases, 54);
}

TEST(ContactKnee, ALitShoulderDoesNotPullTheStepInside)
{
    // A dark ring rising onto a lit shoulder that falls again within a few pixels: the fall,
    // blurred into the step, moves the derivative's peak inside; the step and the fall beyond
    // it fitted together (the fall going the other way) read the step where it is.
    const int count = 40, at = 20;
    for (double sigma : {0.8, 1.1, 1.5})
        for (double edge : {-0.4, 0.0, 0.3})
            for (double length : {1.5, 2.5}) {
                Barrel b;
                b.ring = 70, b.step = -60, b.kink = 12, b.steepest = 12, b.length = length;
                const std::vector<int32_t> level = profile(b, count, at, edge, sigma);
                const double peak = derivativePeak(level, +1) - at - edge;
                EXPECT_LT(peak, -0.2) << "sigma " << sigma << " length " << length;
                ContactKneeWindow w;
                w.blurPx = sigma;
                w.searchInPx = w.searchOutPx = 1.5;
                const int peakAt = int(std::lround(peak + at + edge));
                const ContactKnee knee = locateContactKnee(level.data(), count, peakAt, -1, w);
                ASSERT_TRUE(knee.found) << "sigma " << sigma << " edge " << edge << " length " << length;
                EXPECT_NEAR(peakAt + knee.offsetPx, at + edge, 0.15)
                    << "sigma " << sigma << " edge " << edge << " length " << length;
                EXPECT_GT(knee.stepLevel, 0);
            }
}

TEST(ContactKneeStep, ADrawnStepStaysWhereItIs)
{
    // A pure blurred step (no fall behind it): its knee is the step itself, or none.
    const int count = 40, at = 20;
    for (double sigma : {0.8, 1.2})
        for (double edge : {-0.3, 0.0, 0.4}) {
            Barrel b;
            b.step = 90, b.kink = 0, b.steepest = 0;
            const std::vector<int32_t> level = profile(b, count, at, edge, sigma);
            const int peakAt = int(std::lround(derivativePeak(level, -1)));
            ContactKneeWindow w;
            w.blurPx = sigma;
            const ContactKnee knee = locateContactKnee(level.data(), count, peakAt, -1, w);
            if (knee.found) { EXPECT_NEAR(peakAt + knee.offsetPx, at + edge, 0.1) << sigma << " " << edge; }
        }
}

TEST(ContactKneeStep, RefusesAWindowOffTheProfileOrOffTheFrame)
{
    Barrel b;
    std::vector<int32_t> level = profile(b, 40, 20, 0.0, 1.0);
    ContactKneeWindow w;
    EXPECT_FALSE(locateContactKnee(level.data(), 40, 3, -1, w).found);  // 6 samples inside
    EXPECT_FALSE(locateContactKnee(level.data(), 40, 38, -1, w).found); // 3 beyond
    level[19] = 0;                                                      // a sample off the frame
    EXPECT_FALSE(locateContactKnee(level.data(), 40, 21, -1, w).found);
    // A rising edge searched as a falling one: the fall goes against the sign.
    EXPECT_FALSE(locateContactKnee(profile(b, 40, 20, 0.0, 1.0).data(), 40, 22, +1, w).found);
}
