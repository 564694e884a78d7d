#include "vision/reading_interpreter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "friction/aspect_corrected_model.h"
#include "friction/radii_consistency.h"
#include "friction/reduction_corrected_model.h"
#include "vision/plane_calibration.h"

namespace icacam::vision {

using namespace icacam::friction;

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
// scale grossly off (one measured on the fixture rather than the end face, or on a wrong
// edge, is 5–12 % off at 70–150 mm working distance: σ 8 %). Where the silhouette agrees with
// half height the first dominates and the reduction is known to the press's tolerance; where
// it does not, the others take over, and the mixture's spread covers the step between them.
constexpr double kNominalReductionSigma = 0.003;
constexpr double kGrossScaleSigma = 0.08;
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
// The edge model's own error, beyond the fits' scatter: against the drawn boundaries of the
// development set's photographs the pipeline's R_i lies 0.005 mm (1 σ) off the truth's
// equivalent radius and R_o 0.001 mm (a ragged texture boundary, not a step, on the inside).
constexpr double kInnerEdgeModelMm = 0.005, kOuterEdgeModelMm = 0.001;

// μ as a function of the inputs the budget varies: the ring u (mm) read at reduction r with
// exponent n, carried to the model's 50 % (through the FE slope for a model that does not
// carry itself).
class MuFunction {
public:
    MuFunction(const SpecimenSpec &spec, const FrictionModel &model)
            : spec_(spec), model_(model), carry_(model, model.name())
    {}
    double at(double u, double r, double n) const { return estimate(u, r, n).mu; }
    ModelEstimate estimate(double u, double r, double n) const
    {
        const ModelInputs in{u, n, spec_.kMpa, spec_.d0Mm, spec_.h0Mm, spec_.h0Mm * (1 - r)};
        return model_.correctsReduction() ? model_.estimate(in) : carry_.estimate(in);
    }

private:
    const SpecimenSpec &spec_;
    const FrictionModel &model_;
    ReductionCorrectedModel carry_;
};

struct ScaleAndReduction {
    double dk = 0, dr = 0;          // corrections: relative scale error, reduction offset
    double pk = 0, pr = 0, pkr = 0; // their (co)variances
};

// The silhouette's observation d = δk + β·δr + o + e (e of variance se2: silhouetteRelSigma;
// o an offset of the silhouette alone, with its mean and variance) applied to a prior on
// (δk, δr): the posterior mean and covariance (a linear Gaussian update), widened by χ² where d
// lies further out than the prior and e explain (as for a Birge ratio).
ScaleAndReduction update(const ScaleAndReduction &prior, double d, double beta, double se2, double offset = 0,
                         double offsetVar = 0)
{
    const double S = prior.pk + beta * beta * prior.pr + se2 + offsetVar;
    const double v = d - offset;
    const double w = std::max(1.0, v * v / S);
    ScaleAndReduction p;
    p.dk = prior.pk / S * v;
    p.dr = beta * prior.pr / S * v;
    p.pk = w * (prior.pk - prior.pk * prior.pk / S);
    p.pr = w * (prior.pr - beta * beta * prior.pr * prior.pr / S);
    p.pkr = -w * beta * prior.pk * prior.pr / S;
    return p;
}

// The silhouette measurement's own relative error, from its per-ray fit's scatter.
double silhouetteMeasuredRelSigma(const Measurement &m)
{
    return measuredRMaxRelSigma(m.silhouetteCoverage > 0 && m.rMaxPx > 0 ? m.silhouetteScatterPx / m.rMaxPx : 0);
}

} // namespace

double silhouetteRelSigma(const Measurement &m)
{
    return std::hypot(kFeRMaxRelSigma, silhouetteMeasuredRelSigma(m));
}

void interpretEndFace(const SpecimenSpec &spec, const FrictionModel &model, Measurement *m)
{
    if (m->error != ErrorCode::None) {
        m->status = Status::Error;
        return;
    }
    const DeclaredTolerances &tol = spec.tolerances;
    const bool declared = spec.hFinalMm > 0 && spec.hFinalMm < spec.h0Mm;
    const double r0 = declared ? 1.0 - spec.hFinalMm / spec.h0Mm : kNominalReduction;
    const double sigmaR0 = declared ? tol.hFinalMm / spec.h0Mm : kUndeclaredReductionSigma;
    double sigmaK0 = tol.scaleRel;

    // Geometry in millimetres.
    double s = spec.mmPerPx;
    m->rInnerMm = m->inner.rEqPx * s;
    m->rOuterMm = m->outer.rEqPx * s;
    m->rMaxMm = m->rMaxPx * s;
    m->uPx = m->outer.rEqPx - m->inner.rEqPx;
    m->uMm = m->uPx * s;
    double planeOffsetPx = -1;
    if (spec.calibration) {
        // Each boundary mapped point by point into the end-face plane (undistorted, tilt
        // removed, at the specimen's height); s becomes the contact edge's effective scale.
        PlaneCalibration plane = *spec.calibration;
        plane.heightMm = spec.h0Mm * (1.0 - r0);
        const PlaneOutline pi = planeOutline(m->inner, m->centreX, m->centreY, plane);
        const PlaneOutline po = planeOutline(m->outer, m->centreX, m->centreY, plane);
        if (!(pi.valid && po.valid && m->outer.rEqPx > 0)) {
            m->status = Status::Error;
            m->error = ErrorCode::BadSpecimen;
            return;
        }
        m->rInnerMm = pi.rEqMm, m->rOuterMm = po.rEqMm, m->uMm = po.rEqMm - pi.rEqMm;
        s = po.rEqMm / m->outer.rEqPx;
        // The shape checks judge the end face itself, not the camera's view of it.
        m->inner.ellipticity = pi.ellipticity, m->inner.axisDeg = pi.axisDeg;
        m->outer.ellipticity = po.ellipticity, m->outer.axisDeg = po.axisDeg;
        planeOffsetPx = std::hypot(pi.centroidX - po.centroidX, pi.centroidY - po.centroidY) / s;
        // The barrel is widest about half-way down: its silhouette maps at half the height.
        BoundaryFit silhouette;
        silhouette.a0 = m->rMaxPx;
        PlaneCalibration mid = plane;
        mid.heightMm *= 0.5;
        m->rMaxMm = m->rMaxPx > 0 ? equivalentRadiusMm(silhouette, m->centreX, m->centreY, mid) : 0;
        // The plane's height is as uncertain as the reduction: its part of the scale.
        const double dh = spec.h0Mm * sigmaR0;
        PlaneCalibration up = plane, down = plane;
        up.heightMm += dh, down.heightMm -= dh;
        const double sUp = planeScaleAt(up, m->centreX, m->centreY);
        const double sDown = planeScaleAt(down, m->centreX, m->centreY);
        const double heightPart = sUp > 0 && sDown > 0 ? std::fabs(sUp - sDown) / (sUp + sDown) : 0.01;
        sigmaK0 = std::hypot(tol.calibrationScaleRel, heightPart);
    }

    // u's own uncertainty: the fits' scatter and a 0.1 px location floor per boundary, and the
    // edge model's error in millimetres; an uncalibrated camera's tilt shrinks the equal-area
    // radii by up to e/2 (e the shared ellipticity), which the declared scale may or may not
    // have absorbed.
    const double sigPx = std::sqrt(m->inner.rEqSigmaPx * m->inner.rEqSigmaPx +
                                   m->outer.rEqSigmaPx * m->outer.rEqSigmaPx + 2 * 0.1 * 0.1);
    m->uSigmaMm = sigPx * s;
    const double axisDiff = std::fabs(std::remainder(m->inner.axisDeg - m->outer.axisDeg, 180.0));
    const bool sharedEllipse = m->inner.ellipticity > 0.012 && m->outer.ellipticity > 0.012 && axisDiff < 20;
    double uSigmaEdges = std::hypot(m->uSigmaMm, std::hypot(kInnerEdgeModelMm, kOuterEdgeModelMm));
    if (!spec.calibration && sharedEllipse) {
        const double e = std::min(m->inner.ellipticity, m->outer.ellipticity);
        uSigmaEdges = std::hypot(uSigmaEdges, m->uMm * e / (2 * std::sqrt(3.0)));
    }

    // Image-quality flags.
    uint32_t f = m->flags;
    const double r0Px = 0.5 * spec.d0Mm / s;
    if (std::min(m->inner.coverage, m->outer.coverage) < 0.6) f |= kFlagLowCoverage;
    if (std::max(m->inner.scatterPx, m->outer.scatterPx) > std::max(1.5, 0.006 * r0Px)) f |= kFlagHighScatter;
    if (std::fabs(m->inner.contrast) < 5.0) f |= kFlagLowContrast;
    m->centreOffsetPx = planeOffsetPx >= 0
                            ? planeOffsetPx
                            : std::hypot(m->inner.centreX - m->outer.centreX, m->inner.centreY - m->outer.centreY);
    if (m->centreOffsetPx > std::max(3.0, 0.012 * r0Px)) f |= kFlagCentreOffset;
    if (sharedEllipse) f |= kFlagElliptical;
    if (m->uPx < 3.0) f |= kFlagNarrowRing;
    if (m->edgeWidthPx > 2.6) f |= kFlagBlurred;
    if (m->saturatedFraction > 0.02) f |= kFlagSaturated;

    const MuFunction F(spec, model);
    const double u = m->uMm, n = spec.n;
    const double mu0 = F.at(u, r0, n);

    // The silhouette as an observation of scale and reduction (see the header).
    ScaleAndReduction sr;
    sr.pk = sigmaK0 * sigmaK0;
    sr.pr = sigmaR0 * sigmaR0;
    double d = 0, beta = 0;
    double dContact = 0; // d for a silhouette at the smallest accepted radius (just outside R_o)
    bool usable = false;
    if (spec.calibration) {
        // Calibrated: R_max is reported, not held against the model.
    } else if (m->rMaxPx > 0) {
        const RadiiCheck rc =
            checkRadii(m->rMaxMm, n, mu0, spec.d0Mm, r0, spec.h0Mm, true, silhouetteMeasuredRelSigma(*m));
        m->rMaxZ = rc.z;
        m->reductionEst = rc.reductionEst;
        if (rc.inconsistent()) f |= declared ? kFlagRadiiInconsistent : kFlagScaleSuspect;
        const RadiiCheck up = checkRadii(m->rMaxMm, n, mu0, spec.d0Mm, r0 + 0.01, spec.h0Mm, false);
        const RadiiCheck down = checkRadii(m->rMaxMm, n, mu0, spec.d0Mm, r0 - 0.01, spec.h0Mm, false);
        const double overContact = m->rMaxMm / m->rOuterMm;
        usable = rc.valid && up.valid && down.valid && m->silhouetteCoverage >= kSilhouetteMinCoverage &&
                 overContact > kSilhouetteOverContactMin && overContact < kSilhouetteOverContactMax;
        if (usable) {
            d = std::log(m->rMaxMm / rc.rMaxFeMm);
            dContact = std::log(kSilhouetteOverContactMin * m->rOuterMm / rc.rMaxFeMm);
            beta = std::log(up.rMaxFeMm / down.rMaxFeMm) / 0.02;
            usable = beta > 0.1;
        }
        if (!usable) f |= kFlagSilhouetteUnreliable;
    } else {
        f |= kFlagNoSilhouette;
    }
    const double se = silhouetteRelSigma(*m), se2 = se * se;
    if (usable && declared) {
        const double S = sr.pk + beta * beta * sr.pr + se2;
        if (d * d / S > kContradictionChi2) {
            // Declared scale and height cannot both be right: neither is corrected, and each
            // is widened to explain the whole discrepancy alone.
            sr.pk = std::max(sr.pk, d * d);
            sr.pr = std::max(sr.pr, d * d / (beta * beta));
        } else {
            sr = update(sr, d, beta, se2);
        }
    } else if (usable) {
        // Three explanations of the silhouette's discrepancy, four in an oblique view (see
        // kNominalReductionSigma and kForeshortenMean), and a wrong edge (kMisreadPrior): each
        // one's posterior, weighted by its prior and how well it predicts d, and their
        // mixture's moments.
        constexpr int kExplanations = 5;
        constexpr int kMisread = 4;
        ScaleAndReduction prior[kExplanations];
        prior[0] = sr;                                     // pressed to another height
        prior[1].pk = kGrossScaleSigma * kGrossScaleSigma; // half height, a scale off
        prior[1].pr = kNominalReductionSigma * kNominalReductionSigma;
        prior[2].pk = sr.pk; // half height, scale as declared
        prior[2].pr = kNominalReductionSigma * kNominalReductionSigma;
        prior[3] = prior[2];  // half height, scale as declared, the silhouette foreshortened
        prior[kMisread] = sr; // a wrong edge: the silhouette tells nothing
        const double offset[kExplanations] = {0, 0, 0, kForeshortenMean, 0};
        const double offsetVar[kExplanations] = {0, 0, 0, kForeshortenSigma * kForeshortenSigma, 0};
        const bool oblique = (f & (kFlagElliptical | kFlagCentreOffset)) != 0;
        const double gaussianPrior = (1.0 - kMisreadPrior) / (oblique ? 4 : 3);
        ScaleAndReduction post[kExplanations];
        double w[kExplanations], wSum = 0;
        for (int h = 0; h < kMisread; ++h) {
            const double S = prior[h].pk + beta * beta * prior[h].pr + se2 + offsetVar[h];
            const double v = d - offset[h];
            // Densities up to the common 1/√(2π).
            w[h] = h != 3 || oblique ? gaussianPrior * std::exp(-0.5 * v * v / S) / std::sqrt(S) : 0.0;
            wSum += w[h];
            post[h] = update(prior[h], d, beta, se2, offset[h], offsetVar[h]);
        }
        const double misreadSpan = -kMisreadMinInside - dContact;
        const bool misreadPossible = misreadSpan > 0 && d >= dContact && d <= -kMisreadMinInside;
        w[kMisread] = misreadPossible ? kMisreadPrior * std::sqrt(2 * std::numbers::pi) / misreadSpan : 0.0;
        wSum += w[kMisread];
        post[kMisread] = prior[kMisread];
        sr = ScaleAndReduction{};
        for (int h = 0; h < kExplanations; ++h) {
            w[h] = wSum > 0 ? w[h] / wSum : 1.0 / kExplanations;
            sr.dk += w[h] * post[h].dk;
            sr.dr += w[h] * post[h].dr;
        }
        // A discrepancy the view's foreshortening explains best is not the scale's: the
        // elliptical or centre_offset flag names its cause.
        if (oblique && w[3] >= std::max({w[0], w[1], w[2]})) f &= ~uint32_t(kFlagScaleSuspect);
        // A silhouette more likely a wrong edge than the barrel's outline is not relied on.
        if (w[kMisread] >= std::max({w[0], w[1], w[2], w[3]})) f |= kFlagSilhouetteUnreliable;
        for (int h = 0; h < kExplanations; ++h) {
            const double gk = post[h].dk - sr.dk, gr = post[h].dr - sr.dr;
            sr.pk += w[h] * (post[h].pk + gk * gk);
            sr.pr += w[h] * (post[h].pr + gr * gr);
            sr.pkr += w[h] * (post[h].pkr + gk * gr);
        }
    }
    const double uF = u * std::exp(-sr.dk), rF = r0 + sr.dr;
    m->reduction = rF;
    m->reductionSigma = std::sqrt(sr.pr);
    m->scaleFactor = uF / u;
    m->rInnerMm *= m->scaleFactor, m->rOuterMm *= m->scaleFactor, m->rMaxMm *= m->scaleFactor;
    m->uMm = uF;

    // The reading: a model that carries u to 50 % itself reads at rF; one that does not (the
    // paper's fit as published) reads as is, and the carry it leaves out is in the budget.
    ModelEstimate est;
    double bias = 0;
    if (model.correctsReduction()) {
        est = F.estimate(uF, rF, n);
        if (!declared) est.range &= ~uint32_t(kModelReductionOutside); // the inferred reduction is budgeted
    } else {
        est = model.estimate({uF, n, spec.kMpa, spec.d0Mm, spec.h0Mm, 0});
        bias = F.at(uF, rF, n) - est.mu;
    }
    m->mu = est.mu;

    // Sensitivities by central differences of the model at the reading's inputs.
    const double hu = std::max(1e-4, 0.01 * uF), hr = 0.005, hn = std::max(1e-4, tol.n);
    const double gU = (F.at(uF + hu, rF, n) - F.at(std::max(0.0, uF - hu), rF, n)) / (uF + hu - std::max(0.0, uF - hu));
    const double gR = (F.at(uF, rF + hr, n) - F.at(uF, rF - hr, n)) / (2 * hr);
    const double gN = (F.at(uF, rF, n + hn) - F.at(uF, rF, n - hn)) / (2 * hn);
    const double a = -uF * gU; // per unit relative scale error
    // The carry's own error: a quarter of its effect (the FE slope is resolution-limited).
    const double carry = 0.25 * std::fabs(F.at(uF, rF, n) - F.at(uF, kNominalReduction, n));
    UncertaintyBudget &b = m->budget;
    b.edges = std::fabs(gU) * uSigmaEdges;
    // Scale and reduction are correlated through the silhouette: their covariance term is
    // shared between the two, so that the components add in quadrature to mu_sigma.
    const double cross = a * gR * sr.pkr;
    b.scale = std::sqrt(std::max(0.0, a * a * sr.pk + cross));
    b.reduction = std::sqrt(std::max(0.0, gR * gR * sr.pr + cross) + carry * carry + bias * bias);
    b.n = std::fabs(gN) * tol.n;
    b.model = model.estimate({uF, n, spec.kMpa, spec.d0Mm, spec.h0Mm, 0}).modelSigma;
    m->muSigma =
        std::sqrt(b.edges * b.edges + b.scale * b.scale + b.reduction * b.reduction + b.n * b.n + b.model * b.model);

    if (est.range & (kModelNBelow | kModelNAbove)) f |= kFlagNOutOfRange;
    if (est.range & kModelKOutside) f |= kFlagKOutOfRange;
    if (est.range & kModelMuBelow) f |= kFlagMuBelowRange;
    if (est.range & kModelMuAbove) f |= kFlagMuAboveRange;
    if (est.range & kModelUOutside) f |= kFlagUOutsideModel;
    if (est.range & kModelAspectOutside) f |= kFlagAspectOutside;
    if (model.correctsReduction()) {
        if (est.range & kModelReductionOutside) f |= kFlagReductionOutside;
    } else if (declared && std::fabs(r0 - kNominalReduction) > 0.01) {
        f |= kFlagReductionOutside;
    }

    // Status from the budget.
    m->toleranceMu = spec.tolerance.at(std::fabs(m->mu));
    if (spec.tolerance.coverage * m->muSigma > m->toleranceMu) {
        const double parts[5] = {b.edges, b.scale, b.reduction, b.n, b.model};
        const uint32_t names[5] = {kFlagEdgesUncertain, kFlagScaleUncertain, kFlagReductionUncertain, kFlagNUncertain,
                                   kFlagModelUncertain};
        f |= names[std::max_element(parts, parts + 5) - parts];
    }
    m->flags = f;
    m->status = f ? Status::Warn : Status::Ok;
    m->error = ErrorCode::None;
}

} // namespace icacam::vision
