#pragma once
// What one measurement of an end face returns: boundaries, radii, u, μ ± σ, diagnostics,
// and a status with named flags (PRODUCT.md §6).
#include <cstdint>

#include "vision/error.h"
#include "vision/fixed_point.h"

namespace icacam::vision {

enum class Status : uint8_t { Ok, Warn, Error };
const char *statusName(Status s);

// Conditions a value was produced under that lie outside the model or the checks.
enum MeasureFlag : uint32_t {
    kFlagNOutOfRange = 1u << 0,
    kFlagKOutOfRange = 1u << 1,
    kFlagMuBelowRange = 1u << 2,
    kFlagMuAboveRange = 1u << 3,
    kFlagUOutsideModel = 1u << 4,
    kFlagLowContrast = 1u << 5,        // an edge has little contrast: scatter may hide a bias
    kFlagLowCoverage = 1u << 6,        // an edge was found on too few rays
    kFlagHighScatter = 1u << 7,        // boundary points scatter more than a clean edge does
    kFlagBlurred = 1u << 8,            // edges wider than the ring resolves reliably
    kFlagSaturated = 1u << 9,          // part of the ring is clipped at full scale
    kFlagSpecimenClipped = 1u << 10,   // the specimen runs off the frame
    kFlagElliptical = 1u << 11,        // both boundaries share an ellipticity: tilt or lens
    kFlagCentreOffset = 1u << 12,      // the boundaries are not concentric
    kFlagScaleSuspect = 1u << 13,      // no final height given: R_max contradicts the scale and 50 % reduction
    kFlagNarrowRing = 1u << 14,        // the ICA is only a few pixels wide
    kFlagNoSilhouette = 1u << 15,      // the barrel silhouette was not found: scale unchecked
    kFlagReductionOutside = 1u << 16,  // recorded final height outside what the model covers
    kFlagRadiiInconsistent = 1u << 17, // R_max contradicts the declared scale and final height
    kFlagAspectOutside = 1u << 18,     // the specimen's H0/D0 lies outside what the model covers
    // The budget misses the tolerance; the flag names its leading component (what to declare
    // or improve to get an ok reading).
    kFlagEdgesUncertain = 1u << 19,       // boundary scatter or the edge model
    kFlagScaleUncertain = 1u << 20,       // mm_per_px or the calibration's plane
    kFlagReductionUncertain = 1u << 21,   // the final height (declare h_final_mm)
    kFlagNUncertain = 1u << 22,           // the declared n's tolerance
    kFlagModelUncertain = 1u << 23,       // the friction model's own error
    kFlagSilhouetteUnreliable = 1u << 24, // a silhouette was found but does not fit the FE shape: not used
};
constexpr int kFlagCount = 25;
// The flags that say the budget misses the tolerance (the others are checks).
constexpr uint32_t kBudgetFlags =
    kFlagEdgesUncertain | kFlagScaleUncertain | kFlagReductionUncertain | kFlagNUncertain | kFlagModelUncertain;
const char *flagName(int bit);

// One located edge point on a ray, in pixel coordinates (Q16.16).
struct EdgeSample {
    Q16_16 x, y;
    Q16_16 radius;    // from the pipeline's centre
    int32_t strength; // |derivative| in 1/256 grey levels per px (scaled)
    bool valid;
};

// A fitted closed boundary: r(θ) about the centre, a truncated Fourier series.
struct BoundaryFit {
    static constexpr int kMaxHarmonics = 8;
    int harmonics = 0;
    double a0 = 0;
    double a[kMaxHarmonics + 1] = {};
    double b[kMaxHarmonics + 1] = {};
    double rEqPx = 0;      // sqrt(area / π) of the closed curve
    double rEqSigmaPx = 0; // standard error of rEq from the residual scatter
    double scatterPx = 0;  // robust RMS of the edge points about the curve
    double coverage = 0;   // fraction of rays with an accepted edge point
    double contrast = 0;   // median step height across the edge, grey levels (signed)
    // 1 - b/a of the curve's second harmonic and the long axis's direction, in the image;
    // with a calibration the analyzer replaces both by the end-face plane's (PlaneOutline).
    double ellipticity = 0;
    double axisDeg = 0;
    double centreX = 0, centreY = 0; // centre of the curve (first harmonic), pixels
    int used = 0;                    // edge points kept by the robust fit

    double radiusAt(double theta) const;
    double radiusAt(double cosTheta, double sinTheta) const; // same, trig precomputed
};

// Standard uncertainties of μ, one per source (GUM, JCGM 100), each from the model's own
// sensitivities (finite differences of the friction model). muSigma combines them with the
// scale–reduction correlation the silhouette leaves (see reading_interpreter.h).
struct UncertaintyBudget {
    double edges = 0;     // boundary scatter and the edge model (u's uncertainty)
    double scale = 0;     // mm_per_px's tolerance, or the calibration and the plane's height
    double reduction = 0; // the final height (declared or inferred) and the carry to 50 %
    double n = 0;         // the declared n's tolerance
    double model = 0;     // the 50 % model's own fit error
};

struct Measurement {
    Status status = Status::Error;
    ErrorCode error = ErrorCode::NotConfigured;
    uint32_t flags = 0;

    double centreX = 0, centreY = 0; // pipeline centre (pixels)
    BoundaryFit inner, outer;
    double rMaxPx = 0;      // barrel silhouette radius (equivalent circle); 0 if not found
    double edgeWidthPx = 0; // blur of the contact edge (Gaussian σ estimate)
    double saturatedFraction = 0;

    double rInnerMm = 0, rOuterMm = 0, rMaxMm = 0;
    double uPx = 0, uMm = 0, uSigmaMm = 0;
    double mu = 0, muSigma = 0;
    double centreOffsetPx = 0; // between the boundaries' centres (in the plane, with a calibration)
    // The silhouette against the FE (radii_consistency.h): (R_max − FE R_max)/σ at the
    // declared final height (or 50 % when none), and the reduction R_max implies (-1: none).
    double rMaxZ = 0;
    double reductionEst = -1;
    // The silhouette's per-ray fit: coverage and the points' robust RMS about it (0 when only
    // the mean profile named it).
    double silhouetteCoverage = 0;
    double silhouetteScatterPx = 0;

    // The interpretation (reading_interpreter.h): what the reading used and its budget.
    UncertaintyBudget budget;
    double reduction = 0.5;    // height reduction u was read at (declared, inferred or nominal)
    double reductionSigma = 0; // its standard uncertainty
    double scaleFactor = 1;    // correction the silhouette applied to the declared scale
    double toleranceMu = 0;    // the lab's tolerance for this reading (status ok: 2σ within it)

    // Edge points of each boundary (one per ray, valid or not) for overlays and tests.
    const EdgeSample *innerPoints = nullptr;
    const EdgeSample *outerPoints = nullptr;
    int rayCount = 0;

    bool hasValue() const { return status != Status::Error; }
};

} // namespace icacam::vision
