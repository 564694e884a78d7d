// The ring search on drawn end faces: from a centre near the specimen's axis it must find
// the contact edge, the original face edge and the silhouette where they were drawn, follow
// a contact edge that is not a circle, and name what it could not find.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "tests/vision/synthetic_end_face.h"
#include "vision/end_face_analyzer.h"
#include "vision/radial_profile.h"
#include "vision/ring_search.h"

using namespace icacam;
using namespace icacam::vision;

namespace {

// The working memory EndFaceAnalyzer carves for a search, and the coarse rows its centre
// refinement leaves behind (64 rays at the coarse step from 0.88 R0: the mean profile the
// search names its edges from).
struct Search {
    std::vector<uint16_t> coarse = std::vector<uint16_t>(size_t(kCoarseRays) * kMaxCoarseSamples);
    std::vector<uint16_t> fine = std::vector<uint16_t>(size_t(kFineRays) * kMaxFineSamples);
    std::vector<int16_t> deriv = std::vector<int16_t>(size_t(kFineRays) * kMaxFineSamples);
    std::vector<int32_t> meanProfile = std::vector<int32_t>(kMaxCoarseSamples);
    std::vector<int32_t> meanDeriv = std::vector<int32_t>(kMaxCoarseSamples);
    std::vector<EdgeSample> innerPts = std::vector<EdgeSample>(kFineRays);
    std::vector<EdgeSample> outerPts = std::vector<EdgeSample>(kFineRays);
    EndFaceGeometry m;
    RingSearch search{}; // the last run's, with its mean profile in meanDeriv

    // beyondDrop: RingSearch::runBeyondDrop instead of run.
    // toneGamma: the frame's tone curve the search is told (FaceSearch::toneGamma).
    ErrorCode run(const LumaView &v, double r0, double cx, double cy, bool beyondDrop = false, double toneGamma = 1)
    {
        const double rA = kCoarseStart * r0, rB = kCoarseEnd * r0;
        const double step = coarseStep(r0);
        const int count = std::min(kMaxCoarseSamples, int((rB - rA) / step));
        for (int i = 0; i < kCoarseRays; ++i) {
            RaySpec ray{Q16_16::fromDouble(cx), Q16_16::fromDouble(cy),  {}, {},
                        Q16_16::fromDouble(rA), Q16_16::fromDouble(step)};
            rayDirection(i, kCoarseRays, &ray.cosT, &ray.sinT);
            sampleRay(v, ray, count, coarse.data() + size_t(i) * kMaxCoarseSamples);
        }
        search = RingSearch{&v,
                            r0,
                            cx,
                            cy,
                            coarse.data(),
                            fine.data(),
                            deriv.data(),
                            meanProfile.data(),
                            meanDeriv.data(),
                            innerPts.data(),
                            outerPts.data()};
        search.toneGamma = toneGamma;
        m = EndFaceGeometry{};
        return beyondDrop ? search.runBeyondDrop(&m) : search.run(&m);
    }
};

// Bars on a clean picture blurred by σ = 1 px: the fine rays locate each edge to a small
// fraction of a pixel and 256 of them average what is left (on these pictures the radii come
// within 0.02 px and the centres within 0.005 px); the silhouette is read on the 64 coarse
// rays (2 px step here) and bounded here by one step.
constexpr double kEdgeTolPx = 0.05;
constexpr double kCentreTolPx = 0.02;

} // namespace

TEST(RingSearch, FindsTheDrawnBoundariesAboutTheDrawnCentre)
{
    const test::SyntheticEndFace face;
    const auto px = face.draw();
    Search s;
    const ErrorCode e = s.run(face.view(px), face.r0, face.cx, face.cy);
    ASSERT_EQ(e, ErrorCode::None) << errorName(e);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter, kEdgeTolPx);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, kEdgeTolPx);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, coarseStep(face.r0));
    EXPECT_GT(s.m.silhouetteCoverage, 0.9);
    EXPECT_GT(s.m.silhouetteScatterPx, 0);
    EXPECT_LT(s.m.silhouetteScatterPx, 0.5) << "every coarse ray's point on the drawn outline";
    for (const BoundaryFit *f : {&s.m.outer, &s.m.inner}) {
        EXPECT_GT(f->coverage, 0.95);
        EXPECT_LT(f->scatterPx, 0.2);
        EXPECT_NEAR(f->centreX, face.cx, kCentreTolPx);
        EXPECT_NEAR(f->centreY, face.cy, kCentreTolPx);
    }
    // Contrast across each edge, signed as it is crossed going outwards: the face (150) rises
    // to the ICA (170), the ICA falls to the barrel (30). The blur the contact edge shows is
    // the one it was drawn with.
    EXPECT_NEAR(s.m.inner.contrast, face.ica - face.face, 2);
    EXPECT_NEAR(s.m.outer.contrast, face.barrel - face.ica, 3);
    EXPECT_NEAR(s.m.edgeWidthPx, face.blurSigma, 0.15);
    EXPECT_EQ(s.m.imageFlags & kImageSpecimenClipped, 0u);
    EXPECT_EQ(s.m.saturatedFraction, 0);
    // On a clean picture every ray's point is accepted, and each lies on its drawn circle.
    ASSERT_EQ(s.m.rayCount, kFineRays);
    int valid = 0;
    for (int i = 0; i < s.m.rayCount; ++i) {
        for (const auto &[pts, r] :
             {std::pair{s.m.innerPoints, face.rInner}, std::pair{s.m.outerPoints, face.rOuter}}) {
            if (!pts[i].valid) continue;
            ++valid;
            EXPECT_NEAR(std::hypot(pts[i].x.toDouble() - face.cx, pts[i].y.toDouble() - face.cy), r, 0.5)
                << "ray " << i;
        }
    }
    EXPECT_EQ(valid, 2 * kFineRays);
}

TEST(RingSearch, TheSilhouetteIsTheOutlineNotAHighlightInsideIt)
{
    // The development set's photographs: a faint barrel/background step (7 grey levels) with
    // the ring light's highlight on the barrel just inside it (peak 14 px in). A step
    // detector wide enough for the faint step also spans the highlight's outer flank, and its
    // peak slides there: 1–2 % short, which reads as a smaller reduction. The outline must be
    // found where it was drawn, to a fraction of the coarse step.
    test::SyntheticEndFace face;
    face.barrel = 51, face.background = 44;
    face.highlight = 48, face.highlightGap = 14, face.highlightSigma = 3.5;
    face.blurSigma = 1.2;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, 0.5);
    EXPECT_GT(s.m.silhouetteCoverage, 0.9);
}

// The reference photographs' fixture beyond a dark barrel: the ring light's soft shadow lobes
// leave a faint step (6 grey levels over a few pixels) 6–18 % of R0 beyond the outline on a
// third of the rays, and on those rays it is the outermost clear step. Read there, the
// silhouette comes out several pixels large with a scatter of 10 px, which the reading took
// for a scale measured on the fixture (photo-003: u rescaled by 4.4 %). The outline is where
// most rays agree, and the scattered rays find it too when searched inside.
TEST(RingSearch, TheFixturesShadowLobesAreNotTheOutline)
{
    test::SyntheticEndFace face;
    face.face = 160, face.ica = 150, face.barrel = 69, face.background = 95;
    face.blurSigma = 1.2;
    auto px = face.draw();
    for (int y = 0; y < face.height; ++y)
        for (int x = 0; x < face.width; ++x) {
            const double r = std::hypot(x - face.cx, y - face.cy), theta = std::atan2(y - face.cy, x - face.cx);
            if (std::cos(3 * theta) < 0.3) continue;
            const double lobe = face.rMax + face.r0 * (0.06 + 0.12 * (0.5 + 0.5 * std::sin(7 * theta)));
            px[size_t(y) * face.width + x] +=
                uint8_t(std::lround(6 * 0.5 * (1 + std::erf((r - lobe) / (4 * std::sqrt(2.0))))));
        }
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, 1.0);
    EXPECT_GT(s.m.silhouetteCoverage, 0.9);
    EXPECT_LT(s.m.silhouetteScatterPx, 1.0);
}

// A barrel as dark as the background shows no outline; the contact edge's blurred tail just
// outside it must not pass for one. On a small frame (R0 100 px, a 2 px coarse step) the
// silhouette detector's window 0.04 R0 outside the contact edge reaches 4 px back inside it
// unless it starts beyond the edge's blur: every ray then sees the 190-grey drop and the fit
// places a silhouette 1–2 px outside the contact edge, on all rays alike.
TEST(RingSearch, TheContactEdgesTailIsNoSilhouette)
{
    test::SyntheticEndFace face;
    face.scaleTo(100);
    face.face = 200, face.ica = 210, face.barrel = 20, face.background = 20;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_LT(s.m.silhouetteCoverage, 0.5);
    if (s.m.rMaxPx > 0) { EXPECT_GT(s.m.rMaxPx - s.m.outer.rEqPx, 4.0) << s.m.rMaxPx; }
}

// A highlight band just inside the outline (the development set's devset-001: peak 14 px
// in, a 46 → 35 outline): the outline's own step is not a second step beyond it, also where
// the outline is placed a little inside its step (the per-ray detector, pulled by the
// highlight's flank, leaves it 2–3 px in there), and the search does not flag the outline
// as one it cannot tell from another.
TEST(RingSearch, TheOutlinesOwnStepIsNotItsRival)
{
    test::SyntheticEndFace face;
    face.width = face.height = 1200;
    face.cx = 600.3, face.cy = 590.6;
    face.scaleTo(378);
    face.face = 150, face.ica = 172, face.barrel = 46, face.background = 35;
    face.highlight = 26, face.highlightGap = 14, face.highlightSigma = 3.4;
    face.blurSigma = 1.6;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, 0.01 * face.rMax);
    EXPECT_EQ(s.m.imageFlags & kImageOutlineAmbiguous, 0u);
    for (const double inside : {1.0, 2.0, 3.0})
        EXPECT_FALSE(s.search.outlineRivalled(face.rMax - inside)) << inside << " px inside";
}

// A close camera draws the outline's centre towards the optical axis (the reference
// photographs' photo-007: 11 px from the contact edge's): about the contact edge's centre the
// rays' mean profile smears the one outline into two steps, an outline and a rival. Aligned
// on the fitted outline the rays show one step (kImageOutlineSmeared); a shadow edge beyond
// the outline is a rival there too.
TEST(RingSearch, AnOutlineDrawnAsideIsSmearedNotRivalled)
{
    test::SyntheticEndFace face;
    face.face = 160, face.ica = 150, face.barrel = 40, face.background = 90;
    face.outlineDx = -13, face.outlineDy = 5;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, 1.0);
    EXPECT_NE(s.m.imageFlags & kImageOutlineAmbiguous, 0u) << "the mean profile's smear";
    EXPECT_NE(s.m.imageFlags & kImageOutlineSmeared, 0u);

    // The fixture in the shadow, lit beyond: aligned on the outline, the rays show the
    // shadow's edge as a rival.
    face.shadowGap = 14, face.shadowStep = 25;
    const auto shadowed = face.draw();
    ASSERT_EQ(s.run(face.view(shadowed), face.r0, face.cx, face.cy), ErrorCode::None);
    std::vector<double> outline(kCoarseRays);
    for (int i = 0; i < kCoarseRays; ++i) {
        Q2_14 c, sn;
        rayDirection(i, kCoarseRays, &c, &sn);
        const double along = face.outlineDx * c.toDouble() + face.outlineDy * sn.toDouble();
        const double off2 = face.outlineDx * face.outlineDx + face.outlineDy * face.outlineDy;
        outline[i] = along + std::sqrt(along * along - off2 + face.rMax * face.rMax);
    }
    EXPECT_TRUE(s.search.outlineRivalledAlong(outline.data()));
}

namespace {
// Sensor noise on a drawn frame: a sum of four uniforms per pixel, about normal, σ ≈ 2.2
// grey levels; the same draw for the same seed.
void addNoise(std::vector<uint8_t> *px, uint32_t seed)
{
    uint32_t state = seed * 2654435761u;
    for (uint8_t &p : *px) {
        int n = 0;
        for (int k = 0; k < 4; ++k) {
            state = state * 1664525u + 1013904223u;
            n += int(state >> 30); // 0 … 3
        }
        p = uint8_t(std::clamp(int(p) + n - 6, 0, 255));
    }
}
} // namespace

// A dark barrel on a fixture three grey levels darker, under noise that hides the step on
// most single rays while the mean profile shows it: the sectors' pooled rays locate it round
// the specimen, and the outline is taken where it was drawn. Where barrel and fixture are
// one level, no outline is made of the noise.
TEST(RingSearch, AFaintOutlineIsFoundOnTheSectorsPooledRays)
{
    test::SyntheticEndFace face;
    face.scaleTo(150);
    face.width = face.height = 520;
    face.cx = 261.4, face.cy = 255.7;
    face.face = 100, face.ica = 90, face.barrel = 40, face.background = 37;
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        auto px = face.draw();
        addNoise(&px, seed);
        Search s;
        ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None) << "seed " << seed;
        EXPECT_NEAR(s.m.rMaxPx, face.rMax, 1.5) << "seed " << seed;
        EXPECT_GE(s.m.silhouetteCoverage, 0.5) << "seed " << seed;
    }
    face.background = face.barrel;
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        auto px = face.draw();
        addNoise(&px, seed);
        Search s;
        ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None) << "seed " << seed;
        EXPECT_EQ(s.m.silhouetteCoverage, 0) << "seed " << seed << ": an outline at " << s.m.rMaxPx << " px";
    }
}

// Lit along the line of sight, a barrel's limb is its darkest part; a bright line on it is a
// highlight where its surface faces the lens, inside the outline (the development set draws
// it 40 % of the band's width inside, 6 grey levels above a background just darker than the
// barrel). Every ray's outermost clear step is the line's outer flank: read there, the
// silhouette is 1–2 % short and the reading takes it for another height. The outline is the
// band's step to the background beyond the line; where the barrel is the background's shade
// there is none, and no silhouette is made of the line.
TEST(RingSearch, AHighlightLineIsNotTheOutline)
{
    test::SyntheticEndFace face;
    face.face = 150, face.ica = 170, face.barrel = 47, face.background = 41;
    face.highlight = 32, face.highlightGap = 0.4 * (face.rMax - face.rOuter), face.highlightSigma = 3;
    face.blurSigma = 1.2;
    auto px = face.draw();
    addNoise(&px, 7);
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, 1.0) << "the line's flank lies " << face.highlightGap << " px inside";
    face.background = face.barrel;
    px = face.draw();
    addNoise(&px, 7);
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_EQ(s.m.rMaxPx, 0) << "an outline on the line's flank, " << face.rMax - s.m.rMaxPx << " px inside";
    EXPECT_EQ(s.m.silhouetteCoverage, 0);
    face.barrel = 41, face.background = 47;
    px = face.draw();
    addNoise(&px, 7);
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.rMaxPx, face.rMax, 1.0) << "a lighter background";
}

TEST(RingSearch, AnOffCentreStartIsAbsorbedByTheFit)
{
    // The centre refinement can leave the search a few pixels off the axis: the boundaries
    // are still found, with their own centre where the specimen's is.
    const test::SyntheticEndFace face;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx + 2.5, face.cy - 1.5), ErrorCode::None);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter, kEdgeTolPx);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, kEdgeTolPx);
    for (const BoundaryFit *f : {&s.m.outer, &s.m.inner}) {
        EXPECT_NEAR(f->centreX, face.cx, kCentreTolPx);
        EXPECT_NEAR(f->centreY, face.cy, kCentreTolPx);
    }
}

TEST(RingSearch, FollowsAContactEdgeThatIsNotACircle)
{
    // An oval contact edge (±1.5 % second harmonic): the fitted curve follows it ray by ray and
    // its equivalent radius is the oval's, not the circle's.
    test::SyntheticEndFace face;
    face.outerC2 = 0.015;
    face.outerPhase = 0.4;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter * std::sqrt(1 + 0.5 * face.outerC2 * face.outerC2), kEdgeTolPx);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, kEdgeTolPx);
    double worst = 0;
    for (int k = 0; k < 36; ++k) {
        const double t = 2 * std::numbers::pi * k / 36;
        worst = std::max(worst, std::fabs(s.m.outer.radiusAt(t) - face.outerAt(t)));
    }
    EXPECT_LT(worst, 0.05) << "the fitted contact edge strays from the drawn oval";
    // 1 − b/a of r = R (1 + c cos 2θ): (2c) / (1 + c).
    EXPECT_NEAR(s.m.outer.ellipticity, 2 * face.outerC2 / (1 + face.outerC2), 0.001);
}

TEST(RingSearch, FindsTheRingWhereItIsDarkerThanTheFace)
{
    // The other polarity (a dull ICA on a bright face): both edges fall going outwards.
    test::SyntheticEndFace face;
    face.face = 190;
    face.ica = 120;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter, kEdgeTolPx);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, kEdgeTolPx);
    EXPECT_NEAR(s.m.inner.contrast, face.ica - face.face, 2);
}

// A camera encodes light through its tone curve, which draws each blurred edge's steepest
// point towards its dark side: a dull ring on a bright face reads both edges outwards, a
// bright ring on a dull face its original face's edge inwards. Told the curve, the search
// locates both edges where the optics drew them; untold, u reads off by the shifts.
TEST(RingSearch, EdgesAreLocatedInLinearLightThroughTheFramesToneCurve)
{
    struct Zones {
        double face, ica, barrel;
    };
    for (const Zones z : {Zones{190, 120, 40}, Zones{100, 190, 60}}) {
        test::SyntheticEndFace face;
        face.face = z.face, face.ica = z.ica, face.barrel = z.barrel;
        face.blurSigma = 1.5;
        face.toneGamma = 2.2;
        const auto px = face.draw();
        Search told, untold;
        ASSERT_EQ(told.run(face.view(px), face.r0, face.cx, face.cy, false, face.toneGamma), ErrorCode::None);
        ASSERT_EQ(untold.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
        SCOPED_TRACE(testing::Message() << "face " << z.face << ", ring " << z.ica << ", barrel " << z.barrel);
        // Told, both within 0.08 px (the fine rays' sub-pixel peaks leave a few hundredths).
        EXPECT_NEAR(told.m.inner.rEqPx, face.rInner, 0.08);
        EXPECT_NEAR(told.m.outer.rEqPx, face.rOuter, 0.08);
        // Untold, the original face's edge reads towards the darker zone by a quarter pixel or more.
        const double innerShift = untold.m.inner.rEqPx - face.rInner;
        EXPECT_GT(z.face > z.ica ? innerShift : -innerShift, 0.25);
    }
}

// A dark ring under a ring light (the bench's straight-s1 record 18, aluminium): face 148,
// ring 121, a lit shoulder just outside the contact edge rising to about 140, the barrel
// falling beyond it to 80 and the outline rising to a lighter fixture. The zones name the
// shoulder's rise; the centring, which takes the innermost step at least half the strongest
// of its sign, must not go on to the outline's stronger rise beyond the shoulder's fall (it
// did: R_i read on the shoulder's fall, 23 px out on the bench, R_o on the outline).
TEST(RingSearch, ALitShoulderIsTheContactEdgeNotTheOutlineBeyondIt)
{
    test::SyntheticEndFace face;
    face.scaleTo(121);
    face.rMax = 1.41 * face.r0; // the outline within the centring's reach
    face.face = 148, face.ica = 121, face.barrel = 80, face.background = 125;
    face.highlight = 62, face.highlightSigma = 5;
    face.highlightGap = face.rMax - face.rOuter - 4; // the shoulder peaks 4 px outside R_o
    face.blurSigma = 1.2;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, 0.5);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter, 1.5) << "the shoulder's rise, blurred into its peak";
}

TEST(RingSearch, ARingDarkerThanFaceAndShoulderIsFoundAboutItsFarEdge)
{
    // A polished ring a few pixels wide, darker than the face and than the barrel's lit
    // shoulder beyond it, the outline falling to a dark fixture just outside (the bench's
    // dark_ring at a low μ): at the coarse step the ring is no zone, the face's edge is the
    // largest drop, and no original face's edge lies inside it. The ring's far edge, the
    // profile's step back before the outline, is the contact edge.
    test::SyntheticEndFace face;
    face.scaleTo(130);
    face.rInner = 170, face.rOuter = 173.7, face.rMax = 178.7;
    face.face = 216, face.ica = 120, face.barrel = 80, face.background = 60;
    face.highlight = 75, face.highlightSigma = 2, face.highlightGap = 4.5;
    face.blurSigma = 1.0;
    const auto px = face.draw();
    Search s;
    EXPECT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::InnerEdgeNotFound);
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy, true), ErrorCode::None);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, 0.5);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter, 0.5);
    // The analyzer searches there last.
    static EndFaceAnalyzer analyzer;
    ASSERT_EQ(analyzer.configure(face.width, face.height), ErrorCode::None);
    const EndFaceGeometry g = analyzer.measure(face.view(px), {10, 5.0 / face.r0});
    ASSERT_TRUE(g.found()) << errorName(g.error);
    EXPECT_NEAR(g.inner.rEqPx, face.rInner, 0.5);
    EXPECT_NEAR(g.outer.rEqPx, face.rOuter, 0.5);
}

TEST(RingSearch, AnEmptyFrameHasNoContactEdge)
{
    test::SyntheticEndFace face;
    face.face = face.ica = face.barrel = face.background = 90;
    const auto px = face.draw();
    Search s;
    EXPECT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::OuterEdgeNotFound);
}

TEST(RingSearch, APlainDiscHasNoOriginalFaceEdge)
{
    // A face that runs into the barrel without a ring: the contact edge is there, the edge
    // inside it is not, and the search says which one it missed.
    test::SyntheticEndFace face;
    face.face = face.ica;
    const auto px = face.draw();
    Search s;
    EXPECT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::InnerEdgeNotFound);
}

TEST(RingSearch, NoiseOnAPlainDiscIsNoOriginalFaceEdge)
{
    // The same disc under sensor noise: somewhere inside the contact edge the noise peaks, and
    // rays that follow it would report a ring with nothing between its sides. No such edge is
    // taken for the original face, over many noise draws.
    test::SyntheticEndFace face;
    face.face = face.ica;
    int measured = 0;
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        auto px = face.draw();
        uint32_t state = seed * 2654435761u;
        for (uint8_t &p : px) {
            // Sum of four uniforms: about normal, σ ≈ 3.5 grey levels.
            int n = 0;
            for (int k = 0; k < 4; ++k) {
                state = state * 1664525u + 1013904223u;
                n += int(state >> 29); // 0 … 7
            }
            p = uint8_t(std::clamp(int(p) + n - 14, 0, 255));
        }
        Search s;
        const ErrorCode e = s.run(face.view(px), face.r0, face.cx, face.cy);
        if (e == ErrorCode::None) {
            ++measured;
            ADD_FAILURE() << "seed " << seed << ": a ring of " << s.m.outer.rEqPx - s.m.inner.rEqPx << " px, contrast "
                          << s.m.inner.contrast;
        }
    }
    EXPECT_EQ(measured, 0);
}

TEST(RingSearch, AClippedFaceIsSaturatedNotARing)
{
    // Face and ring both at full scale: the edge between them is gone, and the reason is the
    // exposure, which the search names instead of a missing edge.
    test::SyntheticEndFace face;
    face.face = face.ica = 255;
    const auto px = face.draw();
    Search s;
    EXPECT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::Saturated);
    EXPECT_GT(s.m.saturatedFraction, 0.1);
}

TEST(RingSearch, ASpecimenRunningOffTheFrameIsFlagged)
{
    // The silhouette crosses the frame's left edge: rays leaving the frame are marked, the
    // ring is still found inside it, and the measurement says the specimen was clipped.
    test::SyntheticEndFace face;
    face.cx = face.rOuter + 6.3;
    const auto px = face.draw();
    Search s;
    ASSERT_EQ(s.run(face.view(px), face.r0, face.cx, face.cy), ErrorCode::None);
    EXPECT_NE(s.m.imageFlags & kImageSpecimenClipped, 0u);
    EXPECT_NEAR(s.m.outer.rEqPx, face.rOuter, kEdgeTolPx);
    EXPECT_NEAR(s.m.inner.rEqPx, face.rInner, kEdgeTolPx);
}
