#pragma once
// What the instrument is told about one specimen (manifest row or device config), with the
// tolerance of each declared value and the lab's tolerance on μ. The defaults are the
// instrument's stated assumptions: a reading's budget carries them (docs/uncertainty.md).
#include <string>
#include <string_view>

namespace icacam::reading {

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
    // The camera's distance to the end face (0: not declared): the outline a close camera
    // sees of the barrel lies inside R_max (friction/outline_ratio.h).
    double workingDistanceMm = 0;
    // The camera's tone curve as a power, encoded = linear^(1/toneGamma): 1 for frames whose
    // levels are proportional to light, about 2.2 for a camera's sRGB-like JPEG or PNG. The
    // ring's edges are located in linear light (vision/tone_curve.h).
    double toneGamma = 1;
    DeclaredTolerances tolerances = {};
    ReadingTolerance tolerance = {};
};

// Builds a spec from key/value pairs: a manifest row's columns and the device's config keys
// alike (n, k_mpa, d0_mm, h0_mm, h_final_mm, mm_per_px, working_distance_mm, tone_gamma and the
// tolerances mm_per_px_tol,
// h_final_tol_mm, n_tol, tolerance_mu, tolerance_rel). lookup(key) gives the text of a key, or
// nullptr where it is absent; an empty text counts as absent. Fields absent keep spec's values.
// n is required, mm_per_px where needsScale. False with *why set on a missing, malformed or
// unphysical value.
template <class Lookup> bool specimenFromFields(Lookup &&lookup, bool needsScale, SpecimenSpec *spec, std::string *why);

// One field: its text parsed into spec (the shared part of specimenFromFields). False with
// *why set when the text is not a number or is out of the field's range; unknown keys: false,
// why empty.
bool setSpecimenField(std::string_view key, std::string_view text, SpecimenSpec *spec, std::string *why);
// What specimenFromFields checks once every field is read.
bool checkSpecimen(const SpecimenSpec &spec, bool needsScale, std::string *why);
// The keys specimenFromFields reads, in its order (nullptr-terminated).
extern const char *const kSpecimenKeys[];

template <class Lookup> bool specimenFromFields(Lookup &&lookup, bool needsScale, SpecimenSpec *spec, std::string *why)
{
    for (const char *const *key = kSpecimenKeys; *key; ++key) {
        const char *text = lookup(std::string_view(*key));
        if (!text || !*text) {
            if (std::string_view(*key) == "n" || (needsScale && std::string_view(*key) == "mm_per_px")) {
                *why = std::string("missing ") + *key;
                return false;
            }
            continue;
        }
        if (!setSpecimenField(*key, text, spec, why)) return false;
    }
    return checkSpecimen(*spec, needsScale, why);
}

} // namespace icacam::reading
