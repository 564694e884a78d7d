#pragma once
// What the instrument is told about one specimen (manifest row or device config), with the
// tolerance of each declared value and the lab's tolerance on μ. The defaults are the
// instrument's stated assumptions: a reading's budget carries them (docs/uncertainty.md).
#include "vision/plane_calibration.h"

namespace icacam::vision {

// Standard uncertainties (1 σ) of the declared inputs, where the user gives none.
struct DeclaredTolerances {
    double scaleRel = 0.005; // mm_per_px, relative: a scale measured on the end-face plane
    double hFinalMm = 0.05;  // a declared final height (calliper reading and springback)
    double n = 0.01;         // the strain-hardening exponent (flow-curve fit over a strain range)
    // A calibration's own scale error in the end-face plane, relative (board printing and the
    // fit; the plane height's part is added from the reduction's uncertainty).
    double calibrationScaleRel = 0.002;
};

// When no final height is declared the reading assumes the test's nominal 50 % with this
// standard uncertainty: a specimen "pressed to half height" without a measured final height
// lies anywhere in 45–55 % (uniform: 0.05/√3). The silhouette narrows it (reading_interpreter.h).
inline constexpr double kNominalReduction = 0.5;
inline constexpr double kUndeclaredReductionSigma = 0.0289;

// A reading is ok when coverage·σ_μ ≤ max(absMu, relMu·μ) (and no check flags it).
struct ReadingTolerance {
    double absMu = 0.01;
    double relMu = 0.05;
    double coverage = 2.0;
    double at(double mu) const { return absMu > relMu * mu ? absMu : relMu * mu; }
};

struct SpecimenSpec {
    double n = 0;        // strain-hardening exponent
    double kMpa = 0;     // strength coefficient, 0 if unknown
    double d0Mm = 10;    // initial diameter
    double h0Mm = 15;    // initial height
    double mmPerPx = 0;  // scale in the plane of the end face (with a calibration: 0, or a search hint)
    double hFinalMm = 0; // final height when recorded (0: not declared)
    // Camera calibration (docs/calibration.md): when given, each boundary is mapped into the
    // end-face plane at the specimen's final height (declared, else the reading's reduction),
    // and mmPerPx only sizes the search. Its heightMm is ignored: the interpreter sets it.
    const PlaneCalibration *calibration = nullptr;
    DeclaredTolerances tolerances = {};
    ReadingTolerance tolerance = {};
};

} // namespace icacam::vision
