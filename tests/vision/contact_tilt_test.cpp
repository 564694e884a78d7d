// The contact edge from segment frames against scenes drawn from the model it stands for: a
// flat face whose brightness is the same under every segment, and beyond the contact edge a
// barrel tilted outwards, which returns more of the light of the segment on its own side. The
// whole ring's frame shows no edge there: the shading runs on smoothly across it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "vision/contact_tilt.h"

using namespace icacam::vision;

namespace {

struct TiltScene {
    int width = 480, height = 480, segments = 4;
    double cx = 241.3, cy = 238.7;
    double edgePx = 150;  // the contact edge
    double tilt = 0.25;   // the barrel's share of light from its own side: I_k ∝ 1 + tilt·cos(θ − φ_k)
    double ripple = 0.02; // turning marks on the flat ring: a tilt that alternates every 3 px
    double blurPx = 1.2;  // the tilt's onset spread over the optics' blur (Gaussian)
    double dip = 0;       // a groove tilted inwards just inside the edge: its depth in tilt
    double dipAtPx = 4;   // its centre, inside the edge
};

// Segment k of the scene, 8-bit: a level that falls gently with radius on both sides of the
// edge, modulated by the tilt term on the segment's side.
std::vector<uint8_t> segmentFrame(const TiltScene &s, int k)
{
    std::vector<uint8_t> px(size_t(s.width) * s.height);
    const double phi = 2 * std::numbers::pi * k / s.segments;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const double dx = x - s.cx, dy = y - s.cy, r = std::hypot(dx, dy), th = std::atan2(dy, dx);
            const double onset = 0.5 * std::erfc(-(r - s.edgePx) / (s.blurPx * std::numbers::sqrt2));
            const double mark = s.ripple * std::sin(2 * std::numbers::pi * r / 6);
            const double groove = s.dip * std::exp(-0.5 * std::pow((r - s.edgePx + s.dipAtPx) / 1.2, 2));
            const double g = onset * s.tilt + (1 - onset) * mark - groove;
            const double level = 160 - 0.1 * r;
            px[size_t(y) * s.width + x] =
                uint8_t(std::lround(std::clamp(level * (1 + g * std::cos(th - phi)), 0.0, 255.0)));
        }
    return px;
}

struct Frames {
    std::vector<std::vector<uint8_t>> data;
    LitInTurn lit;
};

Frames framesOf(const TiltScene &s)
{
    Frames f;
    for (int k = 0; k < s.segments; ++k) f.data.push_back(segmentFrame(s, k));
    f.lit.count = s.segments;
    for (int k = 0; k < s.segments; ++k)
        f.lit.segment[k] = LumaView{f.data[size_t(k)].data(), s.width, s.height, s.width, 1};
    return f;
}

BoundaryFit circle(double r)
{
    BoundaryFit b;
    b.a0 = r;
    b.rEqPx = r;
    return b;
}

} // namespace

// A boundary read 6 px beyond the edge (the single frame's steepest fall on a lit shoulder)
// moves back onto it.
TEST(ContactTilt, MovesABoundaryReadBeyondTheEdgeOntoIt)
{
    const TiltScene s;
    const Frames f = framesOf(s);
    const TiltEdge t = contactEdgeByTilt(f.lit, circle(s.edgePx + 6), s.cx, s.cy, 15, 8, 1.2);
    ASSERT_TRUE(t.found);
    EXPECT_NEAR(t.shiftPx, -6, 0.75);
    EXPECT_GT(t.rise, 0.1);
    EXPECT_LT(t.sigmaPx, 0.5);
    EXPECT_GE(t.rays, 60);
}

// Read short of the edge, the boundary moves out to it; three or eight segments tell it alike.
TEST(ContactTilt, AnySegmentCountOfThreeOrMore)
{
    for (int n : {3, 4, 6, 8}) {
        TiltScene s;
        s.segments = n;
        const Frames f = framesOf(s);
        const TiltEdge t = contactEdgeByTilt(f.lit, circle(s.edgePx - 3), s.cx, s.cy, 12, 10, 1.2);
        ASSERT_TRUE(t.found) << n;
        EXPECT_NEAR(t.shiftPx, 3, 0.75) << n;
    }
}

// A flat face throughout (no barrel in the window): no step, whatever the marks' ripple.
TEST(ContactTilt, NoStepOnAFlatFace)
{
    TiltScene s;
    s.tilt = 0;
    s.ripple = 0.03;
    const Frames f = framesOf(s);
    EXPECT_FALSE(contactEdgeByTilt(f.lit, circle(s.edgePx), s.cx, s.cy, 15, 8, 1.2).found);
}

// The innermost step of two (the barrel's first degrees, then its turn further away) is the
// contact edge, the stronger outer one not.
TEST(ContactTilt, TheInnermostOfTwoSteps)
{
    TiltScene s;
    const Frames first = framesOf(s);
    // A second, stronger onset 7 px out: drawn as its own scene and mixed per pixel.
    TiltScene outer = s;
    outer.edgePx = s.edgePx + 7;
    outer.tilt = 0.5;
    const Frames second = framesOf(outer);
    Frames both = first;
    for (int k = 0; k < s.segments; ++k)
        for (size_t i = 0; i < both.data[size_t(k)].size(); ++i)
            both.data[size_t(k)][i] = uint8_t((int(first.data[size_t(k)][i]) + second.data[size_t(k)][i] + 1) / 2);
    for (int k = 0; k < s.segments; ++k)
        both.lit.segment[k] = LumaView{both.data[size_t(k)].data(), s.width, s.height, s.width, 1};
    const TiltEdge t = contactEdgeByTilt(both.lit, circle(s.edgePx + 7), s.cx, s.cy, 15, 8, 1.2);
    ASSERT_TRUE(t.found);
    EXPECT_NEAR(t.shiftPx, -7, 1.0);
}

// A groove tilted inwards a few pixels inside the edge dips T before the barrel's rise: the
// dip's far side read as a step down into a ramp is no knee; the edge is left alone (or, where
// a knee fits, it is where the rise begins).
TEST(ContactTilt, AGrooveDippingInsideTheEdgeIsNotTheKnee)
{
    TiltScene s;
    s.ripple = 0;
    s.dip = 0.06;
    const Frames f = framesOf(s);
    const TiltEdge t = contactEdgeByTilt(f.lit, circle(s.edgePx + 2), s.cx, s.cy, 15, 8, 1.2);
    EXPECT_TRUE(!t.found || std::fabs(t.shiftPx + 2) < 0.75) << t.shiftPx;
}

// Too few segments, or rays that leave the frame: nothing is claimed.
TEST(ContactTilt, NothingFromTwoSegmentsOrAFrameTooSmall)
{
    TiltScene s;
    s.segments = 2;
    const Frames two = framesOf(s);
    EXPECT_FALSE(contactEdgeByTilt(two.lit, circle(s.edgePx), s.cx, s.cy, 15, 8, 1.2).found);
    TiltScene big;
    big.edgePx = 330; // beyond the frame but near the diagonals
    const Frames f = framesOf(big);
    EXPECT_FALSE(contactEdgeByTilt(f.lit, circle(big.edgePx), big.cx, big.cy, 15, 8, 1.2).found);
}
