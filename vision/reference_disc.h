#pragma once
// A reference disc of known diameter lying on the fixture, for the device's quick scale
// check: its centre from the specimen locator (the disc's edge is one circle, which votes
// like a specimen's), its edge located on rays from that centre and fitted as a closed
// curve. Dark on a bright fixture or bright on a dark one. All working memory is the
// caller's (kWorkBytes) and the stack; nothing is allocated.
#include <cstddef>
#include <cstdint>

#include "vision/end_face_geometry.h"
#include "vision/error.h"
#include "vision/luma_view.h"
#include "vision/specimen_locator.h"

namespace icacam::vision {

struct DiscFit {
    ErrorCode error = ErrorCode::NotConfigured; // None, or why no disc was found
    BoundaryFit edge;                           // r(θ) in pixels about (centreX, centreY)
    double centreX = 0, centreY = 0;
};

class ReferenceDiscFinder {
public:
    static constexpr int kRays = 128;
    static constexpr int kMaxSamples = 512;
    static constexpr size_t kWorkBytes = SpecimenLocator::kWorkBytes;
    // The expected radius may be off by this fraction (a wrong scale, a wrong disc).
    static constexpr double kRadiusSpan = 0.3;

    // `work` must hold kWorkBytes and outlive the finder.
    explicit ReferenceDiscFinder(uint8_t *work) : work_(work) {}
    // Finds a disc whose radius is about radiusPx (within ±kRadiusSpan). Errors: BadFrame,
    // BadSpecimen (radius not physical for the frame), NoSpecimen (no disc of about that
    // size), OuterEdgeNotFound (its edge was found on too few rays).
    DiscFit find(const LumaView &v, double radiusPx) const;

private:
    uint8_t *work_;
};

} // namespace icacam::vision
