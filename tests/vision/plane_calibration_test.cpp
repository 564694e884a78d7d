// The fixed-point pixel → plane map against a double reference built on OpenCV
// (projectPoints forward, undistortPoints backward), and the equivalent radius against a
// densely sampled double polygon.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "host_tools/calibration_renderer.h"
#include "vision/boundary_fit.h"
#include "vision/plane_calibration.h"

using namespace icacam;
using vision::PlaneCalibration;

namespace {

// A close, tilted, distorting camera: 8° and 5° tilt, barrel distortion, ~0.014 mm/px.
PlaneCalibration tiltedCamera(double heightMm)
{
    host::CameraModel cam = host::exampleTiltedCamera();
    PlaneCalibration c = host::toPlaneCalibration(cam);
    c.heightMm = heightMm;
    return c;
}

// Double reference: plane point (fixture axes, z = h towards the camera) → pixel.
cv::Point2d project(const PlaneCalibration &c, double X, double Y)
{
    const cv::Matx33d R(c.r);
    const cv::Vec3d t(c.t[0], c.t[1], c.t[2]);
    // The side the camera is on: its centre is −Rᵀt.
    const double up = -(R.t() * t)[2] >= 0 ? 1.0 : -1.0;
    cv::Mat rvec;
    cv::Rodrigues(R, rvec);
    const cv::Matx33d K(c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
    const std::vector<double> D{c.k1, c.k2, c.p1, c.p2, c.k3};
    std::vector<cv::Point3d> obj{{X, Y, up * c.heightMm}};
    std::vector<cv::Point2d> img;
    cv::projectPoints(obj, rvec, t, K, D, img);
    return img[0];
}

// Double reference backward: OpenCV's undistortPoints (iterated to convergence), then the
// ray-plane intersection in double.
cv::Point2d backProject(const PlaneCalibration &c, double px, double py)
{
    const cv::Matx33d K(c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
    const std::vector<double> D{c.k1, c.k2, c.p1, c.p2, c.k3};
    std::vector<cv::Point2d> in{{px, py}}, out;
    cv::undistortPoints(in, out, K, D, cv::noArray(), cv::noArray(),
                        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-15));
    const cv::Matx33d R(c.r);
    const cv::Vec3d t(c.t[0], c.t[1], c.t[2]);
    const cv::Vec3d a = R.t() * cv::Vec3d(out[0].x, out[0].y, 1), b = R.t() * t;
    const double up = -b[2] >= 0 ? 1.0 : -1.0;
    const double lambda = (up * c.heightMm + b[2]) / a[2];
    return {lambda * a[0] - b[0], lambda * a[1] - b[1]};
}

} // namespace

TEST(PlaneCalibration, MapsPixelsBackToThePlanePointsThatProjectedThem)
{
    const PlaneCalibration c = tiltedCamera(7.5);
    const vision::PlaneMapper m(c);
    ASSERT_TRUE(m.valid());
    // Bound: 5e-7 mm (1/27000 px at 0.014 mm/px): the Q16.16 input steps alone are 2e-7 mm
    // on the plane; the fixed-point chain adds less than that (measured 1.4e-7 mm).
    double worst = 0, worstRef = 0;
    for (double X = -10; X <= 10; X += 1.25)
        for (double Y = -8; Y <= 8; Y += 1.0) {
            const cv::Point2d p = project(c, X, Y);
            const vision::PlanePoint q = m.map(vision::Q16_16::fromDouble(p.x), vision::Q16_16::fromDouble(p.y));
            ASSERT_TRUE(q.valid) << X << "," << Y;
            worst = std::max(worst, std::hypot(q.x.toDouble() - X, q.y.toDouble() - Y));
            const cv::Point2d r = backProject(c, p.x, p.y);
            worstRef = std::max(worstRef, std::hypot(r.x - X, r.y - Y));
        }
    std::printf("plane map: worst |error| %.2e mm (OpenCV double reference: %.2e mm)\n", worst, worstRef);
    EXPECT_LT(worst, 5e-7);
}

TEST(PlaneCalibration, AgreesWithOpenCvUndistortAcrossTheFrame)
{
    const PlaneCalibration c = tiltedCamera(6.0);
    const vision::PlaneMapper m(c);
    double worst = 0;
    for (int py = 0; py <= 1088; py += 68)
        for (int px = 0; px <= 1456; px += 91) {
            const vision::PlanePoint q = m.map(vision::Q16_16::fromInt(px), vision::Q16_16::fromInt(py));
            ASSERT_TRUE(q.valid);
            const cv::Point2d r = backProject(c, px, py);
            worst = std::max(worst, std::hypot(q.x.toDouble() - r.x, q.y.toDouble() - r.y));
        }
    EXPECT_LT(worst, 5e-7);
}

TEST(PlaneCalibration, PinholeWithoutTiltIsAPlainScale)
{
    PlaneCalibration c;
    c.fx = c.fy = 4000;
    c.cx = 700, c.cy = 500;
    c.t[2] = 100;    // fixture 100 mm in front; z of the fixture points away from the camera
    c.heightMm = 20; // the plane 20 mm nearer: 80 mm, 0.02 mm/px
    const vision::PlanePoint q = vision::pixelToPlane(c, 900, 400);
    ASSERT_TRUE(q.valid);
    EXPECT_NEAR(q.x.toDouble(), 200 * 0.02, 1e-8);
    EXPECT_NEAR(q.y.toDouble(), -100 * 0.02, 1e-8);
    EXPECT_NEAR(vision::planeScaleAt(c, 700, 500), 0.02, 1e-8);
}

TEST(PlaneCalibration, RefusesWhatItCannotMap)
{
    PlaneCalibration bad;
    EXPECT_FALSE(bad.valid()); // no focal length
    EXPECT_FALSE(vision::pixelToPlane(bad, 10, 10).valid);
    PlaneCalibration c = tiltedCamera(5);
    c.r[0] = 2; // not a rotation
    EXPECT_FALSE(c.valid());
    c = tiltedCamera(5);
    EXPECT_FALSE(vision::pixelToPlane(c, 1e4, 0).valid); // beyond the accepted field
    c.k1 = -40;                                          // folds over inside the frame
    EXPECT_FALSE(vision::pixelToPlane(c, 0, 0).valid);
    c = tiltedCamera(5);
    c.heightMm = 1000; // the plane behind the camera
    EXPECT_FALSE(vision::pixelToPlane(c, 700, 500).valid);
    // Extreme Q16.16 inputs are refused, not wrapped.
    c = tiltedCamera(5);
    EXPECT_FALSE(vision::pixelToPlane(c, -32768, -32768).valid);
    EXPECT_FALSE(vision::pixelToPlane(c, 32767, 32767).valid);
}

TEST(PlaneCalibration, EquivalentRadiusMatchesADenseDoublePolygon)
{
    const PlaneCalibration c = tiltedCamera(7.5);
    vision::BoundaryFit f;
    f.harmonics = 4;
    f.a0 = 430, f.a[1] = 3, f.b[1] = -2, f.a[2] = 4, f.b[3] = -1.5, f.a[4] = 0.8;
    const double cx = 760, cy = 520;
    const double r = vision::equivalentRadiusMm(f, cx, cy, c);
    // Reference: 20000 points through OpenCV's undistortPoints and a double intersection.
    const int N = 20000;
    double area2 = 0;
    cv::Point2d prev;
    for (int i = 0; i <= N; ++i) {
        const double t = 2 * std::numbers::pi * (i % N) / N, rr = f.radiusAt(t);
        const cv::Point2d p = backProject(c, cx + rr * std::cos(t), cy + rr * std::sin(t));
        if (i) area2 += prev.x * p.y - p.x * prev.y;
        prev = p;
    }
    const double ref = std::sqrt(std::fabs(area2) / 2 / std::numbers::pi);
    std::printf("equivalent radius: %.7f mm, reference %.7f mm, diff %.2e mm\n", r, ref, r - ref);
    // Bound: 1e-6 mm, a ten-thousandth of the 0.01 mm in u that moves μ by 0.001–0.007
    // (measured 2e-8 mm: the N-gon's area bias is corrected, the rest is Q16.16 rounding).
    EXPECT_NEAR(r, ref, 1e-6);
    vision::PlaneCalibration broken = c;
    broken.fx = 0;
    EXPECT_EQ(vision::equivalentRadiusMm(f, cx, cy, broken), 0.0);
}

// The shape in the plane (what the calibrated elliptical and centre_offset checks use):
// through an untilted pinhole the plane is the image scaled, so the outline's ellipticity
// and axis must be the pixel fit's and its centroid the first harmonic's offset; through a
// tilted camera, a circle in the plane must come back round.
TEST(PlaneCalibration, OutlineShapeInThePlane)
{
    PlaneCalibration c;
    c.fx = c.fy = 4000;
    c.cx = 700, c.cy = 500;
    c.t[2] = 100;
    c.heightMm = 20; // 0.02 mm/px
    vision::BoundaryFit f;
    f.harmonics = 2;
    f.a0 = 400, f.a[1] = 3;
    const double c2 = 4, axis = 30 * std::numbers::pi / 180;
    f.a[2] = c2 * std::cos(2 * axis), f.b[2] = c2 * std::sin(2 * axis);
    const vision::PlaneOutline o = vision::planeOutline(f, 700, 500, c);
    ASSERT_TRUE(o.valid);
    const double pixelEllipticity = 2 * c2 / (f.a0 + c2); // boundary_fit's definition
    std::printf("outline: ellipticity %.6f (pixel fit %.6f), axis %.3f deg, centroid %.5f %.5f mm\n", o.ellipticity,
                pixelEllipticity, o.axisDeg, o.centroidX, o.centroidY);
    EXPECT_NEAR(o.ellipticity, pixelEllipticity, 2e-4);
    EXPECT_NEAR(o.axisDeg, 30, 0.05);
    // The first harmonic is the centroid to first order; the cross term a1·c2/a0 (0.03 px
    // here) separates them.
    EXPECT_NEAR(o.centroidX, 3 * 0.02, 1e-3);
    EXPECT_NEAR(o.centroidY, 0, 1e-3);
    EXPECT_NEAR(o.rEqMm, vision::equivalentRadiusMm(f, 700, 500, c), 1e-12);

    // A 6 mm circle on the end face of the tilted camera, traced in pixels (OpenCV's
    // projection) and fitted with harmonics as the pipeline does: round in the plane.
    const PlaneCalibration t = tiltedCamera(7.5);
    const int n = 256;
    double radius[n];
    bool valid[n];
    std::vector<cv::Point2d> px;
    for (int i = 0; i < 720; ++i) {
        const double a = 2 * std::numbers::pi * i / 720;
        px.push_back(project(t, 6 * std::cos(a), 6 * std::sin(a)));
    }
    double mx = 0, my = 0;
    for (const auto &p : px) mx += p.x / double(px.size()), my += p.y / double(px.size());
    // Radius of the projected curve on n rays about its mean point (nearest sample in angle).
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        double best = 1e9, r = 0;
        for (const auto &p : px) {
            const double d = std::fabs(std::remainder(std::atan2(p.y - my, p.x - mx) - a, 2 * std::numbers::pi));
            if (d < best) best = d, r = std::hypot(p.x - mx, p.y - my);
        }
        radius[i] = r, valid[i] = true;
    }
    vision::BoundaryFit g;
    vision::FitOptions opt;
    opt.maxHarmonics = 8;
    ASSERT_TRUE(vision::fitBoundary(radius, valid, n, mx, my, opt, &g));
    const vision::PlaneOutline round = vision::planeOutline(g, mx, my, t);
    std::printf("tilted camera: pixel ellipticity %.4f, in the plane %.5f, r %.4f mm\n", g.ellipticity,
                round.ellipticity, round.rEqMm);
    EXPECT_GT(g.ellipticity, 0.005); // the camera does make it elliptical in the image
    EXPECT_LT(round.ellipticity, 0.0005);
    EXPECT_NEAR(round.rEqMm, 6, 0.002);
}
