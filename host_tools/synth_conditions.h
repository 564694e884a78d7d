#pragma once
// Synthetic image sets under conditions a manifest does not declare (docs/uncertainty.md,
// "Coverage"): the end face photographed after a reduction other than 50 %, at a scale
// measured on the fixture instead of the end face, through a tilted distorting lens with or
// without a calibration, or by a low-resolution camera. The manifest says what a lab would
// say; truth.csv says what was really there. `icacam synth --condition` writes them and
// `icacam score` judges a measurement of them.
#include <cstdint>
#include <string>
#include <vector>

namespace icacam::host {

enum class SynthCondition {
    Declared,       // 50 %, straight down, exact scale: the development set's kind
    Reduction,      // 45–55 % reduction, no h_final_mm in the manifest
    FixtureScale,   // mm_per_px measured on the fixture, the end face 7.5 mm nearer (70–150 mm away)
    Tilt,           // tilted 6–15°, barrel distortion, f ≈ 1.1 × width, not calibrated
    CalibratedTilt, // a 12° tilted distorting camera with a calibration from `icacam calibrate`
    LowRes,         // 640 × 480 and 1280 × 720 cameras at 19–42 px/mm
};

const char *conditionName(SynthCondition c);
// A comma-separated list of condition names, or "all". False on an unknown name.
bool parseConditions(const std::string &list, std::vector<SynthCondition> *out);
// The known names, comma-separated (for messages).
std::string conditionNames();

struct ConditionSetOptions {
    std::vector<SynthCondition> conditions;
    int countPerCondition = 24;
    uint32_t seed = 1;
    bool hard = false;  // nuisances at their limits (as `icacam synth --hard`)
    bool quiet = false; // no progress on stderr
};

// Writes DIR/images/*, DIR/manifest.csv (what the lab says), DIR/truth.csv (per id: the
// condition and its true parameters, μ of the specimen, the true radii) and, when a
// condition needs one, DIR/calibration/ (the board photos) and DIR/camera.cal (made by
// `icacam calibrate`); for the tilted conditions DIR/truth/<id>.cal holds the true camera
// (truth.csv's camera_truth), to measure with the condition declared. Records are named
// <condition>-NNNN. Returns the manifest's path.
std::string writeConditionSet(const std::string &dir, const ConditionSetOptions &opt);

} // namespace icacam::host
