#include "reading/interpretation_steps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "friction/outline_ratio.h"
#include "friction/radii_consistency.h"
#include "vision/ray_capacity.h"

namespace icacam::reading {

using friction::FrictionModel;
using friction::ModelEstimate;
using vision::BoundaryFit;
using vision::EndFaceGeometry;
using vision::PlaneCalibration;

namespace {

// A barrel's silhouette lies outside the contact edge, and not far: R_max/R_o spans
// 1.02–1.15 over the FE's (n, μ) at 40–60 % reduction. Outside these bounds the edge taken
// is a highlight's flank, the fixture or a second edge, not the barrel.
constexpr double kSilhouetteOverContactMin = 1.005, kSilhouetteOverContactMax = 1.3;
// The per-ray silhouette fit must see the barrel on half the rays at least.
constexpr double kSilhouetteMinCoverage = 0.5;
// Beyond 3 σ the silhouette contradicts a declared final height and scale outright.
constexpr double kContradictionChi2 = 9.0;
// Without a declared final height the silhouette weighs three explanations, equally likely
// beforehand: the test's nominal half height (a press stopped at it: σ 0.003, 0.045 mm on
// 15 mm) with the scale as declared; the specimen pressed to another height (the undeclared
// reduction's prior, the scale within its tolerance); or the nominal height read through a
// scale measured on the fixture rather than the end face. The fixture lies the end face's
// height h farther from the camera, so such a scale is always too large: by ln(WD / (WD − h)),
// 5–18 % for h = 7.5 mm at 45–150 mm working distance (mean 0.115, σ 0.037 over that range).
// The barrel's widest section lies h/2 below the end face, between the two planes: its
// outline is read too large by about half as much (kSilhouetteScaleShare), not by the whole
// scale error. Where the silhouette agrees with half height the first dominates and the
// reduction is known to the press's tolerance; where it does not, the others take over, and
// the mixture's spread covers the step between them.
constexpr double kNominalReductionSigma = 0.003;
constexpr double kFixtureScaleMean = 0.115, kFixtureScaleSigma = 0.037;
constexpr double kSilhouetteScaleShare = 0.5;
// A view the image shows to be oblique (the boundaries share an ellipse, or their centres
// part) comes from a camera close and off-axis: it sees the barrel's widest section, half-way
// down, from farther than the end face, and a short lens's barrel distortion shrinks it
// further. There a fourth explanation joins: the nominal half height with the declared
// scale and a silhouette read 5 % ± 4 % small (3.75 mm farther at 70–150 mm is 2.5–5 %,
// distortion at the barrel's radius up to a few per cent more). It leaves u's scale alone.
constexpr double kForeshortenMean = -0.05, kForeshortenSigma = 0.04;
// Where the barrel is about as bright as the background, its outline is faint and a ridge or
// reflection on the barrel, inside it, can be the clearest step on every ray: the silhouette
// is then taken on a wrong edge, with little scatter, anywhere from just outside the contact
// edge to a few per cent inside the outline (rendered straight views: 5 in about 800 readings,
// 7–17 % short). Such a silhouette says nothing about scale or reduction; read as a scale
// error it would rescale u by as much. A last explanation therefore keeps the priors, with a
// likelihood uniform over those discrepancies and a prior probability of 2 %. Nearer the
// outline than kMisreadMinInside the rays' scatter measures what a highlight does.
constexpr double kMisreadPrior = 0.02;
constexpr double kMisreadMinInside = 0.03;
// The outline a camera sees lies inside R_max (friction/outline_ratio.h), by a known amount
// where the working distance is declared (to 5 %: a ruler from the lens to the end face).
// Where it is not, the image's outline centre weighs it (below); where that cannot tell (an
// end face on the axis) a telecentric and a close view both stay open, each explanation is
// weighed under both, and the silhouette checks the height only as far as they agree. Taken as telecentric
// throughout, a close camera's outline would read as a specimen pressed less far, and a
// specimen pressed further seen from a close camera would pass for one at half height (a
// rendered one at 52.9 % reads 49.3 %, ok and 0.032 high, that way).
constexpr double kWorkingDistanceRelSigma = 0.05;
// The image's own word on W (CameraDistance): the perspective share s (the outline's centre
// drawn towards the optical axis per unit of the end face's distance from it) weighed on
// kShareSteps cells up to kShareMax (the FE's barrel seen from 40 mm: 0.03–0.07), a
// telecentric view (a telecentric lens, a far camera, a drawing) half the prior. The
// centres' error per axis: their fits' and a floor of 0.4 px (the development set's
// telecentric drawings: the outline's centre lies 0.3–0.7 px off the end face's along and
// across the axis where the rays agree; on the photographic bench the pipeline's outline
// centre lies within 0.1–0.4 px of the rendered one). The optical axis: the frame's centre
// to 1 % of its size (a lens seated on a sensor). A centre misread on some rays: 3 %,
// 5 px or 5 % of the distance from the axis.
constexpr int kShareSteps = 35, kReachSteps = 10;
constexpr double kShareMax = 0.07;
constexpr double kTelecentricPrior = 0.5, kMinViewWeight = 0.001;
constexpr double kShiftFloorPx = 0.4, kAxisRelSigma = 0.01, kShiftOutlierSigmas = 3;
constexpr double kMisreadShift = 0.03, kMisreadShiftPx = 5, kMisreadShiftRel = 0.05;
// The nominal conditions' check: a reading is ok while the silhouette's explanations leave
// less than a 15 % chance that μ lies beyond the tolerance (and the finding names the
// weightiest explanation other than the nominal height with at least 5 % of the weight).
constexpr double kWrongRisk = 0.15;
constexpr double kPlausibleWeight = 0.05;
// What the advice proposes: a final height measured with a micrometer, a scale measured on
// the end-face plane with a reference disc, n fitted over the test's own strain range.
constexpr double kAdvisedHFinalTolMm = 0.01, kAdvisedScaleRel = 0.001, kAdvisedNTol = 0.003;
// A shared ellipse is the view of a tilted camera (or a lens's distortion off-centre): the
// equal-area radii it leaves are covered by the edges' tilt term, which the bench checks on
// cameras tilted 6–15° (shared ellipticity up to about 0.035 with distortion). Beyond 0.05
// (a tilt of about 18°) the term is unchecked and the ellipse is a finding.
constexpr double kTiltEllipticityMax = 0.05;
// An original face's edge of under 8 grey levels is located, but not told for what it is: a
// turning mark on the ring steps the level by as much (a rendered photograph whose face and
// ring are 2 grey levels apart, measured again after a fresh draw of 1 grey level of sensor
// noise, took a mark 11 px inside the contact edge for the edge: 6.2 grey levels, μ 0.115 low,
// and said ok). Over the drawn, reference and rendered sets (about 1 100 readings) one right
// reading lies under it (loopset-059, a 5 px ring whose fitted step is 7.7) and warns; the
// development set's faintest is 10.6, the reference photographs' 18.
constexpr double kLowContrastGrey = 8.0;
// The original face's edge is a step in the surface's finish that the optics alone blur; the
// contact edge is where the flat face ends and the barrel's surface turns away from the
// light. Where the barrel's shading falls off gradually beyond it, the contact edge's step is
// wider than the original face's and its steepest point lies outside the edge, by up to about
// the excess width (rendered photographs: the excess 1.6–3.0 px where R_o read 0.5–4 px
// outside; drawn steps and the development set's and the reference photographs' edges: at
// most 1.6 px). Beyond kContactRampFindingPx that excess is a finding (R_o, taken where the
// ring's level ends, still reads up to 7 px outside on a few rendered ramps), and u's error
// takes it as one standard deviation. The finding's line lies above the knee's
// (vision::kContactRampPx, where the pipeline starts to look for where the level ends) by the
// width's own repeatability: a reference photograph's contact edge that measures 1.58 px
// measures 1.58–1.65 on 24 fresh draws of 1 grey level of sensor noise, and at 1.6 three of
// them warned a right reading. The rendered bench's wrong readings that this finding alone
// warns measure 1.87 px and more; its readings between 1.6 and 1.8 px are right (within
// 0.0094 of μ), and their U covers them without the ramp's term.
constexpr double kContactRampFindingPx = 1.8;
bool contactEdgeOnRamp(const EndFaceGeometry &g)
{
    // Segment frames that showed the tilt step placed the contact edge on the ramp.
    return g.contactRampPx > kContactRampFindingPx &&
           !(g.imageFlags & (vision::kImageContactEdgeByTilt | vision::kImageTiltConfirms));
}
// The edge model's own error, beyond the fits' scatter: against the drawn boundaries of the
// development set's photographs the pipeline's R_i lies 0.005 mm (1 σ) off the truth's
// equivalent radius and R_o 0.001 mm (a ragged texture boundary, not a step, on the inside).
constexpr double kInnerEdgeModelMm = 0.005, kOuterEdgeModelMm = 0.001;
// Under about 3 px the two edges' blurs merge, and the two-step fit reads such a ring up to
// 0.9 px wide (drawn 640 × 480 rings of 2.6–2.9 px read 3.1–3.4 px, with Δμ up to 0.012):
// a ring read under 3.5 px may be one of those, a finding whichever path measured it.
constexpr double kNarrowRingFindingPx = 3.5, kNarrowRingWidenPx = 0.9;
// A ring is resolved where its two edges lie at least this many blur σ apart.
constexpr double kResolvedRingBlurs = 2.0;
// An edge blurred beyond σ 2.6 px: the two-step fit of a ring under 6 px loses its edges.
constexpr double kBlurredPx = 2.6;
// A photograph's narrow-ring fit may instead read two steps of a wide ring's surroundings (a
// lit shoulder beyond a dark ring: μ 0.1–0.2 low). The barrel's outline, which the FE ties
// to μ at the height, then disagrees with the μ read; within 2 σ of it the outline agrees.
constexpr double kNarrowRingOutlineZ = 2.0;

// The silhouette's observation d = α·δk + β·δr + o + e (α the share of a scale error the
// silhouette sees; e of variance se2: silhouetteRelSigma; o an offset of the silhouette alone,
// with its mean and variance) applied to a prior on (δk, δr) with the means prior.dk, prior.dr:
// the posterior mean and covariance (a linear Gaussian update), widened by χ² where d lies
// further out than the prior and e explain (as for a Birge ratio).
ScaleAndReduction update(const ScaleAndReduction &prior, double d, double beta, double se2, double offset = 0,
                         double offsetVar = 0, double alpha = 1)
{
    const double S = alpha * alpha * prior.pk + beta * beta * prior.pr + se2 + offsetVar;
    const double v = d - offset - alpha * prior.dk - beta * prior.dr;
    const double w = std::max(1.0, v * v / S);
    ScaleAndReduction p;
    p.dk = prior.dk + alpha * prior.pk / S * v;
    p.dr = prior.dr + beta * prior.pr / S * v;
    p.pk = w * (prior.pk - alpha * alpha * prior.pk * prior.pk / S);
    p.pr = w * (prior.pr - beta * beta * prior.pr * prior.pr / S);
    p.pkr = -w * alpha * beta * prior.pk * prior.pr / S;
    return p;
}

// With a declared final height: one update (the view's part of d taken off, its spread
// kept), or past 3 σ neither declared value corrected and each widened to explain the whole
// discrepancy alone.
ScaleAndReduction declaredPosteriorInView(ScaleAndReduction sr, const SilhouetteObservation &o, double se2, int c)
{
    const double d = o.d - o.view.offset[c], ve = se2 + o.view.var[c];
    const double S = sr.pk + o.beta * o.beta * sr.pr + ve;
    if (d * d / S > kContradictionChi2) {
        sr.pk = std::max(sr.pk, d * d);
        sr.pr = std::max(sr.pr, d * d / (o.beta * o.beta));
        return sr;
    }
    return update(sr, d, o.beta, ve);
}

// The posteriors of several views (or of one explanation under several), each weighed: their
// mixture's moments.
ScaleAndReduction mixtureOf(const ScaleAndReduction *post, const double *weight, int count)
{
    double wSum = 0;
    for (int i = 0; i < count; ++i) wSum += weight[i];
    if (!(wSum > 0)) return post[0];
    ScaleAndReduction m;
    for (int i = 0; i < count; ++i) {
        m.dk += weight[i] / wSum * post[i].dk;
        m.dr += weight[i] / wSum * post[i].dr;
    }
    for (int i = 0; i < count; ++i) {
        const double w = weight[i] / wSum, gk = post[i].dk - m.dk, gr = post[i].dr - m.dr;
        m.pk += w * (post[i].pk + gk * gk);
        m.pr += w * (post[i].pr + gr * gr);
        m.pkr += w * (post[i].pkr + gk * gr);
    }
    return m;
}

ScaleAndReduction declaredPosterior(const ScaleAndReduction &sr, const SilhouetteObservation &o, double se2)
{
    ScaleAndReduction post[OutlineView::kMax];
    double weight[OutlineView::kMax];
    for (int c = 0; c < o.view.count; ++c) {
        post[c] = declaredPosteriorInView(sr, o, se2, c);
        const double d = o.d - o.view.offset[c], S = sr.pk + o.beta * o.beta * sr.pr + se2 + o.view.var[c];
        weight[c] = o.view.weight[c] * std::exp(-0.5 * d * d / S) / std::sqrt(S);
    }
    return mixtureOf(post, weight, o.view.count);
}

// Without one: three explanations of the silhouette's discrepancy, four in an oblique view
// (kNominalReductionSigma, kForeshortenMean), and a wrong edge (kMisreadPrior): each one's
// posterior, weighted by its prior and how well it predicts d, and their mixture's moments.
// Each explanation's prior on (δk, δr) before the silhouette, from the declared one.
void explanationPriors(const ScaleAndReduction &declared, ScaleAndReduction prior[Explanations::kCount])
{
    using E = Explanations;
    prior[E::OtherHeight] = declared;
    prior[E::ScaleOff] = ScaleAndReduction{};
    prior[E::ScaleOff].dk = kFixtureScaleMean;
    prior[E::ScaleOff].pk = kFixtureScaleSigma * kFixtureScaleSigma;
    prior[E::ScaleOff].pr = kNominalReductionSigma * kNominalReductionSigma;
    prior[E::Nominal] = ScaleAndReduction{};
    prior[E::Nominal].pk = declared.pk;
    prior[E::Nominal].pr = kNominalReductionSigma * kNominalReductionSigma;
    prior[E::Foreshortened] = prior[E::Nominal];
    prior[E::WrongEdge] = declared; // the silhouette tells nothing
}

ScaleAndReduction mixturePosterior(const ScaleAndReduction &declared, const SilhouetteObservation &o, double se2,
                                   bool oblique, uint32_t *flags, Explanations *why)
{
    using E = Explanations;
    const double d = o.d, beta = o.beta;
    ScaleAndReduction prior[E::kCount];
    explanationPriors(declared, prior);
    const double offset[E::kCount] = {0, 0, 0, kForeshortenMean, 0};
    const double offsetVar[E::kCount] = {0, 0, 0, kForeshortenSigma * kForeshortenSigma, 0};
    const double alpha[E::kCount] = {1, kSilhouetteScaleShare, 1, 1, 1};
    const double gaussianPrior = (1.0 - kMisreadPrior) / (oblique ? 4 : 3);
    E e;
    double wSum = 0;
    for (int h = 0; h < E::WrongEdge; ++h) {
        // The camera's part of d added to the explanation's own, in each view the image
        // leaves open; the explanation's posterior is their mixture.
        ScaleAndReduction post[OutlineView::kMax];
        double weight[OutlineView::kMax];
        e.weight[h] = 0;
        for (int c = 0; c < o.view.count; ++c) {
            const double off = offset[h] + o.view.offset[c], offVar = offsetVar[h] + o.view.var[c];
            const double S = alpha[h] * alpha[h] * prior[h].pk + beta * beta * prior[h].pr + se2 + offVar;
            const double v = d - off - alpha[h] * prior[h].dk;
            // Densities up to the common 1/√(2π).
            weight[c] = h != E::Foreshortened || oblique
                            ? gaussianPrior * o.view.weight[c] * std::exp(-0.5 * v * v / S) / std::sqrt(S)
                            : 0.0;
            post[c] = update(prior[h], d, beta, se2, off, offVar, alpha[h]);
            e.weight[h] += weight[c];
            e.part[c][h] = post[c], e.partWeight[c][h] = weight[c];
        }
        wSum += e.weight[h];
        e.post[h] = mixtureOf(post, weight, o.view.count);
    }
    // A wrong edge lies inside the outline the camera sees.
    const double misreadSpan = -kMisreadMinInside - o.dContact;
    e.weight[E::WrongEdge] = 0;
    for (int c = 0; c < o.view.count; ++c) {
        const double dSeen = d - o.view.offset[c];
        const bool misreadPossible = misreadSpan > 0 && dSeen >= o.dContact && dSeen <= -kMisreadMinInside;
        const double w =
            misreadPossible ? o.view.weight[c] * kMisreadPrior * std::sqrt(2 * std::numbers::pi) / misreadSpan : 0.0;
        e.weight[E::WrongEdge] += w;
        e.part[c][E::WrongEdge] = prior[E::WrongEdge], e.partWeight[c][E::WrongEdge] = w;
    }
    wSum += e.weight[E::WrongEdge];
    e.post[E::WrongEdge] = prior[E::WrongEdge];
    if (!(wSum > 0)) std::fill_n(e.weight, int(E::kCount), 1.0); // nothing fits: equally likely
    const ScaleAndReduction sr = mixtureOf(e.post, e.weight, E::kCount);
    for (int h = 0; h < E::kCount; ++h) e.weight[h] = wSum > 0 ? e.weight[h] / wSum : 1.0 / int(E::kCount);
    if (o.view.count > 1 && wSum > 0) {
        e.viewCount = o.view.count;
        for (int c = 0; c < o.view.count; ++c)
            for (int h = 0; h < E::kCount; ++h) e.partWeight[c][h] /= wSum;
    }
    // A silhouette more likely a wrong edge than the barrel's outline is not relied on.
    if (e.weight[E::WrongEdge] >= *std::max_element(e.weight, e.weight + E::WrongEdge))
        *flags |= kFlagSilhouetteUnreliable;
    if (why) *why = e;
    return sr;
}

} // namespace

AssumedReduction assumedReduction(const SpecimenSpec &spec)
{
    AssumedReduction r;
    r.declared = spec.hFinalMm > 0 && spec.hFinalMm < spec.h0Mm;
    r.r = r.declared ? 1.0 - spec.hFinalMm / spec.h0Mm : kNominalReduction;
    r.sigma = r.declared ? spec.tolerances.hFinalMm / spec.h0Mm : kUndeclaredReductionSigma;
    return r;
}

PlaneMapping mapFace(const EndFaceGeometry &g, const SpecimenSpec &spec, const PlaneCalibration *calibration,
                     const AssumedReduction &r)
{
    PlaneMapping p;
    const double s = spec.mmPerPx;
    p.mmPerPx = s;
    p.face.rInnerMm = g.inner.rEqPx * s;
    p.face.rOuterMm = g.outer.rEqPx * s;
    p.face.rMaxMm = g.rMaxPx * s;
    p.face.uMm = (g.outer.rEqPx - g.inner.rEqPx) * s;
    p.inner = {g.inner.ellipticity, g.inner.axisDeg};
    p.outer = {g.outer.ellipticity, g.outer.axisDeg};
    p.scaleRelSigma = spec.tolerances.scaleRel;
    if (!calibration) return p;

    // Each boundary mapped point by point into the end-face plane (undistorted, tilt
    // removed, at the specimen's height); the scale becomes the contact edge's effective one.
    PlaneCalibration plane = *calibration;
    plane.heightMm = spec.h0Mm * (1.0 - r.r);
    const vision::PlaneOutline pi = planeOutline(g.inner, g.centreX, g.centreY, plane);
    const vision::PlaneOutline po = planeOutline(g.outer, g.centreX, g.centreY, plane);
    if (!(pi.valid && po.valid && g.outer.rEqPx > 0)) {
        p.valid = false;
        return p;
    }
    p.face.rInnerMm = pi.rEqMm, p.face.rOuterMm = po.rEqMm, p.face.uMm = po.rEqMm - pi.rEqMm;
    p.mmPerPx = po.rEqMm / g.outer.rEqPx;
    // The shape checks judge the end face itself, not the camera's view of it.
    p.inner = {pi.ellipticity, pi.axisDeg};
    p.outer = {po.ellipticity, po.axisDeg};
    p.centreOffsetPx = std::hypot(pi.centroidX - po.centroidX, pi.centroidY - po.centroidY) / p.mmPerPx;
    // The barrel is widest about half-way down: its silhouette maps at half the height.
    BoundaryFit silhouette;
    silhouette.a0 = g.rMaxPx;
    PlaneCalibration mid = plane;
    mid.heightMm *= 0.5;
    p.face.rMaxMm = g.rMaxPx > 0 ? equivalentRadiusMm(silhouette, g.centreX, g.centreY, mid) : 0;
    // The plane's height is as uncertain as the reduction: its part of the scale.
    const double dh = spec.h0Mm * r.sigma;
    PlaneCalibration up = plane, down = plane;
    up.heightMm += dh, down.heightMm -= dh;
    const double sUp = planeScaleAt(up, g.centreX, g.centreY);
    const double sDown = planeScaleAt(down, g.centreX, g.centreY);
    const double heightPart = sUp > 0 && sDown > 0 ? std::fabs(sUp - sDown) / (sUp + sDown) : 0.01;
    p.scaleRelSigma = std::hypot(spec.tolerances.calibrationScaleRel, heightPart);
    return p;
}

namespace {
// The optics blur both edges alike, so the narrower one's width is theirs where the rays
// located both: the contact edge's takes in the barrel's ramp beyond it (contact_edge_ramp)
// and, across a ring of a few pixels, the other edge's flank; a drawn original face's ragged
// texture boundary widens its own.
double opticsBlurPx(const EndFaceGeometry &g)
{
    return g.innerEdgeWidthPx > 0 ? std::min(g.innerEdgeWidthPx, g.edgeWidthPx) : g.edgeWidthPx;
}
} // namespace

EdgeSigma edgeSigma(const EndFaceGeometry &g, const PlaneMapping &p, bool calibrated)
{
    // The fits' scatter and a 0.1 px location floor per boundary, and the edge model's error
    // in millimetres; an uncalibrated camera's tilt shrinks the equal-area radii by up to e/2
    // (e the shared ellipticity), which the declared scale may or may not have absorbed.
    EdgeSigma e;
    const double sigPx =
        std::sqrt(g.inner.rEqSigmaPx * g.inner.rEqSigmaPx + g.outer.rEqSigmaPx * g.outer.rEqSigmaPx + 2 * 0.1 * 0.1);
    e.uSigmaMm = sigPx * p.mmPerPx;
    const double axisDiff = std::fabs(std::remainder(p.inner.axisDeg - p.outer.axisDeg, 180.0));
    e.sharedEllipse = p.inner.ellipticity > 0.012 && p.outer.ellipticity > 0.012 && axisDiff < 20;
    e.uSigmaEdgesMm = std::hypot(e.uSigmaMm, std::hypot(kInnerEdgeModelMm, kOuterEdgeModelMm));
    e.narrowWidenMm = kNarrowRingWidenPx * p.mmPerPx;
    e.ringFromProfile = (g.imageFlags & vision::kImageNarrowRingFit) != 0;
    // Two steps blurred by σ and closer than 2σ show one derivative peak, not two: such a ring
    // is not resolved, and what the fit splits into two edges may as well be one edge falling
    // into the barrel's ramp (rendered photographs whose face and ring are one shade: the
    // contact edge read as R_i and the ramp's knee as R_o, 4.2–4.5 px apart at σ 2.1–2.3 px,
    // μ 0.06–0.2 low, the outline read 2 % short agreeing with the μ read).
    e.ringUnresolved = g.outer.rEqPx - g.inner.rEqPx < kResolvedRingBlurs * opticsBlurPx(g);
    if (contactEdgeOnRamp(g)) e.uSigmaEdgesMm = std::hypot(e.uSigmaEdgesMm, g.contactRampPx * p.mmPerPx);
    if (g.imageFlags & (vision::kImageContactEdgeByTilt | vision::kImageTiltConfirms))
        e.uSigmaEdgesMm = std::hypot(e.uSigmaEdgesMm, g.tiltSigmaPx * p.mmPerPx);
    if (!calibrated && e.sharedEllipse) {
        const double ell = std::min(p.inner.ellipticity, p.outer.ellipticity);
        e.uSigmaEdgesMm = std::hypot(e.uSigmaEdgesMm, p.face.uMm * ell / (2 * std::sqrt(3.0)));
    }
    return e;
}

uint32_t imageChecks(const EndFaceGeometry &g, const PlaneMapping &p, const EdgeSigma &e, double d0Mm,
                     double *centreOffsetPx)
{
    uint32_t f = 0;
    if (g.imageFlags & vision::kImageSpecimenClipped) f |= kFlagSpecimenClipped;
    if (g.imageFlags & vision::kImageTiltDisagrees) f |= kFlagTiltDisagrees;
    if (g.imageFlags & vision::kImageNarrowRingFit) f |= kFlagNarrowRing;
    // The segment frames' tilt rising at the contact edge itself says which edge ends the
    // flat face.
    const bool tiltConfirms = (g.imageFlags & vision::kImageTiltConfirms) != 0;
    if ((g.imageFlags & vision::kImageContactEdgeUndecided) && !tiltConfirms) f |= kFlagContactEdgeUndecided;
    const double r0Px = 0.5 * d0Mm / p.mmPerPx;
    if (std::min(g.inner.coverage, g.outer.coverage) < 0.6) f |= kFlagLowCoverage;
    if (std::max(g.inner.scatterPx, g.outer.scatterPx) > std::max(1.5, 0.006 * r0Px)) f |= kFlagHighScatter;
    if (std::fabs(g.inner.contrast) < kLowContrastGrey) f |= kFlagLowContrast;
    *centreOffsetPx = p.centreOffsetPx >= 0
                          ? p.centreOffsetPx
                          : std::hypot(g.inner.centreX - g.outer.centreX, g.inner.centreY - g.outer.centreY);
    if (*centreOffsetPx > std::max(3.0, 0.012 * r0Px)) f |= kFlagCentreOffset;
    if (e.sharedEllipse && std::min(p.inner.ellipticity, p.outer.ellipticity) > kTiltEllipticityMax)
        f |= kFlagElliptical;
    if (g.outer.rEqPx - g.inner.rEqPx < kNarrowRingFindingPx || e.ringUnresolved) f |= kFlagNarrowRing;
    const double blurPx = opticsBlurPx(g);
    if (blurPx > kBlurredPx) f |= kFlagBlurred;
    if (contactEdgeOnRamp(g)) f |= kFlagContactEdgeRamp;
    if (g.saturatedFraction > 0.02) f |= kFlagSaturated;
    return f;
}

bool narrowRingCorroborated(const MuFunction &F, const SpecimenSpec &spec, double uMm, double r, double mu,
                            double narrowWidenMm, const SilhouetteObservation *silhouette)
{
    if (!silhouette || !silhouette->usable || std::fabs(silhouette->rMaxZ) > kNarrowRingOutlineZ) return false;
    const double narrower = F.at(std::max(0.0, uMm - narrowWidenMm), r, spec.n);
    return std::fabs(narrower - mu) <= spec.tolerance.at(std::fabs(mu));
}

MuFunction::MuFunction(const SpecimenSpec &spec, const FrictionModel &model)
        : spec_(spec), model_(model), carry_(model, model.name())
{}

double MuFunction::slopeU(double u, double r, double n) const
{
    const double h = std::max(1e-4, 0.01 * u), lo = std::max(0.0, u - h);
    return (at(u + h, r, n) - at(lo, r, n)) / (u + h - lo);
}

ModelEstimate MuFunction::estimate(double u, double r, double n) const
{
    const friction::ModelInputs in{u, n, spec_.kMpa, spec_.d0Mm, spec_.h0Mm, spec_.h0Mm * (1 - r)};
    return model_.correctsReduction() ? model_.estimate(in) : carry_.estimate(in);
}

namespace {

// The FE's barrel at the perspective share s (the outline's centre shift per unit of the end
// face's distance from the axis): the outline over R_max is (1 − s)·c, the side seen at the
// depth z0 where it reaches farthest (k = W/(W + z0) = 1 − s) and c = r(z0)/R_max. c from the
// table at the D0/W whose shift is s (0.98–0.995 over the FE's grid); a barrel flatter about
// its widest section than the FE's (a parametric barrel, a worn die) reaches R_max nearer the
// end face, so c lies between the FE's and 1, uniform.
struct BarrelReach {
    double mean = 1, var = 0;
};
// The FE's shift and c = outline/(R_max·(1 − shift)) on the table's D0/W cells, taken once per
// view: each share s then finds its D0/W and c between two cells.
struct BarrelReachTable {
    double shift[kReachSteps + 1], c[kReachSteps + 1];
    BarrelReachTable(double n, double mu, double reduction)
    {
        const double xMax = friction::outlineD0OverWMax();
        for (int j = 0; j <= kReachSteps; ++j) {
            const double x = xMax * j / kReachSteps;
            shift[j] = friction::outlineShiftAt(n, mu, reduction, x);
            c[j] = friction::outlineRatioAt(n, mu, reduction, x) / (1 - shift[j]);
        }
    }
    BarrelReach at(double s) const
    {
        BarrelReach r;
        if (!(s > 0)) return r;
        double fe = c[kReachSteps]; // beyond the closest camera's shift: its c
        for (int j = 1; j <= kReachSteps; ++j)
            if (shift[j] >= s) {
                const double t = (s - shift[j - 1]) / std::max(1e-9, shift[j] - shift[j - 1]);
                fe = c[j - 1] + t * (c[j] - c[j - 1]);
                break;
            }
        const double lo = std::min(fe, 1.0);
        r.mean = 0.5 * (lo + 1);
        r.var = (1 - lo) * (1 - lo) / 12;
        return r;
    }
};

// How well a perspective share s fits the outline's centre shift (CameraDistance): under s the
// shift is s times the end face's distance from the axis, with the centres' error and the
// axis's (scaled by s); a centre misread by a highlight or a shadow on some rays fits none of
// them, and a broad term keeps it from deciding. 1 where the image did not weigh the shift.
double shareLikelihood(const CameraDistance &c, double share)
{
    if (!c.fromImage) return 1;
    const double off = std::hypot(c.offAxisX, c.offAxisY);
    const double ex = c.shiftX + share * c.offAxisX, ey = c.shiftY + share * c.offAxisY;
    const double var = c.shiftSigmaPx * c.shiftSigmaPx + share * share * c.axisSigmaPx * c.axisSigmaPx;
    const double wide = var + kMisreadShiftPx * kMisreadShiftPx + kMisreadShiftRel * kMisreadShiftRel * off * off;
    const double e2 = ex * ex + ey * ey;
    return (1 - kMisreadShift) * std::exp(-0.5 * e2 / var) / var + kMisreadShift * std::exp(-0.5 * e2 / wide) / wide;
}

// The close camera's part of d over the shares s = sMax·j/kShareSteps (j from jFirst), each
// weighed by its prior and the shift: the summed weight, ln((1 − s)·c) averaged, and its
// variance, their spread and c's.
struct CloseView {
    double weight = 0, mean = 0, var = 0;
};
CloseView closeView(const BarrelReachTable &reach, const CameraDistance &c, double sMax, int jFirst, double prior)
{
    double wSum = 0, m1 = 0, m2 = 0, reachVar = 0;
    for (int j = jFirst; j <= kShareSteps; ++j) {
        const double share = sMax * j / kShareSteps;
        const double w = prior * shareLikelihood(c, share);
        const BarrelReach r = reach.at(share);
        const double ln = std::log((1 - share) * r.mean);
        wSum += w, m1 += w * ln, m2 += w * ln * ln, reachVar += w * r.var;
    }
    CloseView v;
    v.weight = wSum;
    if (!(wSum > 0)) return v;
    v.mean = m1 / wSum;
    v.var = std::max(0.0, m2 / wSum - v.mean * v.mean) + reachVar / wSum;
    return v;
}

// Without a declared distance the share runs from a telecentric view (s 0: a telecentric lens,
// a far camera, a drawing; half the prior) to a camera at about 40 mm (s up to kShareMax, the
// other half, uniform). Two views come out: the telecentric one with its posterior weight, and
// the close camera's. A view under 0.1 % of the weight is left out.
OutlineView imagedView(double n, double mu, double reduction, const CameraDistance &c)
{
    const BarrelReachTable reachTable(n, mu, reduction);
    const double w0 = kTelecentricPrior * shareLikelihood(c, 0);
    const CloseView close = closeView(reachTable, c, kShareMax, 1, (1 - kTelecentricPrior) / kShareSteps);
    OutlineView v;
    v.estimated = true;
    const double total = w0 + close.weight;
    if (!(total > 0) || !(close.weight > kMinViewWeight * total)) return v; // telecentric
    if (w0 < kMinViewWeight * total) {
        v.offset[0] = close.mean, v.var[0] = close.var;
        return v;
    }
    v.count = 2;
    v.weight[0] = w0 / total, v.weight[1] = close.weight / total;
    v.offset[1] = close.mean, v.var[1] = close.var;
    return v;
}

// A declared distance W says how far the end face is, not how the barrel's side runs below
// it: the side reaches farthest at a depth z0 between the end face and the widest section, h/2
// below it (beyond it both r(z) and W/(W + z) fall), so s = z0/(W + z0) lies between 0 and
// (h/2)/(W + h/2), W taken at the near end of its 5 %; c as above. The FE's barrel has one z0,
// a flatter or rounder one another: held to the FE's own outline, the reference photographs
// (W 45–109 mm declared) read their outlines 3–11 σ large and μ 0.01–0.026 low. Where the end
// face lies off the axis the outline's centre shift weighs s within that span.
OutlineView declaredView(double n, double mu, double reduction, const CameraDistance &c)
{
    OutlineView v;
    if (!(c.d0OverW > 0)) return v;                               // a telecentric view's outline is R_max itself
    const double halfHeight = 0.5 * c.h0OverD0 * (1 - reduction); // in D0
    const double nearW = (1 - kWorkingDistanceRelSigma) / c.d0OverW;
    const CloseView close =
        closeView(BarrelReachTable(n, mu, reduction), c, halfHeight / (nearW + halfHeight), 0, 1.0 / (kShareSteps + 1));
    const double table = friction::outlineRatioRelSigma();
    v.offset[0] = close.mean;
    v.var[0] = close.var + table * table;
    return v;
}

} // namespace

OutlineView outlineView(double n, double mu, double reduction, const CameraDistance &camera)
{
    return camera.d0OverW > 0 || !camera.fromImage ? declaredView(n, mu, reduction, camera)
                                                   : imagedView(n, mu, reduction, camera);
}

bool declaredDistanceView(const OutlineView &estimated, OutlineView *declared)
{
    if (!estimated.estimated) return false;
    const int close = estimated.count - 1;
    if (!(estimated.offset[close] < 0)) return false; // the image left only a telecentric view
    *declared = OutlineView{};
    declared->offset[0] = estimated.offset[close];
    declared->var[0] = estimated.var[close];
    return true;
}

CameraDistance declaredCameraDistance(const SpecimenSpec &spec)
{
    CameraDistance c;
    c.d0OverW = spec.workingDistanceMm > 0 ? spec.d0Mm / spec.workingDistanceMm : 0;
    c.h0OverD0 = spec.d0Mm > 0 ? spec.h0Mm / spec.d0Mm : 1.5;
    return c;
}

CameraDistance cameraDistance(const SpecimenSpec &spec, const EndFaceGeometry &g, bool oblique)
{
    CameraDistance c = declaredCameraDistance(spec);
    // A tilted view draws the outline off the end face's centre by its own geometry: there
    // the foreshortened explanation speaks for the view (silhouettePosterior).
    if (oblique || !(g.silhouetteCoverage > 0) || g.frameWidth <= 0 || g.frameHeight <= 0) return c;
    c.fromImage = true;
    c.offAxisX = g.outer.centreX - 0.5 * (g.frameWidth - 1);
    c.offAxisY = g.outer.centreY - 0.5 * (g.frameHeight - 1);
    c.shiftX = g.silhouetteCentreX - g.outer.centreX;
    c.shiftY = g.silhouetteCentreY - g.outer.centreY;
    // A first harmonic's error from n points of scatter σ is σ·√(2/n).
    const double rays = std::max(1.0, g.silhouetteCoverage * vision::kCoarseRays);
    c.shiftSigmaPx = std::hypot(kShiftFloorPx, g.silhouetteScatterPx * std::sqrt(2 / rays));
    c.axisSigmaPx = kAxisRelSigma * std::max(g.frameWidth, g.frameHeight);
    // A straight camera draws the outline towards the axis and nowhere else. A shift across
    // that line, away from the axis or beyond the closest camera's share is some other view's:
    // a tilt the boundaries do not show (the barrel band then swings with the tilt, and the
    // silhouette's own explanations, a wrong edge among them, speak for it) or a misread
    // outline. The view is then taken as telecentric, as without a per-ray silhouette.
    const double off = std::hypot(c.offAxisX, c.offAxisY);
    const double along = off > 0 ? -(c.shiftX * c.offAxisX + c.shiftY * c.offAxisY) / off : 0;
    const double across = off > 0 ? (c.shiftX * c.offAxisY - c.shiftY * c.offAxisX) / off : 0;
    const double sigma = std::hypot(c.shiftSigmaPx, kShareMax * c.axisSigmaPx);
    if (std::fabs(across) > kShiftOutlierSigmas * sigma || along < -kShiftOutlierSigmas * sigma ||
        along > kShareMax * off + kShiftOutlierSigmas * sigma) {
        return declaredCameraDistance(spec);
    }
    return c;
}

SilhouetteObservation observeSilhouette(const FaceInMm &face, double coverage, double scatterPx, double rMaxPx,
                                        const SpecimenSpec &spec, const AssumedReduction &r, double mu0,
                                        const CameraDistance &camera)
{
    SilhouetteObservation o;
    if (!(rMaxPx > 0)) {
        o.flags = kFlagNoSilhouette;
        return o;
    }
    const double n = spec.n;
    o.view = outlineView(n, mu0, r.r, camera);
    // The silhouette on the FE's terms (friction::feRMaxOverSpecimen).
    const double rMaxAsFe = face.rMaxMm * (1 + friction::feRMaxOverSpecimen(n, mu0));
    o.measuredRelSigma = friction::measuredRMaxRelSigma(coverage > 0 ? scatterPx / rMaxPx : 0);
    // z and the reduction it implies are R_max's: the outline the view sees, scaled back. Of
    // two views, the one the image itself favours (the telecentric one where it cannot tell):
    // a silhouette 4 % small beside a declared height is then a contradiction to report, not
    // a close camera the image never showed (the posteriors weigh both).
    const int seen = o.view.count > 1 && o.view.weight[1] > o.view.weight[0] ? 1 : 0;
    const friction::RadiiCheck rc = friction::checkRadii(rMaxAsFe * std::exp(-o.view.offset[seen]), n, mu0, spec.d0Mm,
                                                         r.r, spec.h0Mm, true, o.measuredRelSigma);
    o.rMaxZ = rc.z;
    o.reductionEst = rc.reductionEst;
    // Without a declared final height a discrepancy is weighed by its explanations, and
    // judged by what they do to μ (nominalCheck).
    if (rc.inconsistent() && r.declared) o.flags |= kFlagRadiiInconsistent;
    const friction::RadiiCheck up = friction::checkRadii(rMaxAsFe, n, mu0, spec.d0Mm, r.r + 0.01, spec.h0Mm, false);
    const friction::RadiiCheck down = friction::checkRadii(rMaxAsFe, n, mu0, spec.d0Mm, r.r - 0.01, spec.h0Mm, false);
    const double overContact = face.rMaxMm / face.rOuterMm;
    o.usable = rc.valid && up.valid && down.valid && coverage >= kSilhouetteMinCoverage &&
               overContact > kSilhouetteOverContactMin && overContact < kSilhouetteOverContactMax;
    if (o.usable) {
        o.d = std::log(rMaxAsFe / rc.rMaxFeMm);
        o.dContact = std::log(kSilhouetteOverContactMin * face.rOuterMm / rc.rMaxFeMm);
        o.beta = std::log(up.rMaxFeMm / down.rMaxFeMm) / 0.02;
        o.usable = o.beta > 0.1;
    }
    // An outline the rays see on fewer than half their number (or that only the mean profile
    // shows) was not found: the view is one without a silhouette, its reduction reported only.
    if (!o.usable) o.flags |= coverage < kSilhouetteMinCoverage ? kFlagNoSilhouette : kFlagSilhouetteUnreliable;
    return o;
}

ScaleAndReduction silhouettePosterior(const ScaleAndReduction &prior, const SilhouetteObservation &obs,
                                      double silhouetteRelSigma, bool declared, bool oblique, uint32_t *flags,
                                      Explanations *why)
{
    const double se2 = silhouetteRelSigma * silhouetteRelSigma;
    return declared ? declaredPosterior(prior, obs, se2) : mixturePosterior(prior, obs, se2, oblique, flags, why);
}

namespace {

// The chance that μ, Gaussian about an offset off from the reading's with variance var, lies
// beyond the tolerance either way.
double chanceBeyond(double off, double var, double tol)
{
    const double s = std::sqrt(std::max(1e-24, var)) * std::numbers::sqrt2;
    return 0.5 * (std::erfc((tol - off) / s) + std::erfc((tol + off) / s));
}

// The same where the height is uniform over a range of variance pr (μ moving by g per unit of
// reduction) and the rest Gaussian with variance var: the Gaussian's chance averaged over the
// range's midpoints.
double chanceBeyondOverRange(double off, double var, double g, double pr, double tol)
{
    constexpr int kSteps = 32;
    const double half = std::sqrt(3 * std::max(0.0, pr));
    double sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double dr = half * (2 * (i + 0.5) / kSteps - 1);
        sum += chanceBeyond(std::fabs(off + g * dr), var, tol);
    }
    return sum / kSteps;
}

} // namespace

uint32_t nominalCheck(const MuFunction &F, const SpecimenSpec &spec, double u, double mu, const Explanations *why,
                      double *nominalMu, bool weighRisk)
{
    using E = Explanations;
    const double n = spec.n, tol = spec.tolerance.at(std::fabs(mu));
    *nominalMu = F.at(u, kNominalReduction, n);
    // Where nothing checked the height (weighRisk): the chance that μ lies beyond the
    // tolerance from the reading, under each explanation μ Gaussian about its own value with
    // the spread its posterior of scale and reduction leaves (the declared inputs' other
    // parts are U's, not the check's). The same for a silhouette that may be a wrong edge:
    // that share of the reading is unchecked.
    double risk = 0, uncheckedRisk = 0;
    double otherMu = 0; // μ where the specimen was pressed to another height
    int lead = -1;      // the weightiest explanation other than the nominal height as seen
    for (int h = 0; h < E::kCount; ++h) {
        if (why->weight[h] <= 0) continue;
        const ScaleAndReduction &p = why->post[h];
        const double uh = u * std::exp(-p.dk), rh = kNominalReduction + p.dr;
        const double muH = F.at(uh, rh, n);
        if (weighRisk || h == E::WrongEdge) {
            const double hu = std::max(1e-4, 0.01 * uh), hr = 0.005;
            const double a = -uh * (F.at(uh + hu, rh, n) - F.at(uh - hu, rh, n)) / (2 * hu);
            const double g = (F.at(uh, rh + hr, n) - F.at(uh, rh - hr, n)) / (2 * hr);
            const double off = std::fabs(muH - mu);
            // Where the height is the undeclared range's (another height before the silhouette
            // spoke, or a silhouette that may be a wrong edge), it is uniform over that range,
            // not Gaussian: its share of μ beyond the tolerance is the range's, which a
            // Gaussian of the same variance understates where the tolerance lies inside it
            // (0.41 for 0.52 at a tolerance 0.8 σ out).
            const bool rangeOfHeights = (h == E::OtherHeight && weighRisk) || h == E::WrongEdge;
            const double beyond =
                why->weight[h] * (rangeOfHeights
                                      ? chanceBeyondOverRange(off, a * a * p.pk, g, p.pr, tol)
                                      : chanceBeyond(off, a * a * p.pk + g * g * p.pr + 2 * a * g * p.pkr, tol));
            risk += beyond;
            if (h == E::WrongEdge) uncheckedRisk = beyond;
        }
        // A foreshortened view leads the scale off: the finding then names no scale.
        const bool nominal = h == E::Nominal || h == E::WrongEdge;
        if (!nominal && why->weight[h] >= kPlausibleWeight && (lead < 0 || why->weight[h] > why->weight[lead]))
            lead = h;
        if (h == E::OtherHeight) otherMu = muH;
    }
    // The image says another height (or scale) than the nominal, by enough to move μ.
    // Where another height is the weightiest explanation besides the nominal one, the image
    // says that height: μ there beyond the tolerance of μ at half height is a finding, also
    // where the nominal explanation keeps enough weight to hold the reading's μ within it.
    // Where the image left a telecentric and a close view open, another height says so in each
    // view that gives it weight, or it is the view, not the image, that says it: the camera's
    // distance decides (a far camera's outline, 1 % inside R_max, reads as a height 1.3 % short
    // under a telecentric view and as the nominal one under its own; a drawn specimen pressed
    // to 47 % reads the same way round).
    bool heightInEveryView = true;
    for (int c = 0; c < why->viewCount; ++c) {
        const double w = why->partWeight[c][E::OtherHeight];
        if (!(w >= kPlausibleWeight)) continue;
        const ScaleAndReduction &p = why->part[c][E::OtherHeight];
        if (!(std::fabs(F.at(u * std::exp(-p.dk), kNominalReduction + p.dr, n) - *nominalMu) > tol))
            heightInEveryView = false;
    }
    const bool otherHeight = lead == E::OtherHeight && std::fabs(otherMu - *nominalMu) > tol;
    if (otherHeight && !heightInEveryView && !(std::fabs(*nominalMu - mu) > tol)) return kFlagWorkingDistanceDecides;
    const bool moved = std::fabs(*nominalMu - mu) > tol || otherHeight;
    const uint32_t named = lead == E::ScaleOff ? uint32_t(kFlagScaleSuspect) : uint32_t(kFlagReductionNotNominal);
    if (moved || (weighRisk ? risk : uncheckedRisk) > kWrongRisk) return named;
    if (weighRisk) return 0;
    // What the silhouette says, explanation by explanation and, where the image left a
    // telecentric and a close view open, view by view: the share of the weight whose μ lies
    // beyond the tolerance from the reading's is the chance the reading is wrong for what the
    // image cannot tell apart; beyond kWrongRisk a finding. The spread each part leaves is U's.
    // Where that share lies in one view alone, the camera's distance decides it.
    const int views = std::max(1, why->viewCount);
    double share = 0, shareInView[OutlineView::kMax] = {};
    for (int c = 0; c < views; ++c)
        for (int h = 0; h < E::WrongEdge; ++h) {
            const double w = why->viewCount ? why->partWeight[c][h] : why->weight[h];
            if (!(w > 0)) continue;
            const ScaleAndReduction &p = why->viewCount ? why->part[c][h] : why->post[h];
            if (std::fabs(F.at(u * std::exp(-p.dk), kNominalReduction + p.dr, n) - mu) <= tol) continue;
            share += w, shareInView[c] += w;
        }
    if (!(share > kWrongRisk)) return 0;
    // In one view alone: the other's share no more than a plausible explanation's weight.
    const bool oneView = why->viewCount > 1 && std::min(shareInView[0], shareInView[1]) < kPlausibleWeight;
    return oneView ? uint32_t(kFlagWorkingDistanceDecides) : named;
}

bool uncheckedViewMatters(const MuFunction &F, const SpecimenSpec &spec, const ScaleAndReduction &declared, double uMm,
                          double mu)
{
    using E = Explanations;
    Explanations prior;
    explanationPriors(declared, prior.post);
    for (int h : {E::OtherHeight, E::ScaleOff, E::Nominal}) prior.weight[h] = 1.0 / 3;
    double nominalMu = 0;
    return nominalCheck(F, spec, uMm, mu, &prior, &nominalMu, true) != 0;
}

MuReading readMu(const MuFunction &F, const FrictionModel &model, const SpecimenSpec &spec, double uMm, double r,
                 bool declared)
{
    // A model that carries u to 50 % itself reads at r; one that does not (the paper's fit as
    // published) reads as is, and the carry it leaves out is in the budget.
    MuReading m;
    if (model.correctsReduction()) {
        m.estimate = F.estimate(uMm, r, spec.n);
        // The inferred reduction is budgeted.
        if (!declared) m.estimate.range &= ~uint32_t(friction::kModelReductionOutside);
    } else {
        m.estimate = model.estimate({uMm, spec.n, spec.kMpa, spec.d0Mm, spec.h0Mm, 0});
        m.bias = F.at(uMm, r, spec.n) - m.estimate.mu;
    }
    return m;
}

UncertaintyBudget budgetOf(const MuFunction &F, const FrictionModel &model, const SpecimenSpec &spec, double uF,
                           double rF, const ScaleAndReduction &sr, double uSigmaEdgesMm, double bias)
{
    const double n = spec.n;
    const double hr = 0.005, hn = std::max(1e-4, spec.tolerances.n);
    const double gU = F.slopeU(uF, rF, n);
    const double gR = (F.at(uF, rF + hr, n) - F.at(uF, rF - hr, n)) / (2 * hr);
    const double gN = (F.at(uF, rF, n + hn) - F.at(uF, rF, n - hn)) / (2 * hn);
    const double a = -uF * gU; // per unit relative scale error
    // The carry's own error: a quarter of its effect (the FE slope is resolution-limited).
    const double carry = 0.25 * std::fabs(F.at(uF, rF, n) - F.at(uF, kNominalReduction, n));
    UncertaintyBudget b;
    b.edges = std::fabs(gU) * uSigmaEdgesMm;
    // Scale and reduction are correlated through the silhouette: their covariance term is
    // shared between the two, so that the components add in quadrature to mu_sigma.
    const double cross = a * gR * sr.pkr;
    b.scale = std::sqrt(std::max(0.0, a * a * sr.pk + cross));
    b.reduction = std::sqrt(std::max(0.0, gR * gR * sr.pr + cross) + carry * carry + bias * bias);
    b.n = std::fabs(gN) * spec.tolerances.n;
    b.model = model.estimate({uF, n, spec.kMpa, spec.d0Mm, spec.h0Mm, 0}).modelSigma;
    return b;
}

double combinedSigma(const UncertaintyBudget &b)
{
    return std::sqrt(b.edges * b.edges + b.scale * b.scale + b.reduction * b.reduction + b.n * b.n + b.model * b.model);
}

uint32_t rangeChecks(const FrictionModel &model, const MuReading &m, const AssumedReduction &r)
{
    uint32_t f = 0;
    const uint32_t range = m.estimate.range;
    if (range & (friction::kModelNBelow | friction::kModelNAbove)) f |= kFlagNOutOfRange;
    if (range & friction::kModelKOutside) f |= kFlagKOutOfRange;
    if (range & friction::kModelMuBelow) f |= kFlagMuBelowRange;
    if (range & friction::kModelMuAbove) f |= kFlagMuAboveRange;
    if (range & friction::kModelUOutside) f |= kFlagUOutsideModel;
    if (range & friction::kModelAspectOutside) f |= kFlagAspectOutside;
    if (model.correctsReduction()) {
        if (range & friction::kModelReductionOutside) f |= kFlagReductionOutside;
    } else if (r.declared && std::fabs(r.r - kNominalReduction) > 0.01) {
        f |= kFlagReductionOutside;
    }
    return f;
}

Advice adviseInput(const MuFunction &F, const FrictionModel &model, const SpecimenSpec &spec, double uF, double rF,
                   const ScaleAndReduction &sr, double uSigmaEdgesMm, double bias, bool declared, bool calibrated,
                   double scaleRelSigma, const ScaleAndReduction *withDistance)
{
    const double k = spec.tolerance.coverage;
    auto expandedWith = [&](const ScaleAndReduction &what) {
        return k * combinedSigma(budgetOf(F, model, spec, uF, rF, what, uSigmaEdgesMm, bias));
    };
    const UncertaintyBudget now = budgetOf(F, model, spec, uF, rF, sr, uSigmaEdgesMm, bias);
    Advice a;
    a.uNow = a.uThen = k * combinedSigma(now);
    auto consider = [&](AdviceInput input, double value, double u) {
        if (u < a.uThen) a.input = input, a.value = value, a.uThen = u;
    };
    const double declaredScaleVar = scaleRelSigma * scaleRelSigma;
    // A final height declared with the default tolerance: the reduction known to it, and the
    // scale no longer weighed against the silhouette's other explanations.
    ScaleAndReduction hFinal;
    const double hTol = spec.tolerances.hFinalMm / spec.h0Mm;
    hFinal.pk = declaredScaleVar, hFinal.pr = hTol * hTol;
    if (!declared) consider(AdviceInput::HFinal, 0, expandedWith(hFinal));
    // A final height measured to a micrometer's 0.01 mm.
    if (declared && spec.tolerances.hFinalMm > kAdvisedHFinalTolMm) {
        ScaleAndReduction closer = sr;
        const double t = kAdvisedHFinalTolMm / spec.h0Mm;
        closer.pr = std::min(sr.pr, t * t), closer.pkr = 0;
        consider(AdviceInput::HFinalTol, kAdvisedHFinalTolMm, expandedWith(closer));
    }
    // A scale measured on the end-face plane to 0.1 %.
    if (!calibrated && spec.tolerances.scaleRel > kAdvisedScaleRel) {
        ScaleAndReduction closer = sr;
        closer.pk = std::max(0.0, sr.pk - declaredScaleVar) + kAdvisedScaleRel * kAdvisedScaleRel;
        consider(AdviceInput::ScaleTol, kAdvisedScaleRel, expandedWith(closer));
    }
    // The camera's working distance, measured once for the set-up.
    if (withDistance) consider(AdviceInput::WorkingDistance, 0, expandedWith(*withDistance));
    // n from a flow curve fitted over the test's own strain range.
    if (spec.tolerances.n > kAdvisedNTol) {
        SpecimenSpec closer = spec;
        closer.tolerances.n = kAdvisedNTol;
        const MuFunction G(closer, model);
        const double u = k * combinedSigma(budgetOf(G, model, closer, uF, rF, sr, uSigmaEdgesMm, bias));
        consider(AdviceInput::NTol, kAdvisedNTol, u);
    }
    // Worth a line only where it shrinks U by a tenth.
    if (a.uThen > 0.9 * a.uNow) {
        a.input = AdviceInput::None, a.value = 0, a.uThen = a.uNow;
        a.modelLeads = now.model >= now.edges;
    }
    return a;
}

void decideStatus(const SpecimenSpec &spec, uint32_t f, Reading *out)
{
    out->toleranceMu = spec.tolerance.at(std::fabs(out->mu));
    out->coverage = spec.tolerance.coverage;
    out->decision = out->expanded() <= out->toleranceMu ? Decision::Within : Decision::Beyond;
    out->flags = f;
    out->status = f ? Status::Warn : Status::Ok;
    out->error = ErrorCode::None;
}

} // namespace icacam::reading
