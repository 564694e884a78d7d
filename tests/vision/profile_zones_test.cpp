// Naming the contact edge by the zones either side of each edge (vision/profile_zones.h), on
// mean profiles drawn sample by sample: the photographs' orders of brightness, where the
// steps alone would name the original face's edge, and the drawings' three levels, where
// the zones do not tell.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vision/edge_profile.h"
#include "vision/profile_zones.h"

using namespace icacam::vision;

namespace {

// A profile at 2 px a sample from the original face outwards, built from pieces, blurred by
// a [1 2 1] kernel twice (as the optics and the rays' sampling soften a step).
struct Profile {
    std::vector<double> grey;
    Profile &level(double g, int samples)
    {
        grey.insert(grey.end(), size_t(samples), g);
        return *this;
    }
    Profile &ramp(double from, double to, int samples)
    {
        for (int i = 0; i < samples; ++i) grey.push_back(from + (to - from) * (i + 0.5) / samples);
        return *this;
    }
    int contactEdge(int *edgeIndex = nullptr) const
    {
        std::vector<double> g = grey;
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<double> s = g;
            for (size_t i = 1; i + 1 < g.size(); ++i) s[i] = 0.25 * g[i - 1] + 0.5 * g[i] + 0.25 * g[i + 1];
            g = s;
        }
        std::vector<uint16_t> q(g.size());
        for (size_t i = 0; i < g.size(); ++i) q[i] = uint16_t(std::lround(g[i] * 256));
        std::vector<int32_t> d(g.size());
        profileDerivative(q.data(), int(q.size()), d.data());
        const int n = int(q.size());
        const ProfileEdges edges = findProfileEdges(q.data(), d.data(), n, 2, n - 3, 1000);
        const int k = contactEdgeByZones(q.data(), n, edges, 4);
        if (edgeIndex && k >= 0) *edgeIndex = edges.edge[k].index;
        return k;
    }
};

} // namespace

// Face ≫ ring > barrel < fixture: both of the end face's edges fall, the original face's by
// more; the ring is a level, the barrel beyond the contact edge a ramp into the dark.
TEST(ProfileZones, StaircaseNamesTheSecondFallingEdge)
{
    Profile p;
    p.level(117, 12).level(83, 10).ramp(60, 42, 8).level(95, 3).ramp(95, 114, 15).level(114, 10);
    int at = 0;
    EXPECT_EQ(p.contactEdge(&at), 1);
    EXPECT_NEAR(at, 22, 1);
}

// A burnished ring darker than the barrel's lit shoulder: the contact edge rises.
TEST(ProfileZones, DarkRingNamesTheRisingEdgeOntoTheShoulder)
{
    Profile p;
    p.level(130, 12).level(71, 9).level(131, 2).ramp(125, 72, 6).level(100, 4).ramp(100, 120, 12);
    int at = 0;
    EXPECT_EQ(p.contactEdge(&at), 1);
    EXPECT_NEAR(at, 21, 1);
}

// No ring resolved (one grey with the face): the first edge, followed by the barrel's ramp.
TEST(ProfileZones, FirstEdgeWhenTheBarrelFollowsIt)
{
    Profile p;
    p.level(140, 20).ramp(70, 52, 7).level(120, 3).ramp(120, 150, 15);
    EXPECT_EQ(p.contactEdge(), 0);
}

// A drawing: face, ring, barrel band and background each a level. The zones do not tell
// which edge ends the face; the caller decides by the steps.
TEST(ProfileZones, ThreeLevelsInARowDoNotTell)
{
    Profile p;
    p.level(150, 12).level(170, 8).level(40, 10).level(200, 12);
    EXPECT_EQ(p.contactEdge(), -1);
}

// Turning grooves on the ring are ridges of a few grey levels: weak beside the ring's
// edges, they are not the contact edge.
TEST(ProfileZones, GroovesOnTheRingAreNotTheContactEdge)
{
    Profile p;
    p.level(96, 12).level(130, 2).level(124, 2).level(131, 2).level(124, 2).level(130, 3).ramp(60, 45, 8);
    p.level(160, 10);
    int at = -1;
    const int k = p.contactEdge(&at);
    if (k >= 0) EXPECT_NEAR(at, 23, 1); // the ring's end, never a groove's flank
}
