#pragma once
// cos and sin of the 256 ray angles 2πj/256, computed once. Every ray count the pipeline
// uses (32, 64, 128, 256) divides 256, so ray directions and the boundary fit's harmonics are
// look-ups, not trigonometry per frame.
#include "vision/fixed_point.h"

namespace icacam::vision {

struct AngleTable {
    static constexpr int kSize = 256;
    double cos[kSize], sin[kSize];
    Q2_14 cosQ[kSize], sinQ[kSize]; // the same, rounded to Q2.14 (ray directions)
};

// Built on first use (a function-local static: thread-safe, no heap).
const AngleTable &angleTable();

} // namespace icacam::vision
