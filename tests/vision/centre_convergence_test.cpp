// The measurement must not depend on where the centre search starts: the locator's coarse
// centre lands anywhere within its cell (a few pixels), and every later stage casts its rays
// from the refined centre. Starts moved by 1–3 px in eight directions on a drawn end face
// under sensor noise must give one centre and one pair of radii.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "tests/vision/synthetic_end_face.h"
#include "vision/end_face_analyzer.h"

using namespace icacam;
using namespace icacam::vision;

namespace {

// About normal noise of σ ≈ 3.5 grey levels (a sum of four uniforms), the same for a seed.
void addNoise(std::vector<uint8_t> *px, uint32_t seed)
{
    uint32_t state = seed * 2654435761u;
    for (uint8_t &p : *px) {
        int n = 0;
        for (int k = 0; k < 4; ++k) {
            state = state * 1664525u + 1013904223u;
            n += int(state >> 29); // 0 … 7
        }
        p = uint8_t(std::clamp(int(p) + n - 14, 0, 255));
    }
}

struct Range {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
    double width() const { return hi - lo; }
};

} // namespace

TEST(CentreConvergence, OneCentreAndOnePairOfRadiiWhateverTheStart)
{
    // A small specimen (R0 60 px, as on a 640 × 480 frame) and the nominal one (R0 250 px),
    // centres off the pixel grid.
    for (const double r0 : {60.0, 250.0}) {
        test::SyntheticEndFace face;
        face.scaleTo(r0);
        face.width = face.height = int(3.6 * r0);
        face.cx = 0.5 * face.width + 0.37, face.cy = 0.5 * face.height - 0.21;
        auto px = face.draw();
        addNoise(&px, 7);
        EndFaceAnalyzer analyzer;
        ASSERT_EQ(analyzer.configure(face.width, face.height), ErrorCode::None);
        const FaceSearch search{10, 5.0 / r0};
        Range cx, cy, ri, ro;
        for (const double d : {0.0, 1.0, 2.0, 3.0})
            for (int k = 0; k < (d > 0 ? 8 : 1); ++k) {
                const double a = k * std::numbers::pi / 4;
                const EndFaceGeometry g =
                    analyzer.measureFrom(face.view(px), search, face.cx + d * std::cos(a), face.cy + d * std::sin(a));
                ASSERT_TRUE(g.found()) << "R0 " << r0 << ", start " << d << " px at " << k * 45 << "°";
                cx.add(g.centreX), cy.add(g.centreY);
                ri.add(g.inner.rEqPx), ro.add(g.outer.rEqPx);
            }
        EXPECT_LE(std::hypot(cx.width(), cy.width()), 0.1) << "R0 " << r0;
        EXPECT_LE(ri.width(), 0.05) << "R0 " << r0;
        EXPECT_LE(ro.width(), 0.05) << "R0 " << r0;
        // And the one centre is the specimen's.
        EXPECT_NEAR(0.5 * (cx.lo + cx.hi), face.cx, 0.25) << "R0 " << r0;
        EXPECT_NEAR(0.5 * (cy.lo + cy.hi), face.cy, 0.25) << "R0 " << r0;
    }
}
