#pragma once
// Camera calibration applied per point: a pixel on a boundary → millimetres in the plane of
// the end face, which lies parallel to the fixture at the specimen's final height. Lens
// distortion is removed by a fixed-point iteration and the ray is intersected with that
// plane; nothing remaps the frame. The model is OpenCV's pinhole with Brown–Conrady
// distortion (k1, k2, p1, p2, k3), so a calibration from `icacam calibrate` applies as is.
#include <cstdint>

#include "vision/end_face_geometry.h"
#include "vision/fixed_point.h"

namespace icacam::vision {

// Wide fixed point for the projective stage: ±2^31 with 2^-32 resolution, products and
// quotients taken in 128 bits. It holds normalized image coordinates (|x| < 1 in any lens
// we accept), distortion coefficients, rotation entries and millimetres alike.
using Q32_32 = Q<32, 32>;

struct PlaneCalibration {
    // Intrinsics (pixels) and distortion, OpenCV's convention.
    double fx = 0, fy = 0, cx = 0, cy = 0;
    double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;
    // Pose of the fixture plane: X_camera = R · X_fixture + t (R row-major, t in mm), with
    // the fixture's x-y plane on the fixture surface (the board lying flat on it).
    double r[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double t[3] = {0, 0, 0};
    // Height of the measured plane above the fixture, towards the camera (mm): the end
    // face of a specimen standing on the fixture is at its final height.
    double heightMm = 0;

    // Plausible intrinsics and a pose with the camera in front of the plane.
    bool valid() const;
};

struct PlanePoint {
    Q32_32 x, y; // mm in the plane, fixture axes
    bool valid = false;
};

// The calibration converted once to fixed point; map() then costs a few dozen integer
// operations per point plus the undistortion iteration (typically 4–8 rounds).
class PlaneMapper {
public:
    static constexpr int kMaxIterations = 40;

    explicit PlaneMapper(const PlaneCalibration &cal);
    bool valid() const { return valid_; }
    // Pixel (x right, y down, pixel centres at integers) → point in the plane. Invalid when
    // the point lies outside the lens's accepted field (|normalized| ≥ 1), the distortion
    // cannot be inverted there, or the ray misses the plane.
    PlanePoint map(Q16_16 px, Q16_16 py) const;

private:
    bool valid_ = false;
    int64_t fx_ = 0, fy_ = 0, cx_ = 0, cy_ = 0; // Q32_32 raw, pixels
    int64_t k1_ = 0, k2_ = 0, k3_ = 0, p1_ = 0, p2_ = 0;
    int64_t rt_[9] = {}; // Rᵀ, row-major
    int64_t b_[3] = {};  // Rᵀ t (mm)
    int64_t planeZ_ = 0; // the plane's z in fixture coordinates (mm, sign towards camera)
};

// One point, for callers that map only a few (builds the mapper each call).
PlanePoint pixelToPlane(const PlaneCalibration &cal, double px, double py);

// Local scale (mm per pixel, the square root of the map's area ratio) at a pixel; 0 if the
// point cannot be mapped. A starting scale for the search when only a calibration is given.
double planeScaleAt(const PlaneCalibration &cal, double px, double py);

// Equivalent radius sqrt(A/π) in mm of a fitted boundary, r(θ) about (centreX, centreY) in
// pixels (PRODUCT.md §1): the curve is sampled at kEquivalentRadiusSamples angles, each
// point mapped to the plane, and the enclosed area taken by the shoelace formula. Returns
// 0 when any point cannot be mapped.
constexpr int kEquivalentRadiusSamples = 512;
double equivalentRadiusMm(const BoundaryFit &fit, double centreX, double centreY, const PlaneCalibration &cal);

// A fitted boundary as it lies in the end-face plane: what the pixel fit's ellipticity,
// axis and centre say, with tilt, perspective and distortion taken out. The shape comes
// from the mapped polygon's second area moments (an ellipse of axes a ≥ b has moments in
// the ratio a²:b²), so a circle on the end face reads 0 however the camera looks at it.
struct PlaneOutline {
    bool valid = false;
    double rEqMm = 0;                    // sqrt(A/π), as equivalentRadiusMm
    double centroidX = 0, centroidY = 0; // mm, fixture axes
    double ellipticity = 0;              // 1 − b/a of the moment-equivalent ellipse
    double axisDeg = 0;                  // its long axis, degrees from the fixture's x axis
};
PlaneOutline planeOutline(const BoundaryFit &fit, double centreX, double centreY, const PlaneCalibration &cal);

} // namespace icacam::vision
