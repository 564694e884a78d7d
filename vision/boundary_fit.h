#pragma once
// The closed curve through a boundary's edge points: a robust least-squares Fourier series
// r(θ) about the pipeline's centre, and its enclosed area (the paper's equivalent radius).
#include "vision/end_face_geometry.h"

namespace icacam::vision {

struct FitOptions {
    int maxHarmonics = 4;
    double rejectSigma = 3.0;  // residuals beyond this many robust σ are dropped
    double minRejectPx = 0.75; // never reject closer than this (sub-pixel noise)
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
