// The contact edge tracked between the nodes' touchdowns (fe_contact_track.h) on a synthetic
// rolling side whose true edge is known: the tracked edge must follow it to a fifth of
// a node spacing, where the outermost contact node is off by up to one spacing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "host_tools/fe/fe_contact_track.h"

using namespace icacam::host::fe;

namespace {
constexpr double kTol = 1e-4;
constexpr double kSpacing = 0.1; // mm of former side between nodes
constexpr int kTop = 40;         // nodes 0 … 40, 40 = the corner

// The true edge: s mm of former side rolled onto the platen, from 30 % of reduction on.
double trueEdge(double red)
{
    return red <= 0.3 ? 0.0 : 9.0 * std::pow(red - 0.3, 1.5);
}

// A side that leaves the platen tangentially (gap ∝ distance²) and lies flat where rolled on,
// its nodes at radius 5 + s (+ a uniform radial growth) so the true R_o is known.
// angled: the side meets the platen at a finite angle instead (gap ∝ distance, so it closes
// linearly in reduction), as the FE runs' sides do where they roll fast (high μ).
SideFrame frameAt(double red, bool angled = false)
{
    SideFrame f;
    f.reduction = red;
    const double se = trueEdge(red);
    for (int j = 0; j <= kTop; ++j) {
        const double s = (kTop - j) * kSpacing;
        f.gapMm.push_back(s <= se ? -2e-5 : angled ? 0.3 * (s - se) : 0.8 * (s - se) * (s - se));
        f.rMm.push_back(5.0 + red + s);
    }
    return f;
}
} // namespace

namespace {
// Largest |tracked − true| edge after the first touchdown, and the node method's, in mm.
struct TrackError {
    double tracked = 0, node = 0;
};
TrackError trackError(const std::vector<SideFrame> &frames)
{
    const auto td = touchdownReductions(frames, kTol);
    TrackError e;
    for (size_t k = 0; k < frames.size(); ++k) {
        const double red = frames[k].reduction;
        const double truth = 5.0 + red + trueEdge(red);
        int a = kTop;
        while (a > 0 && frames[k].gapMm[size_t(a - 1)] <= kTol) --a;
        if (red > 0.36) {
            e.tracked = std::max(e.tracked, std::fabs(trackedContactEdge(frames, td, k, kTol) - truth));
            e.node = std::max(e.node, std::fabs(frames[k].rMm[size_t(a)] - truth));
        }
    }
    return e;
}
} // namespace

TEST(FeContactTrack, FollowsASideThatMeetsThePlatenAtAnAngle)
{
    // The touchdown comes from the free approach before it, not from interpolating into the
    // frame where the node already sinks into the penalty contact (a √gap interpolation puts
    // such touchdowns up to half a frame late, and the edge then lags by a node's share).
    std::vector<SideFrame> frames;
    for (int k = 1; k <= 60; ++k) frames.push_back(frameAt(k * 0.01, true));
    const TrackError e = trackError(frames);
    EXPECT_GT(e.node, 0.5 * kSpacing) << "the node method is quantised (the test would not show anything)";
    EXPECT_LT(e.tracked, 0.05 * kSpacing) << "tracked edge off by " << e.tracked << " mm";
}

TEST(FeContactTrack, FollowsTheEdgeBetweenNodes)
{
    std::vector<SideFrame> frames;
    for (int k = 1; k <= 60; ++k) frames.push_back(frameAt(k * 0.01));
    const auto td = touchdownReductions(frames, kTol);
    ASSERT_EQ(td.size(), size_t(kTop + 1));
    EXPECT_EQ(td[kTop], 0.0);
    for (int j = kTop - 1; j > 0; --j) {
        if (td[size_t(j - 1)] >= 0) { EXPECT_GE(td[size_t(j - 1)], td[size_t(j)]) << "touchdowns run down the side"; }
    }
    double worstTracked = 0, worstNode = 0;
    for (size_t k = 0; k < frames.size(); ++k) {
        const double red = frames[k].reduction;
        const double truth = 5.0 + red + trueEdge(red);
        const double tracked = trackedContactEdge(frames, td, k, kTol);
        // The node method: the outermost node on the platen.
        int a = kTop;
        while (a > 0 && frames[k].gapMm[size_t(a - 1)] <= kTol) --a;
        const double node = frames[k].rMm[size_t(a)];
        if (red > 0.36) { // after the first touchdown (the onset itself is not tracked)
            worstTracked = std::max(worstTracked, std::fabs(tracked - truth));
            worstNode = std::max(worstNode, std::fabs(node - truth));
        }
        EXPECT_GE(tracked, node - 1e-12) << "the edge is at or past the last node on the platen";
    }
    EXPECT_GT(worstNode, 0.5 * kSpacing) << "the node method is quantised (the test would not show anything)";
    EXPECT_LT(worstTracked, 0.2 * kSpacing) << "tracked edge off by " << worstTracked << " mm";
}

TEST(FeContactTrack, NoFoldMeansTheCorner)
{
    std::vector<SideFrame> frames{frameAt(0.1), frameAt(0.2), frameAt(0.3)};
    const auto td = touchdownReductions(frames, kTol);
    for (int j = 0; j < kTop; ++j) EXPECT_LT(td[size_t(j)], 0) << "node " << j << " never touched";
    for (size_t k = 0; k < frames.size(); ++k)
        EXPECT_DOUBLE_EQ(trackedContactEdge(frames, td, k, kTol), frames[k].rMm[kTop]);
}

TEST(FeContactTrack, LastFrameExtrapolatesTheNextTouchdown)
{
    // Frames end mid-way between two touchdowns: the next node's touchdown is extrapolated
    // from its gap's closing rate, so the edge is still between the two nodes, not on one.
    std::vector<SideFrame> frames;
    for (int k = 1; k <= 50; ++k) frames.push_back(frameAt(k * 0.01));
    const auto td = touchdownReductions(frames, kTol);
    const double red = frames.back().reduction;
    const double truth = 5.0 + red + trueEdge(red);
    EXPECT_NEAR(trackedContactEdge(frames, td, frames.size() - 1, kTol), truth, 0.25 * kSpacing);
}

TEST(FeContactTrack, ContactThatLiftsOffDoesNotMoveTheEdgeBack)
{
    std::vector<SideFrame> frames{frameAt(0.40), frameAt(0.45), frameAt(0.50)};
    frames.back().gapMm[kTop - 1] = 0.01; // the first side node lifts off again
    const auto td = touchdownReductions(frames, kTol);
    EXPECT_GE(td[kTop - 1], 0) << "a touchdown stays a touchdown";
    EXPECT_GE(trackedContactEdge(frames, td, 2, kTol), frames[2].rMm[kTop - 1]);
}

TEST(FeContactTrack, SaysWhenANodeInsideTheContactZoneLiftedOff)
{
    SideFrame f = frameAt(0.5);
    EXPECT_FALSE(contactZoneBroken(f, kTol)) << "one zone from the corner down";
    f.gapMm[kTop - 1] = 5e-4; // the first side node hovers half a µm above the platen …
    EXPECT_TRUE(contactZoneBroken(f, kTol)) << "… while the nodes below it are down";
    EXPECT_FALSE(contactZoneBroken(frameAt(0.2), kTol)) << "no fold yet";
}
