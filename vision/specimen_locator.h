#pragma once
// Coarse centre of the specimen: a gradient Hough transform on a decimated copy of the
// frame. Every boundary of the end face (face, ICA, barrel, silhouette) is a circle about
// nearly the same centre, so they vote together; a distractor circle in the fixture votes
// alone. Reads 4 pixels per decimated cell, never the whole frame.
#include <cstdint>

#include "vision/luma_view.h"

namespace icacam::vision {

struct CentreEstimate {
    double x = 0, y = 0; // full-frame pixels
    int votes = 0;       // accumulator peak (3×3 sum)
    int background = 0;  // mean accumulator level × 100 (noise floor of the votes)
    bool found = false;
};

class SpecimenLocator {
public:
    static constexpr int kMaxCells = 96; // decimated frame is at most 96 × 96
    // Working memory a locator needs (bytes), for the arena.
    static constexpr size_t kWorkBytes = size_t(kMaxCells) * kMaxCells * 5; // luma, |g|, votes

    // `work` must hold kWorkBytes and outlive the locator.
    explicit SpecimenLocator(uint8_t *work) : work_(work) {}

    // Looks for circles of radius rMinPx … rMaxPx (full-frame pixels).
    CentreEstimate locate(const LumaView &v, double rMinPx, double rMaxPx);

private:
    uint8_t *work_;
};

} // namespace icacam::vision
