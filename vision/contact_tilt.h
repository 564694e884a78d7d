#pragma once
// The contact edge from the surface's tilt: the ring light in segments, lit in turn.
//
// Under the whole ring a barrel whose first tenth of a millimetre leaves the platen at a few
// degrees shines like the flat ring beside it: one photograph shows no edge where the flat
// face ends, and the steepest fall it does show lies where the barrel turns further away
// (rendered 1456 × 1088 photographs: 6–7 px beyond the contact edge). Lit from one side at a
// time it does show: a surface tilted outwards on a ray towards a segment returns more of
// that segment's light and less of the opposite one's, a flat one returns both alike
// whatever its finish or brightness. Per ray at azimuth θ the radial tilt signal
//     T = Σ_k cos(θ − φ_k)·I_k / Σ_k I_k        (φ_k: segment k's azimuth in the image)
// is level across the flat face and ring (turning marks ripple it) and steps up where the
// barrel begins. Its mean over rays aligned on the contact edge the single frame found gives
// the edge: the knee where the innermost clear rise of T leaves the flat face's level.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <cstdint>

#include "vision/end_face_geometry.h"
#include "vision/luma_view.h"

namespace icacam::vision {

// Frames of the same view, each lit by one segment of the ring light. Segment k is centred
// at image azimuth azimuth0Deg + k·360/count degrees, measured from the image's +x axis
// (columns) towards its +y axis (rows, downwards). Exposure is the same for all of them.
struct LitInTurn {
    static constexpr int kMaxSegments = 8;
    LumaView segment[kMaxSegments];
    int count = 0;
    double azimuth0Deg = 0;
};

// Three segments at least tell the tilt in every direction.
inline constexpr int kMinTiltSegments = 3;

struct TiltEdge {
    bool found = false;
    double shiftPx = 0; // the contact edge from the boundary given, along the rays (outwards +)
    double sigmaPx = 0; // its standard uncertainty: the profile's noise over the step's slope
    double rise = 0;    // the step in T (0 … 2)
    double misfit = 0;  // the knee model's RMS residual over the step: what the marks left
    int rays = 0;       // rays that contributed
};

// The contact edge on the tilt profile about the boundary `outer` centred at (cx, cy):
// searched from innerPx inside it to outerPx beyond it; blurPx the optics' Gaussian σ.
// Segments must be the frame's size.
TiltEdge contactEdgeByTilt(const LitInTurn &lit, const BoundaryFit &outer, double cx, double cy, double innerPx,
                           double outerPx, double blurPx);

} // namespace icacam::vision
