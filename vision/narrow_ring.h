#pragma once
// A ring too narrow for the per-ray search: both edges from the mean profile across it.
//
// Where the ICA is a few pixels wide, the original face's edge and the contact edge blur
// into one feature: the derivative shows one peak (or two that overlap), and the per-ray
// search, which looks for the original face's edge a detector's width inside the contact
// edge, finds nothing. The mean profile aligned on the contact edge still holds both steps.
// It is fitted with three levels joined by two steps of one blur (the same optics blur
// both): P(x) = A + B·Φ((x − x_i)/s) + C·Φ((x − x_o)/s), linear in A, B, C for a given
// (x_i, x_o, s), which are searched on a grid and refined. The fit is taken only where the
// second step earns its place: the single-step fit (B = 0) must leave at least four times
// the residual, the inner step must be four noise levels and 5 grey levels high, the ring
// at least one blur and at most 8 px wide, no sample clipped,
// and the face's level everywhere farther inside (from 16 px to the profile's start, the
// widest ICA the search allows) the fit's innermost level (within 30 % of the inner step): on
// a wide ring whose inner edge was missed, a mark on the ICA near the contact edge would
// otherwise pass for the face's edge. Beyond the contact edge the profile ends where a barrel
// band narrower than the reach turns back to the outline.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <cstdint>

namespace icacam::vision {

struct NarrowRingFit {
    bool found = false;
    double innerPx = 0, outerPx = 0; // step positions, pixels from the profile's edge index
    double sigmaWidthPx = 0;         // the width's standard uncertainty (fit and model)
    double blurPx = 0;               // the steps' common Gaussian σ
    double innerStep = 0;            // B, the original face's step (profile units)
};

// profile: the mean profile at 1 px steps, count samples, the contact edge near edgeIndex;
// outerSign: the contact edge's step sign going outwards. The noise level is the fit's own
// residual.
// startWidthPx: the per-ray search's width where it found one (the fit starts there), else 0
// (a coarse grid finds the starts: about ten times the work).
NarrowRingFit fitNarrowRing(const int32_t *profile, int count, int edgeIndex, int outerSign, double startWidthPx = 0);

} // namespace icacam::vision
