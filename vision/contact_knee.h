#pragma once
// Where the flat face's level ends at the contact edge when the barrel's shading ramps away
// from it instead of stepping. The ring is a level up to R_o; there the profile starts to
// fall (a knee, with or without a step), and falls fastest a few pixels on, where the free
// surface has turned past the light: the derivative's peak lies outside the edge. The knee is
// found by fitting a level, a step and a straight fall beyond it, blurred by the optics' own
// Gaussian (the original face's edge, a pure blurred step, measures it), to the profile across
// the edge. Pure C++20: no heap, no exceptions.
#include <cstdint>

namespace icacam::vision {

struct ContactKneeWindow {
    int insideSamples = 6;    // samples fitted inside the located edge (short of the ring's far edge)
    int outsideSamples = 3;   // samples fitted beyond it
    double blurPx = 1.0;      // the optics' Gaussian σ on the profile, pixels
    double searchInPx = 3.0;  // how far inside the located edge the knee may lie
    double searchOutPx = 1.0; // how far beyond it
    double samplePx = 1.0;    // the profile's sample spacing, pixels
    // A step `sign`'s way that the slope beyond does not undo within two blurs is a knee too:
    // a surface leaving the platen at an angle and holding it.
    bool stepAlone = false;
};

struct ContactKnee {
    double offsetPx = 0;             // the knee's position relative to sample `at` (negative: inside)
    double stepLevel = 0, slope = 0; // the fit's step and fall beyond the knee (profile units, per px)
    double residual = 0;             // the fit's RMS residual (profile units)
    bool found = false;
};

// level: the profile across the contact edge in any linear unit, samples outwards, the located
// edge at sample `at`; sign: the way the profile goes beyond the knee, −1 falling outwards, +1
// rising (the step at the knee may go either way: a lit shoulder steps up and falls); a
// level of 0 is a sample off the frame. Not found when the window leaves the profile or the
// frame or holds more than 40 samples, the best knee lies on the search's bound, or the fit's
// fall beyond the knee goes against `sign`.
ContactKnee locateContactKnee(const int32_t *level, int count, int at, int sign, const ContactKneeWindow &w);

} // namespace icacam::vision
