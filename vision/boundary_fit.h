#pragma once
// The closed curve through a boundary's edge points: a robust least-squares Fourier series
// r(θ) about the pipeline's centre, and its enclosed area (the paper's equivalent radius).
#include "vision/end_face_geometry.h"

namespace icacam::vision {

struct FitOptions {
    int maxHarmonics = 4;
    double rejectSigma = 3.0;  // residuals beyond this many robust σ are dropped
    double minRejectPx = 0.75; // never reject closer than this (sub-pixel noise)
    // > 0: before the first fit, also drop radii farther from the median than this many
    // robust σ of their spread about it (1.4826 × the median absolute deviation, minRejectPx
    // at least). A least-squares first fit through a quarter of rays that took a step well
    // beyond the boundary is pulled towards them by several pixels, and the residuals'
    // median with it: the later passes' limit then keeps them. A circle off the rays' centre,
    // or an ellipse, spreads the radii sinusoidally: its MAD is 0.7 of the swing, so this
    // drops none of its points at 3.
    double medianRejectSigma = 0;
};

// Fits the valid radii (n rays, evenly spaced from angle 0; n must divide
// 256). Returns false when fewer than 8 points survive. Per boundary, not per pixel: double is fine here.
// `curveOut`, when given, receives the fitted radius at each of the n rays.
bool fitBoundary(const double *radiusPx, const bool *valid, int n, double centreX, double centreY,
                 const FitOptions &opt, BoundaryFit *out, double *curveOut = nullptr);

// The fitted radius in n directions at once (cos θ_i, sin θ_i): the same arithmetic as
// BoundaryFit::radiusAt for each, bit for bit, with the harmonics' recurrence run across the
// directions in step so that it vectorises.
void radiiAt(const BoundaryFit &fit, const double *cosT, const double *sinT, int n, double *out);

} // namespace icacam::vision
