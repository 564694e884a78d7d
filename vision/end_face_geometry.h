#pragma once
// What the image half of a measurement returns: the end face's boundaries and silhouette in
// pixels, and the conditions the image shows (PRODUCT.md §4: the seam between measuring the
// end face and interpreting it).
#include <cstdint>

#include "vision/error.h"
#include "vision/fixed_point.h"

namespace icacam::vision {

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
    // 1 - b/a of the curve's second harmonic and the long axis's direction, in the image.
    double ellipticity = 0;
    double axisDeg = 0;
    double centreX = 0, centreY = 0; // centre of the curve (first harmonic), pixels
    int used = 0;                    // edge points kept by the robust fit

    double radiusAt(double theta) const;
    double radiusAt(double cosTheta, double sinTheta) const; // same, trig precomputed
};

// What the image alone says about the view, beyond the geometry: conditions a reading must
// carry whatever it is interpreted with.
enum ImageFlag : uint32_t {
    kImageSpecimenClipped = 1u << 0, // the specimen runs off the frame
    kImageNarrowRingFit = 1u << 1,   // the ring was measured by the narrow-ring profile fit
    // Just outside the silhouette the fixture shows a second step of its sign, as strong
    // (the ring light's shadow round the foot): rMaxPx may be either edge, and a scale or
    // reduction inferred from it is not to be trusted.
    kImageOutlineAmbiguous = 1u << 2,
    // The mean profile does not decide which edge ends the flat face: the contact edge
    // taken opens a band that may as well lie on the barrel beyond an unseen original face
    // (profile_zones.h), or it is the outer of two drops with no level told between them
    // and the barrel (a ring of the face's grey inside a drawn barrel band looks alike), or
    // the contact edge rises onto lighter ground with no step beyond it on any ray (it may be
    // the outline), or the face read holds an edge of its own (it may hold the ring). R_i and
    // R_o may both be one edge out.
    kImageContactEdgeUndecided = 1u << 3,
    // The barrel band is wide on one side and hidden behind the end face on the other: the
    // camera sees the specimen obliquely (tilted, or close and off-axis), and no circle is the
    // barrel's outline (rMaxPx is 0). The view, not the specimen, is why there is no silhouette.
    kImageBarrelOblique = 1u << 4,
    // With kImageOutlineAmbiguous: the rays aligned on the fitted outline show no second
    // step. The mean profile about the contact edge's centre smeared the one outline into
    // two, its centre drawn aside by the view (a close camera draws it towards the optical
    // axis; a tilt anywhere): where the view explains the shift, the outline is the barrel's.
    kImageOutlineSmeared = 1u << 5,
    // The segment frames' tilt profile (contact_tilt.h) placed the contact edge: it moved to
    // the tilt's knee (tiltKneePx away), the single frame having read a fall on the barrel.
    kImageContactEdgeByTilt = 1u << 6,
    // The tilt's knee lies within its own reach of the single frame's contact edge: the flat
    // face ends there, which the single frame's ramp or band left open.
    kImageTiltConfirms = 1u << 7,
    // The tilt's knee lies beyond its reach of the contact edge but within what its own error
    // explains: the single frame's contact edge stands, and neither is sure (reading:
    // tilt_disagrees).
    kImageTiltDisagrees = 1u << 8,
    // The segment frames light the specimen from elsewhere than the azimuths given for them
    // (segment_bearing.h: a ring mounted turned, its lines listed the other way round): no
    // tilt is read from them; segment0SeenDeg and segmentWay say where the light came from.
    kImageSegmentsMisplaced = 1u << 9,
    // Which of kImageContactEdgeUndecided's causes the image showed, beside it (the band or
    // the two drops of the profile need no bit of their own): the contact edge rises onto
    // lighter ground with no step beyond it on any ray (the ring read may be the barrel's dark
    // band), or the face read holds an edge of its own (the ring may begin there, the ring
    // read a band on the barrel beyond it).
    kImageUndecidedNoStepBeyond = 1u << 10,
    kImageUndecidedFaceHoldsEdge = 1u << 11,
};

// Where the pipeline looks: the specimen's initial diameter and the scale at the end face
// (a hint: it sizes the search, the reading's scale comes from the instrument), and how the
// frame encodes light: the camera's tone curve as a power, encoded = linear^(1/toneGamma)
// (1: levels proportional to light, as the development set's drawn frames; about 2.2 for a
// camera's sRGB-like output). The ring's edges are located in linear light
// (vision/tone_curve.h).
struct LitInTurn;

struct FaceSearch {
    double d0Mm = 10;
    double mmPerPx = 0;
    double toneGamma = 1;
    // Frames of the same view lit by the ring light's segments in turn (contact_tilt.h), or
    // nullptr: the contact edge is then taken where the surface's tilt says the flat face ends.
    const LitInTurn *litInTurn = nullptr;
};

// The widest ring the search looks for, as a fraction of the specimen's initial radius (u up
// to 1.6 mm on a 10 mm specimen, beyond any friction the models cover).
inline constexpr double kWidestRingOfR0 = 0.32;

// The contact edge's ramp (√(w_o² − w_i²), pixels) beyond which the barrel's shading ramps away
// from the flat face rather than stepping: rendered barrels ramping away measure 1.5–3.5 px;
// drawn steps under 1.0, the development set's and the reference photographs' contact edges
// under 1.6 (data/photobench/README.md). Beyond it the knee is searched twice as deep and an
// arc of an oblique view is followed to where its level ends; the pipeline takes R_o where the
// ring's level ends from a ramp of 0.5 px on (kKneeRampPx, vision/ring_search_contact_edge.cpp).
// The reading's finding (contact_edge_ramp, the ramp in u's error) begins a little above, by
// the width's own repeatability (reading/interpretation_steps.cpp).
inline constexpr double kContactRampPx = 1.6;

// The end face as the image shows it, in pixels: the specimen's centre, the two boundaries'
// fits, the barrel's silhouette, the contact edge's blur and the clipped share. No scale, no
// specimen, no model: the reading interprets it (reading/interpretation.h).
struct EndFaceGeometry {
    ErrorCode error = ErrorCode::NotConfigured;
    uint32_t imageFlags = 0; // ImageFlag bits

    double centreX = 0, centreY = 0; // pipeline centre (pixels)
    BoundaryFit inner, outer;
    double rMaxPx = 0;      // barrel silhouette radius (equivalent circle); 0 if not found
    double edgeWidthPx = 0; // blur of the contact edge (Gaussian σ estimate)
    // The same measure on the original face's edge, a step in the surface's finish that the
    // optics alone blur, and how much wider the contact edge is than it (√(w_o² − w_i²)), both
    // within half the ring: the barrel's shading ramping away from the flat face beyond the
    // contact edge (reading: contact_edge_ramp). 0 where the rays did not locate the original
    // face's edge (a ring read on the mean profile alone, or narrower than two blurs).
    double innerEdgeWidthPx = 0;
    double contactRampPx = 0; // beyond kContactRampPx: the contact edge on the barrel's ramp
    // With segment frames: the tilt's knee from the single frame's contact edge (outwards +),
    // and the contact edge's standard uncertainty the tilt leaves. Segment frames that show
    // no tilt step (or do not fit the frame) leave the single frame's reading as it is.
    double tiltKneePx = 0, tiltSigmaPx = 0;
    // Where the segment frames' light came from (segment_bearing.h): segment 0's azimuth in
    // degrees and the way round (+1 as the azimuth runs, −1 against it); way 0: not measured
    // (no segment frames, or their light too even to tell).
    double segment0SeenDeg = 0;
    int segmentWay = 0;
    double saturatedFraction = 0;
    // The silhouette's per-ray fit: coverage and the points' robust RMS about it (0 when only
    // the mean profile named it).
    double silhouetteCoverage = 0;
    double silhouetteScatterPx = 0;
    // That fit's centre (pixels; 0 with no per-ray fit). A close camera sees the barrel's side
    // below the end face from farther away: an end face off the optical axis has its outline's
    // centre drawn towards the axis, by as much as the view's perspective shrinks the outline.
    double silhouetteCentreX = 0, silhouetteCentreY = 0;
    // The frame measured (pixels): where its optical axis lies when no calibration says.
    int frameWidth = 0, frameHeight = 0;

    // Edge points of each boundary (one per ray, valid or not) for overlays and tests; they
    // stay valid until the analyzer's next measure().
    const EdgeSample *innerPoints = nullptr;
    const EdgeSample *outerPoints = nullptr;
    int rayCount = 0;

    bool found() const { return error == ErrorCode::None; }
};

} // namespace icacam::vision
