#pragma once
// The interpretation's steps (interpretation.h), each a function of its own so that each can
// be tested alone: the final height assumed, the face in millimetres (the plane mapping),
// u's edge uncertainty, the image's checks, the silhouette's observation and the posterior of
// scale and reduction it gives, the nominal conditions' check, μ, the budget, the advice, the
// status and the tolerance decision.
#include <cstdint>

#include "friction/friction_model.h"
#include "friction/reduction_corrected_model.h"
#include "reading/reading.h"
#include "reading/specimen_spec.h"
#include "vision/end_face_geometry.h"
#include "vision/plane_calibration.h"

namespace icacam::reading {

// The final height the reading assumes: declared (with its tolerance) or the test's nominal
// half height with the undeclared prior.
struct AssumedReduction {
    bool declared = false;
    double r = kNominalReduction;
    double sigma = kUndeclaredReductionSigma;
};
AssumedReduction assumedReduction(const SpecimenSpec &spec);

// The face in millimetres: each boundary scaled by the declared mm_per_px, or mapped point by
// point into the end-face plane through a calibration (undistorted, tilt removed, at the
// specimen's height). valid is false when a boundary does not map.
struct PlaneMapping {
    bool valid = true;
    FaceInMm face;
    double mmPerPx = 0; // the contact edge's effective scale
    BoundaryShape inner, outer;
    double centreOffsetPx = -1; // in the plane, in pixels at mmPerPx (-1: judged in the image)
    double scaleRelSigma = 0;   // the scale's relative standard uncertainty
};
PlaneMapping mapFace(const vision::EndFaceGeometry &g, const SpecimenSpec &spec,
                     const vision::PlaneCalibration *calibration, const AssumedReduction &r);

// u's uncertainty from the edges: the fits' scatter and a location floor (uSigmaMm), and with
// the edge model's error and an uncalibrated tilt (uSigmaEdgesMm).
struct EdgeSigma {
    double uSigmaMm = 0;
    double uSigmaEdgesMm = 0;
    bool sharedEllipse = false; // both boundaries elliptical along one axis
    double narrowWidenMm = 0;   // how much wider a ring read narrow may read than it is
    // No ray saw the original face's edge: the profile alone read the ring (narrow_ring).
    bool ringFromProfile = false;
    // The ring's two edges lie closer than twice their blur: not resolved (narrow_ring), and
    // neither the outline nor a small widening vouches for the width read.
    bool ringUnresolved = false;
};
EdgeSigma edgeSigma(const vision::EndFaceGeometry &g, const PlaneMapping &p, bool calibrated);

// The image's own checks: coverage, scatter, contrast, concentricity, an ellipse beyond the
// tilt the budget covers, a narrow ring, blur, saturation, and what the pipeline reported
// (ImageFlag).
uint32_t imageChecks(const vision::EndFaceGeometry &g, const PlaneMapping &p, const EdgeSigma &e, double d0Mm,
                     double *centreOffsetPx);

// μ as a function of the inputs the budget varies: the ring u (mm) read at reduction r with
// exponent n, carried to the model's 50 % (through the FE slope for a model that does not
// carry itself).
class MuFunction {
public:
    MuFunction(const SpecimenSpec &spec, const friction::FrictionModel &model);
    double at(double u, double r, double n) const { return estimate(u, r, n).mu; }
    friction::ModelEstimate estimate(double u, double r, double n) const;
    // dμ/du at u (a central difference over 1 % of u, one-sided where it would cross 0).
    double slopeU(double u, double r, double n) const;

private:
    const SpecimenSpec &spec_;
    const friction::FrictionModel &model_;
    friction::ReductionCorrectedModel carry_;
};

// The scale's relative error and the reduction's offset, with their (co)variances.
struct ScaleAndReduction {
    double dk = 0, dr = 0;          // corrections: relative scale error, reduction offset
    double pk = 0, pr = 0, pkr = 0; // their (co)variances
};

// The silhouette held against the FE's shape: d = ln(R_max / R_max,FE) at the assumed
// reduction, β = ∂ln R_max,FE/∂r, and whether it is usable as an observation of scale and
// reduction. flags: scale_suspect, radii_inconsistent, silhouette_unreliable, no_silhouette.
// The view's own part of d: ln(outline / R_max) of a camera at working distance W
// (friction/outline_ratio.h) and its variance. Where the image leaves both open, two views,
// each with its weight: a telecentric one and a close camera's (the share s weighed by the
// outline's centre shift); the silhouette's explanations then weigh each against d.
struct OutlineView {
    static constexpr int kMax = 2;
    int count = 1;
    bool estimated = false; // from the image (no working distance declared)
    double weight[kMax] = {1, 0};
    double offset[kMax] = {0, 0}, var[kMax] = {0, 0};
};
// What the instrument knows of the camera's distance to the end face. Declared: D0/W, to W's
// 5 %, which bounds the share s by the depth of the barrel's widest section (the side's shape
// below the end face stays open). Otherwise what the image says: a close camera sees the side below the end face from
// farther away, so an end face off the optical axis has its outline's centre drawn towards
// the axis (friction::outlineShiftAt); the shift against the end face's distance from the
// axis weighs that share from a telecentric view (half the prior) to a camera at 40 mm (the
// other half); an end face on the axis leaves the prior's spread. Neither (no silhouette
// centre, an oblique view, a shift no straight camera makes): telecentric.
struct CameraDistance {
    double d0OverW = 0;                // declared D0/W; 0 where none is declared
    double h0OverD0 = 1.5;             // the specimen's H0/D0 (the depth of its widest section)
    bool fromImage = false;            // weigh the perspective share by the outline's centre shift
    double offAxisX = 0, offAxisY = 0; // the end face's centre less the optical axis (px)
    double shiftX = 0, shiftY = 0;     // the outline's centre less the end face's (px)
    double shiftSigmaPx = 0;           // the two centres' own error, per axis
    double axisSigmaPx = 0;            // where the optical axis lies, per axis
};
OutlineView outlineView(double n, double mu, double reduction, const CameraDistance &camera);
// The view had the working distance been declared (the advice): the close camera's outline the
// image weighed, with its own spread, the telecentric alternative gone; false where the view
// was declared or not weighed.
bool declaredDistanceView(const OutlineView &estimated, OutlineView *declared);
// D0/W of the spec's declared working distance, or (none declared, a view whose boundaries
// are concentric, with a per-ray silhouette) the image's outline centre against its end face's.
CameraDistance cameraDistance(const SpecimenSpec &spec, const vision::EndFaceGeometry &g, bool oblique);

struct SilhouetteObservation {
    bool usable = false;
    double d = 0, beta = 0;
    double dContact = 0; // d for a silhouette at the smallest accepted radius (just outside R_o)
    double rMaxZ = 0;
    double reductionEst = -1;
    double measuredRelSigma = 0; // the measurement's own relative error
    OutlineView view;            // the camera's part of d
    uint32_t flags = 0;
};
// coverage, scatterPx: the silhouette's per-ray fit (coverage 1 and scatter 0 for a radius
// given as a number). camera: as outlineView.
SilhouetteObservation observeSilhouette(const FaceInMm &face, double coverage, double scatterPx, double rMaxPx,
                                        const SpecimenSpec &spec, const AssumedReduction &r, double mu0,
                                        const CameraDistance &camera);
// The spec's declared working distance alone (radii given as numbers: no image to say more).
CameraDistance declaredCameraDistance(const SpecimenSpec &spec);

// A ring read narrow (narrow_ring) may read up to narrowWidenMm too wide, or, on a photograph,
// on the wrong steps altogether. Where the barrel's outline agrees with the μ it reads and
// that widening cannot move μ beyond the tolerance, the narrow ring is no finding: true.
bool narrowRingCorroborated(const MuFunction &F, const SpecimenSpec &spec, double uMm, double r, double mu,
                            double narrowWidenMm, const SilhouetteObservation *silhouette);

// The silhouette's explanations of its discrepancy where no final height is declared
// (interpretation.h): each one's posterior of scale and reduction and its weight.
struct Explanations {
    enum Which { OtherHeight, ScaleOff, Nominal, Foreshortened, WrongEdge, kCount };
    ScaleAndReduction post[kCount];
    double weight[kCount] = {};
    // Each explanation within each view the image left open (a telecentric and a close
    // camera): its share of the weight and its scale and reduction (viewCount 0: one view,
    // the explanations as above).
    int viewCount = 0;
    double partWeight[OutlineView::kMax][kCount] = {};
    ScaleAndReduction part[OutlineView::kMax][kCount];
};

// The posterior of scale and reduction given the silhouette (interpretation.h): a linear
// update where the final height is declared, the mixture of explanations where it is not
// (then *why, when given, receives them; oblique: the view is tilted, so a foreshortened
// silhouette is one of them). *flags may gain silhouette_unreliable.
ScaleAndReduction silhouettePosterior(const ScaleAndReduction &prior, const SilhouetteObservation &obs,
                                      double silhouetteRelSigma, bool declared, bool oblique, uint32_t *flags,
                                      Explanations *why = nullptr);

// The method's nominal conditions checked where no final height is declared: μ at the
// nominal half height with the declared scale, and under every explanation of the silhouette
// that keeps some weight, against the reading's μ. Any of them beyond the tolerance is a
// finding: reduction_not_nominal, or scale_suspect where a scale off explains the silhouette
// best. Where the silhouette was seen (weighRisk false) what it says is the finding: the share
// of the weight whose explanations (within each view the image left open) read μ beyond the
// tolerance, by their means; the spread each leaves is U's. Where that share lies in a close
// or a telecentric view alone the camera's distance decides it: working_distance_decides.
// Where nothing checked the height (weighRisk true) the chance that μ lies beyond the
// tolerance under the explanations' priors, spreads and all, is the finding.
// *nominalMu: μ at the nominal conditions.
uint32_t nominalCheck(const MuFunction &F, const SpecimenSpec &spec, double uDeclaredMm, double mu,
                      const Explanations *why, double *nominalMu, bool weighRisk = false);

// A straight view without a silhouette, no final height declared: the height and the
// declared scale go unchecked, and the explanations keep their prior weights (nominal half
// height; another height over the undeclared range; a scale measured on the fixture). True
// where they leave more than the nominal check's chance that μ lies beyond the tolerance:
// then no_silhouette is a finding; where μ barely depends on them it is not.
// declared: the declared scale's and reduction's prior (as silhouettePosterior takes it).
bool uncheckedViewMatters(const MuFunction &F, const SpecimenSpec &spec, const ScaleAndReduction &declared, double uMm,
                          double mu);

// μ at the corrected u and reduction; bias: the carry to 50 % a model that does not carry
// itself leaves out (budgeted).
struct MuReading {
    friction::ModelEstimate estimate;
    double bias = 0;
};
MuReading readMu(const MuFunction &F, const friction::FrictionModel &model, const SpecimenSpec &spec, double uMm,
                 double r, bool declared);

// The budget's components at the reading's inputs (sensitivities by central differences).
UncertaintyBudget budgetOf(const MuFunction &F, const friction::FrictionModel &model, const SpecimenSpec &spec,
                           double uMm, double r, const ScaleAndReduction &sr, double uSigmaEdgesMm, double bias);
double combinedSigma(const UncertaintyBudget &b);

// The declared input that would shrink U the most: the budget again with that input declared
// or declared closer (h_final_mm where none is, h_final_tol_mm, mm_per_px_tol, n_tol,
// working_distance_mm where the image weighed it). scaleRelSigma: the declared scale's part
// of sr.pk; calibrated: the scale is the calibration's (no mm_per_px_tol to advise).
// withDistance: the posterior had the working distance been declared (nullptr: no such advice).
Advice adviseInput(const MuFunction &F, const friction::FrictionModel &model, const SpecimenSpec &spec, double uMm,
                   double r, const ScaleAndReduction &sr, double uSigmaEdgesMm, double bias, bool declared,
                   bool calibrated, double scaleRelSigma, const ScaleAndReduction *withDistance = nullptr);

// The model's range flags and the reduction's; the status from the checks' flags alone, and
// the decision of U against the tolerance.
uint32_t rangeChecks(const friction::FrictionModel &model, const MuReading &m, const AssumedReduction &r);
void decideStatus(const SpecimenSpec &spec, uint32_t flags, Reading *out);

} // namespace icacam::reading
