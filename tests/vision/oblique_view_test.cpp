// The end face seen by a tilted camera (tests/vision/oblique_end_face.h): the barrel shows as a
// wide band on one side and hides behind the end face on the other, so that the strongest edge
// on each ray is the outline on one side and the contact edge on the other. Their centre lies
// off the end face's; the end face must still be read about its own, both boundaries where
// they were drawn, and the contact edge's ramp on the side facing the camera reported.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/vision/oblique_end_face.h"
#include "vision/end_face_analyzer.h"

using namespace icacam;
using namespace icacam::vision;

namespace {

EndFaceGeometry measureDrawn(const test::ObliqueEndFace &f)
{
    static EndFaceAnalyzer analyzer;
    EXPECT_EQ(analyzer.configure(f.width, f.height), ErrorCode::None);
    const auto px = f.draw();
    return analyzer.measure(f.view(px), {10, 5.0 / f.r0});
}

} // namespace

// Drawn as the bench's tilted staircase photographs render (tilted-s1 record 6, tilted-s2
// record 21): about the strongest edges' centre, 16 px off, the mean profile smears the two
// edges into one descent and no original face's edge shows inside it. About the end face's
// own centre, from the innermost clear edge on each ray, both are found where they were drawn.
TEST(RingSearchObliqueView, ReadsTheEndFaceAboutItsOwnCentre)
{
    const test::ObliqueEndFace f;
    const EndFaceGeometry g = measureDrawn(f);
    ASSERT_EQ(g.error, ErrorCode::None) << errorName(g.error);
    EXPECT_NEAR(g.inner.rEqPx, f.rInner, 0.5);
    EXPECT_NEAR(g.outer.rEqPx, f.rOuter, 0.5);
    for (const BoundaryFit *b : {&g.inner, &g.outer}) {
        EXPECT_NEAR(b->centreX, f.cx, 1.5);
        EXPECT_NEAR(b->centreY, f.cy, 1.5);
    }
}

// Where the barrel faces the camera, the shoulder's shading ramps over 7 px beyond the contact
// edge and the derivative peaks 2–3 px outside it; on the far side it peaks on the edge. Over
// the whole ring the ramp averages out under kContactRampPx; arc by arc it shows, and the
// reading must hear of it (contact_edge_ramp). Each arc's points are moved to where its ring
// level ends, the far side's left on the step.
TEST(RingSearchObliqueView, TheRampOnTheSideFacingTheCameraIsReported)
{
    const test::ObliqueEndFace f;
    const EndFaceGeometry g = measureDrawn(f);
    ASSERT_EQ(g.error, ErrorCode::None) << errorName(g.error);
    EXPECT_GT(g.contactRampPx, kContactRampPx);
    const double facing = f.facingDeg * std::numbers::pi / 180;
    double worst = 0;
    for (int i = 0; i < g.rayCount; ++i) {
        const EdgeSample &q = g.outerPoints[i];
        if (!q.valid) continue;
        const double dx = q.x.toDouble() - f.cx, dy = q.y.toDouble() - f.cy;
        if (std::cos(std::atan2(dy, dx) - facing) < 0.7) continue; // the side facing the camera
        worst = std::max(worst, std::fabs(std::hypot(dx, dy) - f.rOuter));
    }
    EXPECT_LT(worst, 1.5) << "a point on the side facing the camera read on the shoulder's ramp";
}
