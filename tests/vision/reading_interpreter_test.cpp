// The interpretation on measured faces built from the FE's own radii: what a silhouette that
// reads small is taken for, in a straight view and in an oblique one.
#include <gtest/gtest.h>

#include <cmath>

#include "vision/model/friction_models.h"
#include "vision/model/radii_consistency.h"
#include "vision/reading_interpreter.h"

namespace icacam::vision {
namespace {

constexpr double kN = 0.25, kMu = 0.15, kMmPerPx = 0.02;

// A face at 50 % reduction as the pipeline would hand it over, the silhouette scaled by
// rMaxFactor; an oblique view gives both boundaries the same ellipse.
Measurement face(double rMaxFactor, bool oblique)
{
    double ri = 0, ro = 0, rm = 0;
    EXPECT_TRUE(feRadiusAt(FeRadius::Inner, kN, kMu, 0.5, &ri));
    EXPECT_TRUE(feRadiusAt(FeRadius::Outer, kN, kMu, 0.5, &ro));
    EXPECT_TRUE(feRadiusAt(FeRadius::Max, kN, kMu, 0.5, &rm));
    Measurement m;
    m.status = Status::Error; // as measureFace leaves a found face
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
    m.rMaxPx = rm * rMaxFactor / kMmPerPx;
    m.silhouetteCoverage = 1;
    m.edgeWidthPx = 1;
    return m;
}

Measurement interpret(Measurement m)
{
    SpecimenSpec spec;
    spec.n = kN;
    spec.mmPerPx = kMmPerPx;
    interpretEndFace(spec, *frictionModel(kDefaultModel), &m);
    return m;
}

TEST(ReadingInterpreter, SilhouetteAtItsSizeKeepsTheNominalHalfHeight)
{
    const Measurement m = interpret(face(1.0, false));
    ASSERT_NE(m.status, Status::Error);
    EXPECT_NEAR(m.reduction, 0.5, 0.003);
    EXPECT_LT(m.reductionSigma, 0.01);
}

// Seen obliquely from a finite distance, the barrel's widest section (half-way down) reads
// small against the end face's scale: the reading keeps the nominal height rather than
// carrying u to a reduction the view alone explains. Seen straight on, the same silhouette
// means another height (or scale) and moves the reduction.
TEST(ReadingInterpreter, SmallSilhouetteInAnObliqueViewIsForeshortening)
{
    const Measurement straight = interpret(face(0.95, false));
    const Measurement oblique = interpret(face(0.95, true));
    ASSERT_TRUE(oblique.flags & kFlagElliptical);
    ASSERT_FALSE(straight.flags & kFlagElliptical);
    EXPECT_GT(std::fabs(straight.reduction - 0.5), 0.01);
    EXPECT_LT(std::fabs(oblique.reduction - 0.5), 0.5 * std::fabs(straight.reduction - 0.5));
    EXPECT_LT(std::fabs(oblique.scaleFactor - 1), 0.5 * std::fabs(straight.scaleFactor - 1))
        << "foreshortening leaves u's scale alone";
    EXPECT_TRUE(straight.flags & kFlagScaleSuspect);
    EXPECT_FALSE(oblique.flags & kFlagScaleSuspect) << "the view, not the scale, is named";
}

// A silhouette is as good as its rays agree. Where a highlight band merges into the outline
// on some rays, their points scatter about the fit by a few per cent and the radius may read
// short by as much: such a silhouette tells the reduction less, and contradicts no scale.
// The same radius from rays that agree to 0.1 % is a contradiction.
TEST(ReadingInterpreter, ASilhouetteIsTrustedAsFarAsItsRaysAgree)
{
    Measurement tight = face(0.975, false), scattered = face(0.975, false);
    tight.silhouetteScatterPx = 0.001 * tight.rMaxPx;
    scattered.silhouetteScatterPx = 0.02 * scattered.rMaxPx;
    const Measurement t = interpret(tight), s = interpret(scattered);
    ASSERT_NE(t.status, Status::Error);
    ASSERT_NE(s.status, Status::Error);
    EXPECT_LT(t.reductionSigma, s.reductionSigma);
    EXPECT_LT(std::fabs(s.reduction - 0.5), std::fabs(t.reduction - 0.5));
    EXPECT_TRUE(t.flags & kFlagScaleSuspect);
    EXPECT_FALSE(s.flags & kFlagScaleSuspect);
    EXPECT_GT(std::fabs(t.rMaxZ), 2 * std::fabs(s.rMaxZ)) << "z is measured against each one's own σ";
}

} // namespace
} // namespace icacam::vision
