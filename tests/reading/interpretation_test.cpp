// The interpretation on measured faces built from the FE's own radii: what a silhouette that
// reads small is taken for, in a straight view and in an oblique one.
#include <gtest/gtest.h>

#include <cmath>

#include "friction/friction_models.h"
#include "friction/outline_ratio.h"
#include "friction/radii_consistency.h"
#include "reading/interpretation.h"

namespace icacam::reading {
using namespace icacam::friction;
using vision::BoundaryFit;
using vision::EndFaceGeometry;
namespace {

constexpr double kN = 0.25, kMu = 0.15, kMmPerPx = 0.02;

// A face at 50 % reduction as the pipeline would hand it over, the silhouette a specimen's
// (feRMaxOverSpecimen inside the FE's) scaled by rMaxFactor; an oblique view gives both
// boundaries the same ellipse.
EndFaceGeometry face(double rMaxFactor, bool oblique, double n = kN, double mu = kMu)
{
    double ri = 0, ro = 0, rm = 0;
    EXPECT_TRUE(feRadiusAt(FeRadius::Inner, n, mu, 0.5, &ri));
    EXPECT_TRUE(feRadiusAt(FeRadius::Outer, n, mu, 0.5, &ro));
    EXPECT_TRUE(feRadiusAt(FeRadius::Max, n, mu, 0.5, &rm));
    EndFaceGeometry m;
    m.error = ErrorCode::None;
    for (BoundaryFit *b : {&m.inner, &m.outer}) {
        b->coverage = 1;
        b->contrast = 40;
        b->rEqSigmaPx = 0.05;
        b->scatterPx = 0.3;
        b->ellipticity = oblique ? 0.03 : 0;
        b->axisDeg = 30;
    }
    m.inner.rEqPx = ri / kMmPerPx;
    m.outer.rEqPx = ro / kMmPerPx;
    m.rMaxPx = rm / (1 + feRMaxOverSpecimen(n, mu)) * rMaxFactor / kMmPerPx;
    m.silhouetteCoverage = 1;
    m.edgeWidthPx = 1;
    return m;
}

// The face seen by a straight camera w mm above it, its centre (offX, offY) px from the
// optical axis of a 1456 × 1088 frame: the outline as that camera sees it, its centre drawn
// towards the axis by the share the side's depth takes off.
EndFaceGeometry closeCameraFace(double w, double offX, double offY)
{
    const double x = 10.0 / w, share = outlineShiftAt(kN, kMu, 0.5, x);
    EndFaceGeometry g = face(outlineRatioAt(kN, kMu, 0.5, x), false);
    g.frameWidth = 1456, g.frameHeight = 1088;
    const double axisX = 0.5 * (g.frameWidth - 1), axisY = 0.5 * (g.frameHeight - 1);
    for (BoundaryFit *b : {&g.inner, &g.outer}) b->centreX = axisX + offX, b->centreY = axisY + offY;
    g.centreX = g.outer.centreX, g.centreY = g.outer.centreY;
    g.silhouetteScatterPx = 0.5;
    g.silhouetteCentreX = g.outer.centreX - share * offX;
    g.silhouetteCentreY = g.outer.centreY - share * offY;
    return g;
}

// What the nominal conditions' check finds where the silhouette departs from the nominal half
// height: another height, or a scale off, that moves μ beyond the tolerance.
constexpr uint32_t kNominalFinding = kFlagScaleSuspect | kFlagReductionNotNominal;

Reading interpret(const EndFaceGeometry &g, double n = kN)
{
    SpecimenSpec spec;
    spec.n = n;
    spec.mmPerPx = kMmPerPx;
    return reading::interpret(g, spec, nullptr, *frictionModel(kDefaultModel));
}

// A camera W above the end face sees the outline inside R_max (friction/outline_ratio.h).
// Declared, W bounds that outline without fixing it: the side reaches farthest somewhere
// between the end face and its widest section, so the FE's barrel, and a flatter one whose
// outline lies nearer R_max (the reference photographs': 1–3 % inside where the FE's is 3–6 %),
// are both the nominal half height, with the spread that leaves in the reduction. An outline
// inside what the roundest barrel shows from there, or beyond R_max, is another height or
// scale. Undeclared, the FE's close outline on the axis reads as a specimen pressed less far,
// and says so.
TEST(Interpretation, TheDeclaredWorkingDistanceBoundsTheOutlineNotTheBarrelsShape)
{
    const double w = 55, fe = outlineRatioAt(kN, kMu, 0.5, 10.0 / w);
    SpecimenSpec spec;
    spec.n = kN;
    spec.mmPerPx = kMmPerPx;
    const Reading undeclared = reading::interpret(face(fe, false), spec, nullptr, *frictionModel(kDefaultModel));
    EXPECT_TRUE(undeclared.flags & kNominalFinding);
    EXPECT_LT(undeclared.reduction, 0.49);
    spec.workingDistanceMm = w;
    for (double ratio : {fe, 0.5 * (fe + 1)}) {
        const Reading declared = reading::interpret(face(ratio, false), spec, nullptr, *frictionModel(kDefaultModel));
        ASSERT_EQ(declared.status, Status::Ok) << ratio << " " << declared.flags;
        EXPECT_NEAR(declared.reduction, 0.5, 2 * declared.reductionSigma) << ratio;
        EXPECT_LT(declared.reductionSigma, 0.02) << ratio;
        EXPECT_NEAR(declared.mu, kMu, 0.01) << ratio; // ok and right
    }
    // The roundest barrel reaches farthest at its widest section, h/2 below the face.
    const double roundest = w / (w + 0.25 * spec.h0Mm);
    for (double ratio : {0.96 * roundest, 1.04}) {
        const Reading off = reading::interpret(face(ratio, false), spec, nullptr, *frictionModel(kDefaultModel));
        EXPECT_TRUE(off.flags & kNominalFinding) << ratio << " " << off.reduction << " " << off.scaleFactor;
    }
}

// Undeclared, the working distance is what the image says: an end face off the optical axis
// has its outline's centre drawn towards the axis by the share the side's depth takes off
// (friction::outlineShiftAt). The close camera's outline, so drawn, is the nominal half
// height; the same outline with its centre on the end face's (a telecentric view) is a
// specimen pressed less far; a shift across the axis is no straight camera's, and the image
// then says nothing of W.
TEST(Interpretation, TheOutlinesCentreShiftTellsACloseCamerasOutlineFromAnotherHeight)
{
    const double w = 55, x = 10.0 / w;
    const double share = outlineShiftAt(kN, kMu, 0.5, x);
    const double offX = 220, offY = -90; // the end face's centre from the axis, px
    const EndFaceGeometry g = closeCameraFace(w, offX, offY);
    const Reading close = interpret(g);
    ASSERT_EQ(close.status, Status::Ok) << close.flags;
    EXPECT_NEAR(close.reduction, 0.5, 0.003);
    EXPECT_NEAR(close.scaleFactor, 1, 0.005);

    // A specimen 2 % oval shows both boundaries elliptical along one axis: its own shape, not
    // the camera's. The outline's shift still says the close camera.
    EndFaceGeometry oval = g;
    for (BoundaryFit *b : {&oval.inner, &oval.outer}) b->ellipticity = 0.02, b->axisDeg = 35;
    const Reading ovalClose = interpret(oval);
    EXPECT_NEAR(ovalClose.reduction, 0.5, 0.003) << ovalClose.flags;

    EndFaceGeometry centred = g;
    centred.silhouetteCentreX = g.outer.centreX, centred.silhouetteCentreY = g.outer.centreY;
    const Reading telecentric = interpret(centred);
    EXPECT_TRUE(telecentric.flags & kNominalFinding) << telecentric.flags;
    EXPECT_LT(telecentric.reduction, 0.49);

    EndFaceGeometry across = g; // the same shift turned a quarter round: no straight camera's
    across.silhouetteCentreX = g.outer.centreX + share * offY;
    across.silhouetteCentreY = g.outer.centreY - share * offX;
    const Reading skew = interpret(across);
    EXPECT_TRUE(skew.flags & kNominalFinding) << skew.flags;
    EXPECT_NEAR(skew.reduction, telecentric.reduction, 0.002);
}

// An end face on the optical axis shows no shift whatever W is: the close camera's outline is
// then one of two views the reading weighs, beside another height seen telecentrically. It
// cannot tell them apart, so its U covers both and, where they part by more than the
// tolerance, it says so: never a silent wrong reading. Off the axis, the shift decides.
TEST(Interpretation, AnEndFaceOnTheAxisIsNeverASilentWrongReading)
{
    const double w = 55, x = 10.0 / w;
    const double share = outlineShiftAt(kN, kMu, 0.5, x);
    auto seenFrom = [&](double offX) {
        EndFaceGeometry g = face(outlineRatioAt(kN, kMu, 0.5, x), false);
        g.frameWidth = 1456, g.frameHeight = 1088;
        const double axisX = 0.5 * (g.frameWidth - 1), axisY = 0.5 * (g.frameHeight - 1);
        for (BoundaryFit *b : {&g.inner, &g.outer}) b->centreX = axisX + offX, b->centreY = axisY;
        g.centreX = g.outer.centreX, g.centreY = g.outer.centreY;
        g.silhouetteScatterPx = 0.5;
        g.silhouetteCentreX = g.outer.centreX - share * offX, g.silhouetteCentreY = g.outer.centreY;
        return interpret(g);
    };
    const Reading onAxis = seenFrom(3), offAxis = seenFrom(300);
    // The same face with the working distance declared: what the reading should come to.
    SpecimenSpec declared;
    declared.n = kN, declared.mmPerPx = kMmPerPx, declared.workingDistanceMm = w;
    const Reading truth = reading::interpret(face(outlineRatioAt(kN, kMu, 0.5, x), false), declared, nullptr,
                                             *frictionModel(kDefaultModel));
    ASSERT_EQ(offAxis.status, Status::Ok) << offAxis.flags;
    EXPECT_NEAR(offAxis.mu, truth.mu, 0.002);
    EXPECT_NEAR(offAxis.reduction, 0.5, 0.003);
    ASSERT_TRUE(onAxis.hasValue());
    EXPECT_GT(onAxis.muSigma, offAxis.muSigma);
    EXPECT_LT(std::fabs(onAxis.mu - truth.mu), 2 * onAxis.muSigma) << "U covers what the image could not tell";
    if (std::fabs(onAxis.mu - truth.mu) > std::max(0.01, 0.05 * truth.mu)) {
        EXPECT_TRUE(onAxis.flags & kNominalFinding) << "a wrong reading warns: " << onAxis.flags;
    }
}

// Where the outline cannot be told from the fixture's shadow the silhouette neither moves the
// reading nor says another height: the height goes unchecked, its U covers 45–55 %, and the
// declared scale goes unchecked too (no_silhouette), as in any view without a silhouette.
TEST(Interpretation, AnAmbiguousOutlineNeitherRescalesNorSaysAnotherHeight)
{
    EndFaceGeometry g = face(0.95, false);
    g.imageFlags |= vision::kImageOutlineAmbiguous;
    const Reading m = interpret(g);
    EXPECT_EQ(m.flags, uint32_t(kFlagNoSilhouette));
    EXPECT_DOUBLE_EQ(m.reduction, 0.5);
    EXPECT_DOUBLE_EQ(m.scaleFactor, 1.0);
    EXPECT_NEAR(m.reductionSigma, kUndeclaredReductionSigma, 1e-9);
    EXPECT_TRUE(m.advice.reductionUnchecked);
}

// A close camera draws the outline's centre towards the optical axis: about the end face's
// centre the one outline smears into two steps, which the mean profile takes for an outline
// and its rival (the reference photographs' photo-007: 11 px). Where vision finds no rival on
// the rays aligned on the fitted outline (kImageOutlineSmeared) and the shift is the one a
// straight close camera makes, the outline is the barrel's and checks the height; a shift
// across the axis is no view's that explains the smear, and the outline stays ambiguous.
TEST(Interpretation, AnOutlineSmearedByTheViewIsTheBarrels)
{
    const double w = 55, share = outlineShiftAt(kN, kMu, 0.5, 10.0 / w);
    const double offX = 220, offY = -90;
    EndFaceGeometry g = closeCameraFace(w, offX, offY);
    g.imageFlags |= vision::kImageOutlineAmbiguous | vision::kImageOutlineSmeared;
    const Reading smeared = interpret(g);
    ASSERT_EQ(smeared.status, Status::Ok) << smeared.flags;
    EXPECT_NEAR(smeared.reduction, 0.5, 0.003);
    EXPECT_FALSE(smeared.advice.reductionUnchecked);

    EndFaceGeometry across = g; // the same shift turned a quarter round
    across.silhouetteCentreX = g.outer.centreX + share * offY;
    across.silhouetteCentreY = g.outer.centreY - share * offX;
    EXPECT_EQ(interpret(across).flags, uint32_t(kFlagNoSilhouette));

    EndFaceGeometry rivalled = g; // a rival on the aligned rays too: the fixture's shadow
    rivalled.imageFlags &= ~uint32_t(vision::kImageOutlineSmeared);
    EXPECT_EQ(interpret(rivalled).flags, uint32_t(kFlagNoSilhouette));
}

TEST(Interpretation, SilhouetteAtItsSizeKeepsTheNominalHalfHeight)
{
    const Reading m = interpret(face(1.0, false));
    ASSERT_NE(m.status, Status::Error);
    EXPECT_NEAR(m.reduction, 0.5, 0.003);
    EXPECT_LT(m.reductionSigma, 0.01);
}

// Seen obliquely from a finite distance, the barrel's widest section (half-way down) reads
// small against the end face's scale: the reading keeps the nominal height rather than
// carrying u to a reduction the view alone explains. Seen straight on, the same silhouette
// means another height (or scale) and moves the reduction.
TEST(Interpretation, SmallSilhouetteInAnObliqueViewIsForeshortening)
{
    const Reading straight = interpret(face(0.95, false));
    const Reading oblique = interpret(face(0.95, true));
    EXPECT_FALSE(oblique.flags & kFlagElliptical) << "a tilt the budget's tilt term covers";
    ASSERT_FALSE(straight.flags & kFlagElliptical);
    EXPECT_GT(std::fabs(straight.reduction - 0.5), 0.01);
    EXPECT_LT(std::fabs(oblique.reduction - 0.5), 0.5 * std::fabs(straight.reduction - 0.5));
    EXPECT_LT(std::fabs(oblique.scaleFactor - 1), 0.5 * std::fabs(straight.scaleFactor - 1))
        << "foreshortening leaves u's scale alone";
    EXPECT_TRUE(straight.flags & kNominalFinding);
    EXPECT_FALSE(oblique.flags & kFlagScaleSuspect) << "the view, not the scale, explains it";
}

// A silhouette is as good as its rays agree. Where a highlight band merges into the outline
// on some rays, their points scatter about the fit by a few per cent and the radius may read
// short by as much: such a silhouette tells the reduction less, and contradicts no scale.
// The same radius from rays that agree to 0.1 % is a contradiction.
TEST(Interpretation, ASilhouetteIsTrustedAsFarAsItsRaysAgree)
{
    EndFaceGeometry tight = face(0.975, false), scattered = face(0.975, false);
    tight.silhouetteScatterPx = 0.001 * tight.rMaxPx;
    scattered.silhouetteScatterPx = 0.02 * scattered.rMaxPx;
    const Reading t = interpret(tight), s = interpret(scattered);
    ASSERT_NE(t.status, Status::Error);
    ASSERT_NE(s.status, Status::Error);
    EXPECT_LT(t.reductionSigma, s.reductionSigma);
    EXPECT_LT(std::fabs(s.reduction - 0.5), std::fabs(t.reduction - 0.5));
    EXPECT_TRUE(t.flags & kNominalFinding);
    EXPECT_FALSE(s.flags & kFlagScaleSuspect) << "a scattered silhouette blames no scale";
    EXPECT_GT(std::fabs(t.rMaxZ), 2 * std::fabs(s.rMaxZ)) << "z is measured against each one's own σ";
}

// A silhouette taken on a wrong edge, a ridge on the barrel just outside the contact edge,
// agrees along the rays like the outline itself. On a wide barrel band (n 0.1, μ 0.25: R_max
// 19 % beyond R_o) it reads 15 % short; taken for a scale error alone it would rescale u by
// as much, with a σ from the scale's prior that does not reach the truth. The wrong-edge
// explanation keeps the reading's σ over what the right silhouette reads.
TEST(Interpretation, ASilhouetteOnAWrongEdgeDoesNotRescaleTheRingUnseen)
{
    constexpr double n = 0.1, mu = 0.25;
    EndFaceGeometry right = face(1.0, false, n, mu), wrong = face(1.0, false, n, mu);
    wrong.rMaxPx = 1.03 * wrong.outer.rEqPx;
    for (EndFaceGeometry *m : {&right, &wrong}) m->silhouetteScatterPx = 0.002 * m->rMaxPx;
    const Reading r = interpret(right, n), w = interpret(wrong, n);
    ASSERT_NE(w.status, Status::Error);
    // At n 0.1, μ 0.25 the silhouette's resolution (≈ 0.005 of reduction) moves μ by half the
    // tolerance, so the right reading may itself be warned of; it is never taken for a wrong edge.
    ASSERT_FALSE(r.flags & kFlagSilhouetteUnreliable);
    EXPECT_EQ(w.status, Status::Warn);
    EXPECT_TRUE(w.flags & kNominalFinding);
    EXPECT_LT(std::fabs(w.mu - r.mu), 2 * w.muSigma) << "μ " << w.mu << " ± " << w.muSigma << " against " << r.mu;
}

// A straight view without a silhouette leaves the height and the declared scale unchecked;
// that is a finding where they move μ, not where μ hardly depends on them. At μ 0.06 the
// undeclared 45–55 % and a scale measured on the fixture (11 % large) stay within the
// tolerance; at μ 0.15 the fixture's scale alone moves μ beyond it.
TEST(Interpretation, NoSilhouetteIsAFindingWhereTheUncheckedInputsMoveMu)
{
    EndFaceGeometry low = face(1.0, false, kN, 0.06), high = face(1.0, false, kN, 0.15);
    low.rMaxPx = high.rMaxPx = 0;
    const Reading l = interpret(low), h = interpret(high);
    EXPECT_EQ(l.status, Status::Ok) << l.flags;
    EXPECT_TRUE(l.advice.reductionUnchecked);
    EXPECT_NEAR(l.reductionSigma, kUndeclaredReductionSigma, 1e-12);
    EXPECT_EQ(h.status, Status::Warn);
    EXPECT_TRUE(h.flags & kFlagNoSilhouette);
}

// A silhouette a little small at a high μ: half height through a scale at the edge of its
// tolerance explains it about as well as a specimen pressed less far, and the reading's μ,
// weighed between the two, stays within the tolerance of μ at half height. The image still
// says another height first among the others, and μ there lies beyond the tolerance: a
// finding (on drawn sets pressed to 48–49 % such readings were 0.012–0.019 off, said ok).
TEST(Interpretation, AnotherHeightTheImageSaysIsAFindingThoughTheMixtureStaysNearHalf)
{
    constexpr double n = 0.35, mu = 0.25;
    EndFaceGeometry g = face(0.99, false, n, mu);
    g.silhouetteScatterPx = 0.5;
    const Reading r = interpret(g, n);
    EXPECT_EQ(r.status, Status::Warn);
    EXPECT_TRUE(r.flags & kFlagReductionNotNominal) << r.flags;
    EXPECT_LT(std::fabs(r.mu - r.nominalMu), 0.05 * r.mu) << "the mixture's μ stays within the tolerance";
}

// A ring the profile alone read (no ray saw the original face's edge) may be the contact
// edge's own fall beside a face as bright as the ring: where the outline does not vouch for
// it, U reaches the μ of a ring as wide as the search looks. Read narrow on a specimen whose
// ring is of μ 0.15, that μ lies within U; the same ring located on the rays keeps its U.
TEST(Interpretation, ARingTheRaysDidNotSeeMayBeWiderThanRead)
{
    EndFaceGeometry g = face(1.0, false);
    g.rMaxPx = 0;                      // nothing to vouch for the ring
    g.inner.rEqPx = g.outer.rEqPx - 6; // the profile's two steps, 6 px apart
    const Reading seen = interpret(g);
    g.imageFlags |= vision::kImageNarrowRingFit;
    const Reading unseen = interpret(g);
    EXPECT_EQ(unseen.status, Status::Warn);
    EXPECT_TRUE(unseen.flags & kFlagNarrowRing);
    EXPECT_DOUBLE_EQ(unseen.mu, seen.mu);
    EXPECT_LT(unseen.mu, kMu - 0.05) << "read low";
    EXPECT_LT(2 * seen.muSigma, kMu - seen.mu) << "the ring as read does not cover the truth";
    EXPECT_GT(2 * unseen.muSigma, kMu - unseen.mu) << "the ring that may be wider does";
    EXPECT_GT(unseen.budget.edges, unseen.budget.reduction);
}

// Two edges closer than twice their blur show one derivative peak: a ring read so is not
// resolved, and the two steps the fit found may be the contact edge's fall and the barrel's
// knee beside a face as bright as the ring. Neither the outline nor a small widening vouches
// for it (a warning, U reaching a ring as wide as the search looks); the same width between
// sharp edges is a ring like any other.
TEST(Interpretation, ARingNarrowerThanTwiceItsBlurIsNotResolved)
{
    EndFaceGeometry g = face(1.0, false);
    g.inner.rEqPx = g.outer.rEqPx - 4.4;
    g.edgeWidthPx = 1.0;
    const Reading sharp = interpret(g);
    EXPECT_FALSE(sharp.flags & kFlagNarrowRing) << sharp.flags;
    g.edgeWidthPx = 2.3;
    const Reading blurred = interpret(g);
    EXPECT_EQ(blurred.status, Status::Warn);
    EXPECT_TRUE(blurred.flags & kFlagNarrowRing) << blurred.flags;
    EXPECT_DOUBLE_EQ(blurred.mu, sharp.mu);
    EXPECT_LT(blurred.mu, kMu - 0.05) << "read low";
    EXPECT_GT(2 * blurred.muSigma, kMu - blurred.mu) << "U covers a ring the fit did not resolve";
}

// An outline on fewer than half the rays was not found: the view is one without a silhouette
// (no_silhouette), not one whose silhouette contradicts the barrel (silhouette_unreliable).
TEST(Interpretation, AnOutlineOnFewRaysIsNoSilhouette)
{
    EndFaceGeometry g = face(1.0, false);
    g.silhouetteCoverage = 0.3;
    const Reading m = interpret(g);
    EXPECT_TRUE(m.flags & kFlagNoSilhouette) << m.flags;
    EXPECT_FALSE(m.flags & kFlagSilhouetteUnreliable);
    EXPECT_DOUBLE_EQ(m.scaleFactor, 1.0);
}

} // namespace
// Without a silhouette nothing checks the scale or the final height, in a tilted view as in a
// straight one: a finding (a scale measured on the fixture would otherwise pass unseen). The
// budget keeps the undeclared reduction's whole range and the advice says the height went
// unchecked.
TEST(Interpretation, NoSilhouetteLeavesScaleAndHeightUnchecked)
{
    EndFaceGeometry straight = face(1.0, false), oblique = face(1.0, true);
    straight.rMaxPx = oblique.rMaxPx = 0;
    const Reading s = interpret(straight), o = interpret(oblique);
    EXPECT_TRUE(s.flags & kFlagNoSilhouette);
    EXPECT_TRUE(o.flags & kFlagNoSilhouette);
    EXPECT_NEAR(o.reductionSigma, kUndeclaredReductionSigma, 1e-12);
    EXPECT_TRUE(o.advice.reductionUnchecked);
    EXPECT_EQ(o.advice.input, AdviceInput::HFinal);
    const Reading seen = interpret(face(1.0, true));
    EXPECT_FALSE(seen.advice.reductionUnchecked) << "a silhouette checked the height";
    EXPECT_LT(seen.muSigma, o.muSigma);
}

} // namespace icacam::reading
