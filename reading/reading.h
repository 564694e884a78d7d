#pragma once
// A reading: the end face's geometry interpreted with what the instrument was told (the
// specimen, the scale or calibration, the friction model): radii in mm, u, μ ± σ with its
// budget, a status from the checks alone and their named flags, the decision against the
// lab's tolerance and the advice (PRODUCT.md §2, §4 and §6).
#include <cstdint>

#include "vision/end_face_geometry.h"
#include "vision/error.h"

namespace icacam::reading {

using vision::ErrorCode;

enum class Status : uint8_t { Ok, Warn, Error };
const char *statusName(Status s);

// Conditions a value was produced under that lie outside the model or the checks.
enum ReadingFlag : uint32_t {
    kFlagNOutOfRange = 1u << 0,
    kFlagKOutOfRange = 1u << 1,
    kFlagMuBelowRange = 1u << 2,
    kFlagMuAboveRange = 1u << 3,
    kFlagUOutsideModel = 1u << 4,
    kFlagLowContrast = 1u << 5,           // an edge has little contrast: scatter may hide a bias
    kFlagLowCoverage = 1u << 6,           // an edge was found on too few rays
    kFlagHighScatter = 1u << 7,           // boundary points scatter more than a clean edge does
    kFlagBlurred = 1u << 8,               // edges wider than the ring resolves reliably
    kFlagSaturated = 1u << 9,             // part of the ring is clipped at full scale
    kFlagSpecimenClipped = 1u << 10,      // the specimen runs off the frame
    kFlagElliptical = 1u << 11,           // the boundaries share an ellipse beyond the tilt the budget covers
    kFlagCentreOffset = 1u << 12,         // the boundaries are not concentric
    kFlagScaleSuspect = 1u << 13,         // no final height given: a scale off explains R_max best, and moves μ
    kFlagNarrowRing = 1u << 14,           // the ICA is only a few pixels wide
    kFlagNoSilhouette = 1u << 15,         // the barrel silhouette was not found: scale unchecked
    kFlagReductionOutside = 1u << 16,     // recorded final height outside what the model covers
    kFlagRadiiInconsistent = 1u << 17,    // R_max contradicts the declared scale and final height
    kFlagAspectOutside = 1u << 18,        // the specimen's H0/D0 lies outside what the model covers
    kFlagSilhouetteUnreliable = 1u << 19, // a silhouette was found but does not fit the FE shape: not used
    // No final height given, and the silhouette says the specimen was pressed to another
    // height than the test's nominal half by enough to move μ beyond the tolerance.
    kFlagReductionNotNominal = 1u << 20,
    // The profile across the ring does not tell which edge ends the flat face: the contact
    // edge taken opens a band that may as well be a highlight on the barrel (vision's
    // kImageContactEdgeUndecided); R_i and R_o may both be one edge out.
    kFlagContactEdgeUndecided = 1u << 21,
    // The contact edge's step is wider than the original face's by a ramp: the barrel's
    // shading falls away beyond the flat face, and R_o is read up to that ramp outside it.
    kFlagContactEdgeRamp = 1u << 22,
    // No final height or working distance given, and the silhouette reads a height from a close
    // camera other than from a far one, by enough to move μ beyond the tolerance.
    kFlagWorkingDistanceDecides = 1u << 23,
    // Segment frames were given and the surface's tilt places the flat face's end a few
    // pixels from the contact edge the frame shows, farther than the tilt confirms it and
    // nearer than it can overrule it: R_o may lie anywhere between the two.
    kFlagTiltDisagrees = 1u << 24,
};
constexpr int kFlagCount = 25;
const char *flagName(int bit);

// The expanded uncertainty U = k·σ_μ against the lab's tolerance on μ (a decision rule in the
// sense of ISO/IEC 17025 §7.8.6): a decision about the reading, not a check of it.
enum class Decision : uint8_t { Within, Beyond };
const char *decisionName(Decision d);

// The one declared input that would shrink U the most, and U before and after. None: no
// declared input shrinks U by a tenth; U is then mostly the model's own or the edges'.
enum class AdviceInput : uint8_t { None, HFinal, HFinalTol, ScaleTol, NTol, WorkingDistance };
struct Advice {
    AdviceInput input = AdviceInput::None;
    double value = 0; // the input's value to declare (a tolerance), 0 for h_final_mm itself
    double uNow = 0, uThen = 0;
    bool modelLeads = false; // for None: the model's own error leads the budget (else the edges)
    // No final height, and nothing in the image checks it (no silhouette, or a calibrated
    // view): U covers the undeclared reduction's whole range, 45–55 %.
    bool reductionUnchecked = false;
    // The final height was declared: a finding about the silhouette then concerns the declared
    // scale alone, and its words do not ask for the height.
    bool heightDeclared = false;
    // An uncalibrated oblique view without a silhouette: the declared scale is unchecked too
    // (a scale measured on the fixture would pass; a calibration checks it).
    bool scaleUnchecked = false;
    // The segment frames lit the specimen from elsewhere than they were said to (the tilt not
    // read): where segment 0 was seen, and the way round (−1: the segments run against the
    // azimuth); way 0: nothing to say.
    double segment0SeenDeg = 0;
    int segmentWay = 0;
};
// The manifest column (and the device config key's last part) the advice names.
const char *adviceInputName(AdviceInput a);

// Standard uncertainties of μ, one per source (GUM, JCGM 100), each from the model's own
// sensitivities (finite differences of the friction model). muSigma combines them with the
// scale–reduction correlation the silhouette leaves (see interpretation.h).
struct UncertaintyBudget {
    double edges = 0;     // boundary scatter and the edge model (u's uncertainty)
    double scale = 0;     // mm_per_px's tolerance, or the calibration and the plane's height
    double reduction = 0; // the final height (declared or inferred) and the carry to 50 %
    double n = 0;         // the declared n's tolerance
    double model = 0;     // the 50 % model's own fit error
};

// A boundary's shape as the checks judge it: in the image, or with a calibration in the
// end-face plane (the camera's view taken out).
struct BoundaryShape {
    double ellipticity = 0; // 1 - b/a
    double axisDeg = 0;     // the long axis's direction
};

// The end face in millimetres at the declared scale (or through the calibration), before
// the silhouette's correction of the scale: what the instrument was told, applied.
struct FaceInMm {
    double rInnerMm = 0, rOuterMm = 0;
    double rMaxMm = 0; // the silhouette (0: none)
    double uMm = 0;
};

// μ from the face as declared: the model at the declared u and final height, before the
// silhouette's correction (the loop's residual is taken against this).
struct DeclaredEstimate {
    double mu = 0;
    double dMuDu = 0; // per mm
};

struct Reading {
    Status status = Status::Error;
    ErrorCode error = ErrorCode::NotConfigured;
    uint32_t flags = 0;

    bool imaged = true;               // read from an image (false: from radii)
    vision::EndFaceGeometry geometry; // as the image showed it, in pixels (none for radii)
    FaceInMm face;                    // at the declared scale
    double scaleFactor = 1;           // the silhouette's correction of the declared scale
    BoundaryShape innerShape, outerShape;

    double uPx = 0;
    double uMm = 0;      // the ring the model read: face.uMm corrected by the scale factor
    double uSigmaMm = 0; // u's scatter (the fits and the location floor), at the declared scale
    double mu = 0, muSigma = 0;
    UncertaintyBudget budget;
    double reduction = 0.5;    // height reduction u was read at (declared, inferred or nominal)
    double reductionSigma = 0; // its standard uncertainty
    double toleranceMu = 0;    // the lab's tolerance for this reading
    double coverage = 2;       // k of the expanded uncertainty U = k·σ_μ
    Decision decision = Decision::Within;
    Advice advice;
    // μ at the test's nominal conditions (the declared scale, 50 %): what the silhouette's
    // explanations are held against where no final height is declared.
    double nominalMu = 0;
    DeclaredEstimate declared;

    double centreOffsetPx = 0; // between the boundaries' centres (in the plane, with a calibration)
    // The silhouette against the FE (friction/radii_consistency.h): (R_max − FE R_max)/σ at
    // the declared final height (or 50 % when none), and the reduction R_max implies (-1: none).
    double rMaxZ = 0;
    double reductionEst = -1;

    // The radii as read (the silhouette's scale correction applied).
    double rInnerMm() const { return face.rInnerMm * scaleFactor; }
    double rOuterMm() const { return face.rOuterMm * scaleFactor; }
    double rMaxMm() const { return face.rMaxMm * scaleFactor; }
    bool hasValue() const { return status != Status::Error; }
    double expanded() const { return coverage * muSigma; }
};

} // namespace icacam::reading
