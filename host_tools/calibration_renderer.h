#pragma once
// Synthetic photographs through a known camera: calibration boards (chessboards) in any
// pose, and an end face (EndFaceScene, rendered flat) seen through a tilted, distorting
// lens. Ground truth for `icacam calibrate` and for the calibrated measurement. The
// specimen as a solid body (barrel and occlusion) is specimen_body_renderer.h.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "host_tools/end_face_renderer.h"
#include "vision/plane_calibration.h"

namespace icacam::host {

// A camera in OpenCV's model, and the pose of the fixture plane in front of it
// (X_camera = R(rvec) · X_fixture + tvec, mm; fixture z points away from the camera).
struct CameraModel {
    int width = 1456, height = 1088;
    double fx = 4000, fy = 4000, cx = 728, cy = 544;
    double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;
    cv::Vec3d fixtureRvec{0, 0, 0}, fixtureTvec{0, 0, 60};
};

// A camera 62 mm above the fixture, tilted 8° and 5°, with barrel distortion (about 9 px
// at the frame's corners): about 0.0136 mm/px at a 7.5 mm high end face.
CameraModel exampleTiltedCamera();

// The camera as the vision library's calibration (height 0: the fixture itself).
vision::PlaneCalibration toPlaneCalibration(const CameraModel &cam);

struct ChessboardSpec {
    int cols = 9, rows = 7; // inner corners (OpenCV's pattern size)
    double squareMm = 1.4;
};

// Inner-corner positions on the board (z = 0), row by row, first corner at the origin.
std::vector<cv::Point3f> chessboardCorners(const ChessboardSpec &b);

// A symmetric grid of dark dots on white paper (OpenCV's symmetric circle grid): dot
// centres `spacingMm` apart, the first at the origin; the paper reaches 1.5 spacings
// beyond the outer dots.
struct CircleGridSpec {
    int cols = 9, rows = 7;
    double spacingMm = 1.4;
    double dotDiameterMm = 0.7;
    // The same outline for the pose generator (calibrationPoses keeps 2 pitches around).
    ChessboardSpec extent() const { return {cols, rows, spacingMm}; }
};

// Renders views through one camera. The undistorted ray of every pixel is computed once.
class BoardPhotoRenderer {
public:
    explicit BoardPhotoRenderer(const CameraModel &cam);
    // A chessboard (with a white margin) on a grey surround, at the pose (board → camera),
    // then Gaussian blur (σ px) and sensor noise (σ grey levels).
    cv::Mat chessboard(const ChessboardSpec &b, const cv::Vec3d &rvec, const cv::Vec3d &tvec, double blurPx,
                       double noise, uint32_t seed) const;
    // The chessboard moving during a rolling-shutter exposure: row y is exposed at time
    // y / height along the straight path from pose 0 to pose 1. Its corners fit no single
    // pose: a genuinely bad calibration view (the board was still being put down).
    cv::Mat movingChessboard(const ChessboardSpec &b, const cv::Vec3d &rvec0, const cv::Vec3d &tvec0,
                             const cv::Vec3d &rvec1, const cv::Vec3d &tvec1, double blurPx, double noise,
                             uint32_t seed) const;
    // A circle grid at the pose, likewise.
    cv::Mat circleGrid(const CircleGridSpec &g, const cv::Vec3d &rvec, const cv::Vec3d &tvec, double blurPx,
                       double noise, uint32_t seed) const;
    // A reference disc (grey level discGrey) of diameterMm lying on the fixture centred at
    // (xMm, yMm), its top face heightMm above the fixture, on a fixture of grey fixtureGrey.
    cv::Mat disc(double diameterMm, double xMm, double yMm, double heightMm, double discGrey, double fixtureGrey,
                 double blurPx, double noise, uint32_t seed) const;
    // The end face of `scene` (its mm geometry; its pixel scale and position are ignored)
    // standing on the fixture at (xMm, yMm) with its end face heightMm above it. The top
    // (face, ICA and contact edge) lies in the plane at heightMm; beyond the contact edge
    // the barrel is seen at half that height, where it is widest (its silhouette).
    cv::Mat endFace(const EndFaceScene &scene, double xMm, double yMm, double heightMm, double blurPx, double noise,
                    uint32_t seed) const;
    const CameraModel &camera() const { return cam_; }

private:
    // Fixture-frame intersection of every pixel's ray with the plane z = zMm, for a pose.
    void intersect(const cv::Matx33d &R, const cv::Vec3d &t, double zMm, cv::Mat *X, cv::Mat *Y,
                   cv::Mat *footprint) const;
    CameraModel cam_;
    cv::Mat rays_; // CV_64FC2: undistorted normalized coordinates per pixel
};

// A camera looking down at the fixture from fixtureDistanceMm (along its axis), its axis
// tilted tiltDeg from the fixture's normal towards azimuthDeg (in the fixture plane), focal
// length fPx, principal point (cxPx, cyPx), radial distortion k1 (barrel when negative).
CameraModel tiltedCamera(int width, int height, double fPx, double cxPx, double cyPx, double k1, double tiltDeg,
                         double azimuthDeg, double fixtureDistanceMm);

// Where the camera's axis meets the plane heightMm above the fixture (fixture mm).
cv::Point2d axisOnPlane(const CameraModel &cam, double heightMm);

// The image of the point (xMm, yMm) of the plane heightMm above the fixture (pixels).
cv::Point2d projectFromPlane(const CameraModel &cam, double xMm, double yMm, double heightMm);

// The mean scale there (mm per pixel, the square root of the area ratio, lens included):
// the one number a lab would declare for an object lying there.
double planeScaleAtPoint(const CameraModel &cam, double xMm, double yMm, double heightMm);

// A set of board poses for calibration: tilts up to ±25° in several directions at
// distances around the fixture's (0.84–1.06 × the camera's distance to the fixture, its
// translation's z), the board kept in the frame.
std::vector<std::pair<cv::Vec3d, cv::Vec3d>> calibrationPoses(const CameraModel &cam, const ChessboardSpec &b,
                                                              int count, uint32_t seed);

} // namespace icacam::host
