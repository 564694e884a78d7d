#include "reading/interpretation.h"

#include <algorithm>
#include <cmath>

#include "friction/radii_consistency.h"
#include "reading/interpretation_steps.h"

namespace icacam::reading {

using friction::ModelEstimate;
using vision::EndFaceGeometry;

namespace {

// The silhouette measurement's own relative error, from its per-ray fit's scatter.
double silhouetteMeasuredRelSigma(double coverage, double scatterPx, double rMaxPx)
{
    return friction::measuredRMaxRelSigma(coverage > 0 && rMaxPx > 0 ? scatterPx / rMaxPx : 0);
}

// What the steps after the face is in millimetres read it with, images and radii alike.
struct FaceInputs {
    const SpecimenSpec &spec;
    const friction::FrictionModel &model;
    const AssumedReduction &assumed;
    double scaleRelSigma;                    // the declared scale's relative σ
    const EdgeSigma &edges;                  // the edges' part of u's error
    const SilhouetteObservation *silhouette; // nullptr: none held against the model (calibrated)
    double silhouetteSigma;                  // the silhouette's relative σ
    bool calibrated, oblique;
};

// No ray saw the original face's edge and the outline does not vouch for the ring the profile
// read: the face may show no edge of its own (as bright as the ring, its turning marks alone
// telling them apart), and the ring read is then the contact edge's own fall (1456 × 1088
// photographs of such faces read μ 0.04–0.19 low). The edge may lie anywhere out to the widest
// ring searched: u's σ that spans that μ, uniform, at the slope of μ(u) where the ring reads.
double unseenRingSigmaMm(const MuFunction &F, const SpecimenSpec &spec, double uMm, double r, double mu)
{
    const double widest = vision::kWidestRingOfR0 * 0.5 * spec.d0Mm;
    if (!(widest > uMm)) return 0;
    const double slope = std::fabs(F.slopeU(uMm, r, spec.n));
    const double spanMu = std::fabs(F.at(widest, r, spec.n) - mu);
    return slope > 0 ? spanMu / (slope * std::sqrt(12.0)) : (widest - uMm) / std::sqrt(12.0);
}

// The steps after the face is in millimetres, shared by images and radii; f: the image's own
// findings so far.
void readFace(const FaceInputs &in, uint32_t f, Reading *out)
{
    const SpecimenSpec &spec = in.spec;
    const friction::FrictionModel &model = in.model;
    const AssumedReduction &assumed = in.assumed;
    const EdgeSigma &edges = in.edges;
    const SilhouetteObservation *silhouette = in.silhouette;
    const double scaleRelSigma = in.scaleRelSigma, silhouetteSigma = in.silhouetteSigma;
    const bool calibrated = in.calibrated, oblique = in.oblique;
    const MuFunction F(spec, model);
    const double u = out->face.uMm, n = spec.n;
    ScaleAndReduction declared;
    declared.pk = scaleRelSigma * scaleRelSigma;
    declared.pr = assumed.sigma * assumed.sigma;
    ScaleAndReduction sr = declared;
    Explanations why;
    bool explained = false;
    ScaleAndReduction withDistance;
    bool distanceAdvice = false;
    if (silhouette) {
        out->rMaxZ = silhouette->rMaxZ;
        out->reductionEst = silhouette->reductionEst;
        // Without one the scale is unchecked too, in a tilted view as in a straight one: a
        // scale measured on the fixture would pass unseen (no_silhouette stays a finding).
        f |= silhouette->flags;
        if (silhouette->usable) {
            sr = silhouettePosterior(sr, *silhouette, silhouetteSigma, assumed.declared, oblique, &f, &why);
            explained = !assumed.declared;
            // Had the working distance been declared: the close camera's outline, to the table.
            SilhouetteObservation atDistance = *silhouette;
            if (declaredDistanceView(silhouette->view, &atDistance.view)) {
                uint32_t ignored = 0;
                withDistance =
                    silhouettePosterior(declared, atDistance, silhouetteSigma, assumed.declared, oblique, &ignored);
                distanceAdvice = true;
            }
        }
    }
    const double uF = u * std::exp(-sr.dk), rF = assumed.r + sr.dr;
    out->reduction = rF;
    out->reductionSigma = std::sqrt(sr.pr);
    out->scaleFactor = uF / u;
    out->uMm = uF;

    const MuReading read = readMu(F, model, spec, uF, rF, assumed.declared);
    out->mu = read.estimate.mu;
    if ((f & kFlagNarrowRing) && !edges.ringUnresolved &&
        narrowRingCorroborated(F, spec, uF, rF, out->mu, edges.narrowWidenMm * uF / u, silhouette))
        f &= ~kFlagNarrowRing;
    double uSigmaEdgesMm = edges.uSigmaEdgesMm;
    if ((f & kFlagNarrowRing) && (edges.ringFromProfile || edges.ringUnresolved))
        uSigmaEdgesMm = std::hypot(uSigmaEdgesMm, unseenRingSigmaMm(F, spec, uF, rF, out->mu));
    out->budget = budgetOf(F, model, spec, uF, rF, sr, uSigmaEdgesMm, read.bias);
    out->muSigma = combinedSigma(out->budget);
    out->advice = adviseInput(F, model, spec, uF, rF, sr, uSigmaEdgesMm, read.bias, assumed.declared, calibrated,
                              scaleRelSigma, distanceAdvice ? &withDistance : nullptr);
    out->advice.reductionUnchecked = !assumed.declared && !explained;
    out->advice.heightDeclared = assumed.declared;
    const ModelEstimate asDeclared = model.estimate({u, n, spec.kMpa, spec.d0Mm, spec.h0Mm, spec.hFinalMm});
    out->declared = {asDeclared.mu, asDeclared.dMuDu};
    out->nominalMu = F.at(u, kNominalReduction, n);
    // A silhouette found unusable is a finding of its own (silhouette_unreliable, no_silhouette);
    // where the image has none to check the height with, U covers the undeclared range.
    if (explained) f |= nominalCheck(F, spec, u, out->mu, &why, &out->nominalMu);
    // Without a silhouette the height and the declared scale are unchecked (U covers the
    // undeclared range, the advice says so); a finding where they could move μ beyond the
    // tolerance, not where μ barely depends on them.
    if ((f & kFlagNoSilhouette) && !assumed.declared && !calibrated &&
        !uncheckedViewMatters(F, spec, declared, u, out->mu))
        f &= ~kFlagNoSilhouette;
    decideStatus(spec, f | rangeChecks(model, read, assumed), out);
}

// The FE's R_max the silhouette is held against depends on μ (the barrel grows with it):
// taken first at μ as the ring reads at the assumed height, it is taken again at the μ the
// reading arrives at where the silhouette moved the height. A specimen pressed to 48 % reads
// μ 0.02–0.04 low at 50 %, and at that μ the FE's R_max is 0.3–0.4 % smaller: the silhouette
// looked 0.004 of reduction nearer half height than it was.
bool reobserve(const AssumedReduction &assumed, const SilhouetteObservation &obs, const Reading &out)
{
    return !assumed.declared && obs.usable && std::fabs(out.reduction - assumed.r) > 1e-4;
}

// μ of the specimen as the reading has it: the ring at its corrected scale, at the inferred
// height (carried there for a model that reads at 50 % only).
double specimenMu(const SpecimenSpec &spec, const friction::FrictionModel &model, const Reading &out)
{
    return MuFunction(spec, model).at(out.uMm, out.reduction, spec.n);
}

} // namespace

double silhouetteRelSigma(const EndFaceGeometry &g)
{
    return std::hypot(friction::kFeRMaxRelSigma,
                      silhouetteMeasuredRelSigma(g.silhouetteCoverage, g.silhouetteScatterPx, g.rMaxPx));
}

Reading interpret(const EndFaceGeometry &g, const SpecimenSpec &spec, const vision::PlaneCalibration *calibration,
                  const friction::FrictionModel &model)
{
    Reading out;
    out.geometry = g;
    out.error = g.error;
    if (g.error != ErrorCode::None) return out;
    const AssumedReduction assumed = assumedReduction(spec);
    const PlaneMapping p = mapFace(g, spec, calibration, assumed);
    if (!p.valid) {
        out.error = ErrorCode::BadSpecimen;
        return out;
    }
    out.face = p.face;
    out.innerShape = p.inner, out.outerShape = p.outer;
    out.uPx = g.outer.rEqPx - g.inner.rEqPx;
    const EdgeSigma e = edgeSigma(g, p, calibration != nullptr);
    out.uSigmaMm = e.uSigmaMm;
    const uint32_t f = imageChecks(g, p, e, spec.d0Mm, &out.centreOffsetPx);
    // The image shows the camera oblique: the boundaries share an ellipse, or part.
    const bool oblique = e.sharedEllipse || (f & kFlagCentreOffset);

    // An oblique view hides the barrel's outline on its far side: no silhouette is what such
    // a view shows, not a finding about the specimen. The height and the declared scale are
    // unchecked, which U (the undeclared reduction's range, the tilt term) and the advice
    // carry; a straight view without one stays no_silhouette.
    const bool outlineHiddenByView = !(g.rMaxPx > 0) && (g.imageFlags & vision::kImageBarrelOblique);
    // The outline's centre weighs the working distance unless the boundaries are off-centre: an
    // ellipse they share alone is as often the specimen's own (a body 0.8 % oval, an original
    // face 1–2 % out of round: ellipticities 0.012–0.03 on straight rendered photographs) as a
    // tilt, and a tilt's shift of the outline across or beyond the perspective's line is
    // caught there as some other view's.
    const CameraDistance camera = cameraDistance(spec, g, (f & kFlagCentreOffset) != 0);
    SilhouetteObservation obs;
    const SilhouetteObservation *silhouette = nullptr;
    auto observeAt = [&](double mu) {
        obs =
            observeSilhouette(p.face, g.silhouetteCoverage, g.silhouetteScatterPx, g.rMaxPx, spec, assumed, mu, camera);
        // Where the outline cannot be told from the fixture's shadow beyond it, the radius
        // taken may be either: it neither rescales nor says another height, and the reading
        // is that of a view without a silhouette (the height unchecked, U covering 45–55 %; the
        // declared scale unchecked too, which no_silhouette says: a scale measured on the
        // fixture would otherwise pass 0.01–0.04 high, CalibratedMeasure.*).
        // An outline only the mean profile's smear rivals, its centre drawn towards the axis
        // as a straight close camera draws it (camera.fromImage), is the barrel's.
        const bool smearedByView = (g.imageFlags & vision::kImageOutlineSmeared) && camera.fromImage;
        if ((g.imageFlags & vision::kImageOutlineAmbiguous) && !smearedByView)
            obs.usable = false, obs.flags = kFlagNoSilhouette;
        if (outlineHiddenByView) obs.flags &= ~kFlagNoSilhouette;
    };
    if (!calibration) {
        // Calibrated: R_max is reported, not held against the model.
        observeAt(MuFunction(spec, model).at(p.face.uMm, assumed.r, spec.n));
        silhouette = &obs;
    }
    auto read = [&] {
        readFace({spec, model, assumed, p.scaleRelSigma, e, silhouette, silhouetteRelSigma(g), calibration != nullptr,
                  oblique},
                 f, &out);
    };
    read();
    if (silhouette && reobserve(assumed, obs, out)) {
        observeAt(specimenMu(spec, model, out));
        read();
    }
    out.advice.scaleUnchecked = silhouette && outlineHiddenByView;
    if (g.imageFlags & vision::kImageSegmentsMisplaced)
        out.advice.segment0SeenDeg = g.segment0SeenDeg, out.advice.segmentWay = g.segmentWay;
    return out;
}

Reading interpret(const FaceInMm &face, const SpecimenSpec &spec, const friction::FrictionModel &model)
{
    Reading out;
    out.imaged = false;
    out.error = ErrorCode::None;
    out.geometry.error = ErrorCode::None;
    out.face = face;
    out.face.uMm = face.rOuterMm - face.rInnerMm;
    const AssumedReduction assumed = assumedReduction(spec);
    const MuFunction F(spec, model);
    const double silhouetteSigma = std::hypot(friction::kFeRMaxRelSigma, friction::measuredRMaxRelSigma(0));
    SilhouetteObservation obs;
    auto readAt = [&](double mu) {
        obs = observeSilhouette(out.face, 1, 0, face.rMaxMm, spec, assumed, mu, declaredCameraDistance(spec));
        const EdgeSigma noEdges;
        readFace({spec, model, assumed, spec.tolerances.scaleRel, noEdges, &obs, silhouetteSigma, false, false}, 0,
                 &out);
    };
    readAt(F.at(out.face.uMm, assumed.r, spec.n));
    if (reobserve(assumed, obs, out)) readAt(specimenMu(spec, model, out));
    return out;
}

} // namespace icacam::reading
