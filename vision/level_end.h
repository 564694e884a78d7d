#pragma once
// Where the flat face's level ends: the contact edge on a mean profile across it.
//
// The end face is flat, and the camera sees the immigrated ring as one level up to the
// contact edge. Beyond it the barrel falls away from the camera, and its brightness under a
// ring light changes there: a jump where the surface's normal turns, then a ramp into the
// dark or a lit shoulder as it turns further. Blurred by the optics, such a profile is
// steepest out on the ramp, not on the edge: the derivative's peak lies beyond it, by up to
// a few pixels. Where the barrel is a level too (a drawn band), the step's middle is the
// edge and the derivative's peak is on it.
//
// The model: P(x) = L + J·Φ(z) + a·σ·(zΦ(z) + φ(z)) + b·σ²·((z² + 1)Φ(z) + zφ(z)), z = (x − e)/σ:
// the level L up to e, then any quadratic beyond it (jump J, slope a, curvature b), all
// blurred by a Gaussian of σ, the blur measured on the original face's edge (a step between
// two levels, so its blur is the optics' own). Linear in L, J, a, b for a given e, which is
// searched on a grid and refined. It is taken only where the quadratic earns its place over
// a plain blurred step (J alone), by far more than the noise, and where the barrel beyond the
// edge is no level (it changes by at least half the jump): on a step the caller keeps the
// derivative's peak.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <cstdint>

namespace icacam::vision {

struct LevelEnd {
    bool found = false;
    double edge = 0;          // e, in samples
    bool stepSuffices = true; // a blurred step between two levels explains the profile
    double jump = 0;          // J: the level's step onto the barrel (grey levels)
    double barrelChange = 0;  // the barrel's change from the edge to the window's end (grey levels)
};

// profile: a mean profile in Q8 grey at 1 px steps; the fit reads samples lo … hi and
// searches e over [eLo, eHi]; sigma: the blur (pixels).
LevelEnd fitLevelEnd(const int32_t *profile, int count, int lo, int hi, double eLo, double eHi, double sigma);

// The blur (Gaussian σ, pixels) of the step between two levels within lo … hi, its middle
// in [eLo, eHi]; −1 where no step fits.
double fitStepBlur(const int32_t *profile, int count, int lo, int hi, double eLo, double eHi);

} // namespace icacam::vision
