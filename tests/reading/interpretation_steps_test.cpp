// Each step of the interpretation alone (reading/interpretation_steps.h), on faces whose
// answer is known without running the rest.
#include <gtest/gtest.h>

#include <cmath>

#include "friction/friction_models.h"
#include "friction/paper_model.h"
#include "reading/interpretation_steps.h"

namespace icacam::reading {
namespace {

using vision::BoundaryFit;
using vision::EndFaceGeometry;

constexpr double kMmPerPx = 0.02;

EndFaceGeometry circularFace(double riPx, double roPx)
{
    EndFaceGeometry g;
    g.error = ErrorCode::None;
    g.centreX = 700, g.centreY = 500;
    for (BoundaryFit *b : {&g.inner, &g.outer}) {
        b->coverage = 1, b->contrast = 40, b->rEqSigmaPx = 0.05, b->scatterPx = 0.3;
        b->centreX = 700, b->centreY = 500;
    }
    g.inner.rEqPx = g.inner.a0 = riPx;
    g.outer.rEqPx = g.outer.a0 = roPx;
    g.rMaxPx = 1.08 * roPx;
    g.silhouetteCoverage = 1;
    g.edgeWidthPx = 1;
    return g;
}

SpecimenSpec spec(double hFinalMm = 0)
{
    SpecimenSpec s;
    s.n = 0.25, s.mmPerPx = kMmPerPx, s.hFinalMm = hFinalMm;
    return s;
}

TEST(AssumedReduction, DeclaredHeightOrTheNominalHalfWithTheUndeclaredPrior)
{
    const AssumedReduction none = assumedReduction(spec());
    EXPECT_FALSE(none.declared);
    EXPECT_EQ(none.r, 0.5);
    EXPECT_EQ(none.sigma, kUndeclaredReductionSigma);
    const AssumedReduction d = assumedReduction(spec(7.2));
    EXPECT_TRUE(d.declared);
    EXPECT_NEAR(d.r, 1 - 7.2 / 15, 1e-12);
    EXPECT_NEAR(d.sigma, 0.05 / 15, 1e-12);
    EXPECT_FALSE(assumedReduction(spec(15.5)).declared) << "a final height above h0 is not a reduction";
}

TEST(PlaneMapping, WithoutCalibrationTheDeclaredScale)
{
    const EndFaceGeometry g = circularFace(250, 300);
    const PlaneMapping p = mapFace(g, spec(), nullptr, assumedReduction(spec()));
    ASSERT_TRUE(p.valid);
    EXPECT_DOUBLE_EQ(p.face.rInnerMm, 250 * kMmPerPx);
    EXPECT_DOUBLE_EQ(p.face.rOuterMm, 300 * kMmPerPx);
    EXPECT_DOUBLE_EQ(p.face.uMm, 50 * kMmPerPx);
    EXPECT_DOUBLE_EQ(p.face.rMaxMm, g.rMaxPx * kMmPerPx);
    EXPECT_EQ(p.scaleRelSigma, spec().tolerances.scaleRel);
    EXPECT_LT(p.centreOffsetPx, 0) << "concentricity is judged in the image";
}

TEST(PlaneMapping, ThroughACalibrationTheEndFacePlane)
{
    // A pinhole straight above the fixture 100 mm away: the end face 7.5 mm off it is mapped
    // at about 0.05 mm per pixel, and the plane's height uncertainty enters the scale's σ.
    vision::PlaneCalibration cal;
    cal.fx = cal.fy = 2000, cal.cx = 700, cal.cy = 500;
    cal.t[2] = 100;
    const EndFaceGeometry g = circularFace(250, 300);
    const PlaneMapping p = mapFace(g, spec(), &cal, assumedReduction(spec()));
    ASSERT_TRUE(p.valid);
    EXPECT_NEAR(p.mmPerPx, 0.05, 0.005);
    EXPECT_NEAR(p.face.uMm, 50 * p.mmPerPx, 1e-3);
    EXPECT_GT(p.scaleRelSigma, spec().tolerances.calibrationScaleRel);
    EXPECT_GE(p.centreOffsetPx, 0) << "concentricity is judged in the plane";
}

TEST(EdgeSigma, TheFitsAFloorAndAnUncalibratedTilt)
{
    EndFaceGeometry g = circularFace(250, 300);
    const PlaneMapping round = mapFace(g, spec(), nullptr, assumedReduction(spec()));
    const EdgeSigma e = edgeSigma(g, round, false);
    EXPECT_NEAR(e.uSigmaMm, std::sqrt(2 * 0.05 * 0.05 + 2 * 0.01) * kMmPerPx, 1e-12);
    EXPECT_GT(e.uSigmaEdgesMm, e.uSigmaMm) << "the edge model's error is added";
    EXPECT_FALSE(e.sharedEllipse);
    g.inner.ellipticity = g.outer.ellipticity = 0.05, g.inner.axisDeg = g.outer.axisDeg = 30;
    const PlaneMapping oval = mapFace(g, spec(), nullptr, assumedReduction(spec()));
    const EdgeSigma tilted = edgeSigma(g, oval, false);
    EXPECT_TRUE(tilted.sharedEllipse);
    EXPECT_GT(tilted.uSigmaEdgesMm, e.uSigmaEdgesMm);
    EXPECT_EQ(edgeSigma(g, oval, true).uSigmaEdgesMm, e.uSigmaEdgesMm) << "a calibration took the tilt out";
}

TEST(ImageChecks, EachConditionRaisesItsFlag)
{
    const AssumedReduction r = assumedReduction(spec());
    auto flagsOf = [&](const EndFaceGeometry &g) {
        const PlaneMapping p = mapFace(g, spec(), nullptr, r);
        double offset = 0;
        return imageChecks(g, p, edgeSigma(g, p, false), 10, &offset);
    };
    EndFaceGeometry g = circularFace(250, 300);
    EXPECT_EQ(flagsOf(g), 0u);
    g.inner.coverage = 0.4;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagLowCoverage));
    g = circularFace(250, 300), g.inner.contrast = -3;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagLowContrast));
    // Located but not told from a turning mark's step of as much (6.2 grey levels read so).
    g.inner.contrast = 7;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagLowContrast));
    g.inner.contrast = -9;
    EXPECT_EQ(flagsOf(g), 0u);
    g = circularFace(250, 300), g.edgeWidthPx = 3;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagBlurred));
    // A sharp original face's edge beside a wide contact edge: the optics are sharp, the width
    // is the barrel's (its ramp measured within reach judges it), or the inner edge's flank.
    g.innerEdgeWidthPx = 1.2;
    EXPECT_EQ(flagsOf(g), 0u);
    g.innerEdgeWidthPx = 2.9;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagBlurred));
    g = circularFace(250, 300), g.inner.centreX += 6;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagCentreOffset));
    g = circularFace(250, 252);
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagNarrowRing));
    g = circularFace(250, 300), g.imageFlags = vision::kImageSpecimenClipped;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagSpecimenClipped));
    // A shared ellipse a tilt explains is covered by the edges' tilt term; beyond it, a finding.
    g = circularFace(250, 300), g.inner.ellipticity = g.outer.ellipticity = 0.03;
    g.inner.axisDeg = g.outer.axisDeg = 30;
    EXPECT_EQ(flagsOf(g), 0u);
    g.inner.ellipticity = g.outer.ellipticity = 0.08;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagElliptical));
    // A contact edge about as wide as the original face's is a step; one wider by a ramp of
    // 2 px is the barrel's shading falling away beyond it.
    g = circularFace(250, 300), g.innerEdgeWidthPx = 1.2, g.contactRampPx = 1.0;
    EXPECT_EQ(flagsOf(g), 0u);
    g.contactRampPx = 2.0;
    EXPECT_EQ(flagsOf(g), uint32_t(kFlagContactEdgeRamp));
    // Just past the knee's line the width is still within its own repeatability of a step's (a
    // reference photograph's 1.58 px reads up to 1.65 on fresh sensor noise): no finding.
    g.contactRampPx = 1.7;
    EXPECT_GT(g.contactRampPx, vision::kContactRampPx);
    EXPECT_EQ(flagsOf(g), 0u);
}

// Where the contact edge ramps away, R_o may lie anywhere within the ramp: u's error takes it
// (in millimetres at the plane's scale); a step's edge keeps the fits' and the edge model's.
TEST(EdgeSigma, AContactEdgeOnARampWidensU)
{
    const AssumedReduction r = assumedReduction(spec());
    EndFaceGeometry g = circularFace(250, 300);
    const PlaneMapping p = mapFace(g, spec(), nullptr, r);
    const double step = edgeSigma(g, p, false).uSigmaEdgesMm;
    g.innerEdgeWidthPx = 1.2, g.contactRampPx = 1.0;
    EXPECT_EQ(edgeSigma(g, p, false).uSigmaEdgesMm, step);
    g.contactRampPx = 2.5;
    const double ramp = edgeSigma(g, p, false).uSigmaEdgesMm;
    EXPECT_NEAR(ramp, std::hypot(step, 2.5 * p.mmPerPx), 1e-12);
}

// Segment frames whose tilt confirms the contact edge resolve what the single frame left open
// (its ramp, which edge ends the flat face), u's error taking the tilt's instead of the ramp;
// a tilt moving the edge resolves the ramp; one disagreeing within its own error is a finding.
TEST(ImageChecks, TheTiltResolvesOrDisagrees)
{
    const AssumedReduction r = assumedReduction(spec());
    auto checked = [&](const EndFaceGeometry &g, EdgeSigma *e) {
        const PlaneMapping p = mapFace(g, spec(), nullptr, r);
        *e = edgeSigma(g, p, false);
        double offset = 0;
        return imageChecks(g, p, *e, 10, &offset);
    };
    EndFaceGeometry g = circularFace(250, 300);
    g.innerEdgeWidthPx = 1.2, g.contactRampPx = 2.5;
    g.imageFlags = vision::kImageContactEdgeUndecided;
    EdgeSigma single, confirmed, moved;
    EXPECT_EQ(checked(g, &single), uint32_t(kFlagContactEdgeRamp | kFlagContactEdgeUndecided));
    g.imageFlags |= vision::kImageTiltConfirms, g.tiltSigmaPx = 1.0;
    EXPECT_EQ(checked(g, &confirmed), 0u);
    EXPECT_LT(confirmed.uSigmaEdgesMm, single.uSigmaEdgesMm) << "a 1 px knee instead of a 2.5 px ramp";
    g.imageFlags = vision::kImageContactEdgeUndecided | vision::kImageContactEdgeByTilt;
    EXPECT_EQ(checked(g, &moved), uint32_t(kFlagContactEdgeUndecided)) << "R_i is the single frame's";
    g.imageFlags = vision::kImageTiltDisagrees;
    EXPECT_EQ(checked(g, &moved), uint32_t(kFlagContactEdgeRamp | kFlagTiltDisagrees));
}

// A ring read narrow is a finding unless the outline agrees with the μ it reads and the
// widening a narrow read may carry cannot move μ beyond the tolerance.
TEST(NarrowRing, CorroboratedByTheOutlineWhereItsWideningCannotMoveMu)
{
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    const SpecimenSpec s = spec();
    const MuFunction F(s, model);
    const double u = 0.06, mu = F.at(u, 0.5, s.n), tol = s.tolerance.at(mu);
    SilhouetteObservation agrees;
    agrees.usable = true, agrees.rMaxZ = 0.5;
    const double small = 0.2 * u, large = 0.9 * u;
    ASSERT_LT(std::fabs(F.at(u - small, 0.5, s.n) - mu), tol) << "the test needs a harmless widening";
    ASSERT_GT(std::fabs(F.at(u - large, 0.5, s.n) - mu), tol) << "and one that moves μ beyond it";
    EXPECT_TRUE(narrowRingCorroborated(F, s, u, 0.5, mu, small, &agrees));
    EXPECT_FALSE(narrowRingCorroborated(F, s, u, 0.5, mu, large, &agrees));
    EXPECT_FALSE(narrowRingCorroborated(F, s, u, 0.5, mu, small, nullptr)) << "no outline to agree";
    SilhouetteObservation disagrees = agrees;
    disagrees.rMaxZ = -3.0; // the barrel of another μ: the ring may be two other steps
    EXPECT_FALSE(narrowRingCorroborated(F, s, u, 0.5, mu, small, &disagrees));
    SilhouetteObservation unusable = agrees;
    unusable.usable = false;
    EXPECT_FALSE(narrowRingCorroborated(F, s, u, 0.5, mu, small, &unusable));
}

TEST(SilhouetteObservation, NoneFoundAFittingOneAndOneOutsideTheBarrel)
{
    const SpecimenSpec s = spec();
    const AssumedReduction r = assumedReduction(s);
    FaceInMm face{5.0, 6.0, 0, 1.0};
    EXPECT_EQ(observeSilhouette(face, 1, 0, 0, s, r, 0.15, CameraDistance{}).flags, uint32_t(kFlagNoSilhouette));
    face.rMaxMm = 6.6;
    const SilhouetteObservation fits = observeSilhouette(face, 1, 0, 330, s, r, 0.15, CameraDistance{});
    EXPECT_TRUE(fits.usable);
    EXPECT_GT(fits.beta, 0.1) << "a further pressed barrel is wider";
    face.rMaxMm = 6.01; // hugging the contact edge: a highlight's flank, not the barrel
    const SilhouetteObservation flank = observeSilhouette(face, 1, 0, 300.5, s, r, 0.15, CameraDistance{});
    EXPECT_FALSE(flank.usable);
    EXPECT_TRUE(flank.flags & kFlagSilhouetteUnreliable);
}

TEST(SilhouettePosterior, DeclaredHeightCorrectsTheScaleAndAContradictionWidensBoth)
{
    ScaleAndReduction prior;
    prior.pk = 0.005 * 0.005, prior.pr = 0.0033 * 0.0033;
    SilhouetteObservation o;
    o.usable = true, o.beta = 0.6, o.d = 0.004;
    uint32_t flags = 0;
    const ScaleAndReduction small = silhouettePosterior(prior, o, 0.003, true, false, &flags);
    EXPECT_GT(small.dk, 0);
    EXPECT_LT(small.pk, prior.pk) << "an agreeing silhouette narrows the scale";
    o.d = 0.1; // far past 3 σ
    const ScaleAndReduction far = silhouettePosterior(prior, o, 0.003, true, false, &flags);
    EXPECT_EQ(far.dk, 0) << "neither declared value is corrected";
    EXPECT_GE(far.pk, o.d * o.d);
    EXPECT_EQ(flags, 0u);
}

TEST(SilhouettePosterior, WithoutHeightAnAgreeingSilhouettePinsTheNominalHalf)
{
    ScaleAndReduction prior;
    prior.pk = 0.005 * 0.005, prior.pr = kUndeclaredReductionSigma * kUndeclaredReductionSigma;
    SilhouetteObservation o;
    o.usable = true, o.beta = 0.6, o.d = 0.0;
    uint32_t flags = 0;
    const ScaleAndReduction p = silhouettePosterior(prior, o, 0.004, false, false, &flags);
    EXPECT_LT(std::sqrt(p.pr), 0.5 * kUndeclaredReductionSigma);
    EXPECT_NEAR(p.dr, 0, 1e-3);
}

TEST(ReadMu, ACarryingModelReadsAtTheReductionAndThePaperCarriesInItsBudget)
{
    const friction::FrictionModel &carrying = *friction::frictionModel(friction::kDefaultModel);
    const friction::PaperModel paper;
    const SpecimenSpec s = spec();
    const MuFunction fc(s, carrying), fp(s, paper);
    const MuReading c = readMu(fc, carrying, s, 0.5, 0.5, false);
    EXPECT_NEAR(c.estimate.mu, fc.at(0.5, 0.5, 0.25), 1e-12);
    EXPECT_EQ(c.bias, 0);
    const MuReading p = readMu(fp, paper, s, 0.5, 0.48, false);
    EXPECT_NEAR(p.estimate.mu, paper.estimate({0.5, 0.25, 0, 10, 15, 0}).mu, 1e-12);
    EXPECT_NE(p.bias, 0) << "the carry from 48 % to 50 % is the paper model's bias";
}

TEST(Budget, ComponentsFollowTheirInputsAndCombineInQuadrature)
{
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    SpecimenSpec s = spec(7.5);
    const MuFunction F(s, model);
    ScaleAndReduction sr;
    sr.pk = 0.005 * 0.005, sr.pr = 0.0033 * 0.0033;
    const UncertaintyBudget b = budgetOf(F, model, s, 0.5, 0.5, sr, 0.003, 0);
    EXPECT_GT(b.edges, 0);
    EXPECT_GT(b.scale, 0);
    EXPECT_GT(b.n, 0);
    EXPECT_NEAR(
        combinedSigma(b),
        std::sqrt(b.edges * b.edges + b.scale * b.scale + b.reduction * b.reduction + b.n * b.n + b.model * b.model),
        1e-15);
    s.tolerances.n = 0.02;
    const MuFunction F2(s, model);
    EXPECT_NEAR(budgetOf(F2, model, s, 0.5, 0.5, sr, 0.003, 0).n / b.n, 2.0, 0.2) << "n's part scales with its σ";
}

TEST(Status, FromTheChecksAloneAndTheToleranceDecisionApart)
{
    SpecimenSpec s = spec();
    Reading r;
    r.mu = 0.15, r.muSigma = 0.002;
    r.budget.edges = 0.002;
    decideStatus(s, 0, &r);
    EXPECT_EQ(r.status, Status::Ok);
    EXPECT_EQ(r.decision, Decision::Within);
    EXPECT_NEAR(r.toleranceMu, 0.01, 1e-12);
    decideStatus(s, kFlagBlurred, &r);
    EXPECT_EQ(r.status, Status::Warn);
    // The model's own error past the tolerance: U beyond it, and still ok.
    r.muSigma = 0.008, r.budget.model = 0.007;
    decideStatus(s, 0, &r);
    EXPECT_EQ(r.status, Status::Ok);
    EXPECT_EQ(r.flags, 0u);
    EXPECT_EQ(r.decision, Decision::Beyond);
    EXPECT_NEAR(r.expanded(), 0.016, 1e-12);
}

// Without a final height, explanations of the silhouette are held against the reading's μ: one
// that moves μ beyond the tolerance is named, an agreeing silhouette leaves the reading ok.
TEST(NominalCheck, AnExplanationBeyondTheToleranceIsAFinding)
{
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    const SpecimenSpec s = spec();
    const MuFunction F(s, model);
    const double u = 0.5, mu = F.at(u, 0.5, s.n);
    Explanations why;
    why.weight[Explanations::Nominal] = 1;
    double nominal = 0;
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), 0u);
    EXPECT_NEAR(nominal, mu, 1e-12);
    // Pressed to 55 %: the carry moves μ by more than the tolerance.
    ASSERT_GT(std::fabs(F.at(u, 0.55, s.n) - mu), s.tolerance.at(mu)) << "the test needs a step beyond it";
    why.weight[Explanations::Nominal] = 0.3;
    why.weight[Explanations::OtherHeight] = 0.7;
    why.post[Explanations::OtherHeight].dr = 0.05;
    EXPECT_EQ(nominalCheck(F, s, u, F.at(u, 0.55, s.n), &why, &nominal), uint32_t(kFlagReductionNotNominal));
    // A scale 20 % off explains it best: the scale is named.
    why.weight[Explanations::OtherHeight] = 0.1;
    why.weight[Explanations::ScaleOff] = 0.6;
    why.post[Explanations::ScaleOff].dk = 0.2;
    const double rescaled = F.at(u * std::exp(-0.2), 0.5, s.n);
    ASSERT_GT(std::fabs(rescaled - mu), s.tolerance.at(mu));
    EXPECT_EQ(nominalCheck(F, s, u, rescaled, &why, &nominal), uint32_t(kFlagScaleSuspect));
    // An explanation that keeps almost no weight is not held against the reading.
    why = {};
    why.weight[Explanations::Nominal] = 0.99, why.weight[Explanations::OtherHeight] = 0.01;
    why.post[Explanations::OtherHeight].dr = 0.05;
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), 0u);
}

// A silhouette that agrees with half height leaves the reading ok however wide the spread it
// leaves (that is U's, and the decision's); where nothing checked the height, the chance that
// μ lies beyond the tolerance under the priors is the finding.
TEST(NominalCheck, TheSpreadAnAgreeingSilhouetteLeavesIsUsNotAFinding)
{
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    const SpecimenSpec s = spec();
    const MuFunction F(s, model);
    const double u = 0.5, mu = F.at(u, 0.5, s.n);
    Explanations why;
    why.weight[Explanations::Nominal] = 0.5, why.weight[Explanations::OtherHeight] = 0.5;
    why.post[Explanations::OtherHeight].pr = 0.02 * 0.02; // centred on half height, wide
    double nominal = 0;
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), 0u);
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal, true), uint32_t(kFlagReductionNotNominal));
}

// Where the image left a telecentric and a close view open and each reads its own height, the
// share of the weight whose μ lies beyond the tolerance is the chance the reading is wrong:
// over 15 % a finding, and where that share lies in one view alone, the camera's distance
// decides it; a view that reads the reading's height is no finding however wide it is.
TEST(NominalCheck, AViewThatReadsAnotherHeightNamesTheWorkingDistance)
{
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    const SpecimenSpec s = spec();
    const MuFunction F(s, model);
    const double u = 0.5, mu = F.at(u, 0.5, s.n);
    ASSERT_GT(std::fabs(F.at(u, 0.53, s.n) - mu), s.tolerance.at(mu)) << "the test needs a view apart";
    Explanations why;
    why.weight[Explanations::Nominal] = 1;
    why.viewCount = 2;
    why.partWeight[0][Explanations::Nominal] = 0.7;
    why.partWeight[1][Explanations::Nominal] = 0.3;
    why.part[1][Explanations::Nominal].pr = 0.02 * 0.02;
    double nominal = 0;
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), 0u);
    why.part[1][Explanations::Nominal].dr = 0.03; // the close camera reads 53 %
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), uint32_t(kFlagWorkingDistanceDecides));
    why.partWeight[0][Explanations::Nominal] = 0.9, why.partWeight[1][Explanations::Nominal] = 0.1;
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), 0u) << "a view with a tenth of the weight";
    why.partWeight[0][Explanations::Nominal] = 0.5, why.partWeight[1][Explanations::Nominal] = 0.3;
    why.partWeight[0][Explanations::OtherHeight] = 0.2, why.part[0][Explanations::OtherHeight].dr = 0.03;
    why.weight[Explanations::OtherHeight] = 0.2, why.post[Explanations::OtherHeight].dr = 0.03;
    EXPECT_EQ(nominalCheck(F, s, u, mu, &why, &nominal), uint32_t(kFlagReductionNotNominal))
        << "both views hold another height open";
}

// The advice names the declared input that shrinks U the most: the final height where the
// undeclared reduction leads, none where the model's own error does.
TEST(Advice, NamesTheInputThatShrinksUTheMost)
{
    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    const SpecimenSpec s = spec();
    const MuFunction F(s, model);
    ScaleAndReduction wide;
    wide.pk = 0.005 * 0.005, wide.pr = kUndeclaredReductionSigma * kUndeclaredReductionSigma;
    const Advice a = adviseInput(F, model, s, 0.5, 0.5, wide, 0.003, 0, false, false, 0.005);
    EXPECT_EQ(a.input, AdviceInput::HFinal);
    EXPECT_LT(a.uThen, 0.7 * a.uNow);
    EXPECT_NEAR(a.uNow, 2 * combinedSigma(budgetOf(F, model, s, 0.5, 0.5, wide, 0.003, 0)), 1e-12);
    // Declared to a micrometer, n and the scale close: nothing declared shrinks U by a tenth.
    SpecimenSpec tight = spec(7.5);
    tight.tolerances.hFinalMm = 0.01, tight.tolerances.n = 0.003, tight.tolerances.scaleRel = 0.001;
    const MuFunction G(tight, model);
    ScaleAndReduction known;
    known.pk = 0.001 * 0.001, known.pr = (0.01 / 15) * (0.01 / 15);
    const Advice none = adviseInput(G, model, tight, 0.5, 0.5, known, 0.001, 0, true, false, 0.001);
    EXPECT_EQ(none.input, AdviceInput::None);
    EXPECT_TRUE(none.modelLeads);
    EXPECT_EQ(none.uThen, none.uNow);
}

// Where the image weighed the camera's distance and that left the scale and the height wide,
// declaring working_distance_mm is advised with the U it leaves: the close camera's view
// without the telecentric one, the barrel's shape as open as the image left it. A view that
// was declared, or one the image found telecentric, has no such advice.
TEST(Advice, NamesTheWorkingDistanceWhereTheImageWeighedIt)
{
    OutlineView declaredView;
    OutlineView asDeclared;
    EXPECT_FALSE(declaredDistanceView(declaredView, &asDeclared));
    OutlineView telecentric;
    telecentric.estimated = true;
    EXPECT_FALSE(declaredDistanceView(telecentric, &asDeclared));
    OutlineView both;
    both.estimated = true, both.count = 2;
    both.weight[0] = 0.4, both.weight[1] = 0.6;
    both.offset[1] = -0.045, both.var[1] = 0.012 * 0.012;
    ASSERT_TRUE(declaredDistanceView(both, &asDeclared));
    EXPECT_EQ(asDeclared.count, 1);
    EXPECT_DOUBLE_EQ(asDeclared.offset[0], -0.045);
    EXPECT_DOUBLE_EQ(asDeclared.var[0], 0.012 * 0.012);

    const friction::FrictionModel &model = *friction::frictionModel(friction::kDefaultModel);
    const SpecimenSpec s = spec(7.5);
    const MuFunction F(s, model);
    ScaleAndReduction open; // the scale wide where the view was not known
    open.pk = 0.04 * 0.04, open.pr = (0.05 / 15) * (0.05 / 15);
    ScaleAndReduction pinned = open;
    pinned.pk = 0.005 * 0.005;
    const Advice a = adviseInput(F, model, s, 0.5, 0.5, open, 0.003, 0, true, false, 0.005, &pinned);
    EXPECT_EQ(a.input, AdviceInput::WorkingDistance);
    EXPECT_LT(a.uThen, 0.9 * a.uNow);
    EXPECT_NE(adviseInput(F, model, s, 0.5, 0.5, open, 0.003, 0, true, false, 0.005).input,
              AdviceInput::WorkingDistance);
}

} // namespace
} // namespace icacam::reading
