// `icacam calibrate` on board photos rendered through a known tilted, distorting camera:
// the parameters come back within stated tolerances; too few or blurred views are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "calibration/calibration_file.h"
#include "host_tools/calibrate_command.h"
#include "host_tools/calibration_renderer.h"
#include "vision/plane_calibration.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string &name)
{
    const fs::path d = fs::temp_directory_path() / ("icacam-calib-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// The board lying flat on the fixture, centred on the fixture's origin.
std::pair<cv::Vec3d, cv::Vec3d> flatPose(const host::CameraModel &cam, const host::ChessboardSpec &b)
{
    cv::Matx33d R;
    cv::Rodrigues(cam.fixtureRvec, R);
    const cv::Vec3d offset(-(b.cols - 1) * b.squareMm / 2, -(b.rows - 1) * b.squareMm / 2, 0);
    return {cam.fixtureRvec, cam.fixtureTvec + R * offset};
}

// Renders `count` views (blurred by blurPx) and the flat view into a folder.
fs::path renderSet(const std::string &name, const host::BoardPhotoRenderer &r, const host::ChessboardSpec &b, int count,
                   double blurPx)
{
    const fs::path d = freshDir(name);
    const auto poses = host::calibrationPoses(r.camera(), b, count, 7);
    for (size_t i = 0; i < poses.size(); ++i)
        cv::imwrite((d / ("view" + std::to_string(10 + i) + ".png")).string(),
                    r.chessboard(b, poses[i].first, poses[i].second, blurPx, 2.0, uint32_t(100 + i)));
    const auto flat = flatPose(r.camera(), b);
    cv::imwrite((d / "flat.png").string(), r.chessboard(b, flat.first, flat.second, 0.8, 2.0, 99));
    return d;
}

// The same for a circle grid (poses from the same generator, over the grid's outline).
fs::path renderCircleSet(const std::string &name, const host::BoardPhotoRenderer &r, const host::CircleGridSpec &g,
                         int count, double blurPx)
{
    const fs::path d = freshDir(name);
    const auto poses = host::calibrationPoses(r.camera(), g.extent(), count, 7);
    for (size_t i = 0; i < poses.size(); ++i)
        cv::imwrite((d / ("view" + std::to_string(10 + i) + ".png")).string(),
                    r.circleGrid(g, poses[i].first, poses[i].second, blurPx, 2.0, uint32_t(100 + i)));
    const auto flat = flatPose(r.camera(), g.extent());
    cv::imwrite((d / "flat.png").string(), r.circleGrid(g, flat.first, flat.second, 0.8, 2.0, 99));
    return d;
}

std::string runCalibrate(const fs::path &dir, const std::string &out, const std::string &board = "chessboard:9x7:1.4",
                         const std::vector<std::string> &extra = {})
{
    std::vector<std::string> args{"--images", dir.string(), "--board", board, "--flat", (dir / "flat.png").string(),
                                  "--out",    out};
    args.insert(args.end(), extra.begin(), extra.end());
    try {
        host::calibrateCommand(args);
    } catch (const std::exception &e) {
        return e.what();
    }
    return "";
}

// The angle between the fixture's normal and the camera's axis (degrees).
double tiltDeg(const vision::PlaneCalibration &p)
{
    return std::acos(std::min(1.0, std::fabs(p.r[8]))) * 180 / M_PI;
}

} // namespace

TEST(Calibrate, RecoversTheCameraAndTheFixturePlane)
{
    const host::CameraModel cam = host::exampleTiltedCamera();
    const host::BoardPhotoRenderer r(cam);
    const host::ChessboardSpec b;
    const fs::path d = renderSet("good", r, b, 14, 0.8);
    const std::string out = (d / "camera.cal").string();
    ASSERT_EQ(runCalibrate(d, out), "");
    calibration::CalibrationFile c;
    ASSERT_EQ(calibration::readCalibrationFile(out, &c), "");
    const vision::PlaneCalibration &p = c.plane;
    std::printf("calibrate: rms %.3f px, fx %.1f (%.1f) fy %.1f (%.1f) cx %.1f (%.1f) cy %.1f (%.1f) "
                "k1 %.4f (%.4f) k2 %.3f (%.3f)\n",
                c.rmsPx, p.fx, cam.fx, p.fy, cam.fy, p.cx, cam.cx, p.cy, cam.cy, p.k1, cam.k1, p.k2, cam.k2);
    EXPECT_EQ(c.views, 15);
    EXPECT_LT(c.rmsPx, 0.15);
    // Tolerances: focal length 0.5 %, principal point 8 px (both trade against tilt in a
    // narrow field), k1 0.05.
    EXPECT_NEAR(p.fx / cam.fx, 1, 0.005);
    EXPECT_NEAR(p.fy / cam.fy, 1, 0.005);
    EXPECT_NEAR(p.cx, cam.cx, 8);
    EXPECT_NEAR(p.cy, cam.cy, 8);
    EXPECT_NEAR(p.k1, cam.k1, 0.05);
    // What the measurement needs: the map into the end-face plane. Over the specimen's
    // area (±8 mm) at 7.5 mm height, points land within 0.004 mm and the local scale
    // within 0.1 % of the truth.
    vision::PlaneCalibration truth = host::toPlaneCalibration(cam);
    truth.heightMm = 7.5;
    vision::PlaneCalibration got = p;
    got.heightMm = 7.5;
    double worst = 0;
    for (double y = 150; y <= 950; y += 100)
        for (double x = 250; x <= 1250; x += 100) {
            const auto a = vision::pixelToPlane(truth, x, y), g = vision::pixelToPlane(got, x, y);
            ASSERT_TRUE(a.valid && g.valid);
            // Positions are relative to the board origin: compare distances from the centre.
            const auto a0 = vision::pixelToPlane(truth, 741, 531), g0 = vision::pixelToPlane(got, 741, 531);
            worst = std::max(worst, std::fabs(std::hypot((a.x - a0.x).toDouble(), (a.y - a0.y).toDouble()) -
                                              std::hypot((g.x - g0.x).toDouble(), (g.y - g0.y).toDouble())));
        }
    const double sTrue = vision::planeScaleAt(truth, 741, 531), sGot = vision::planeScaleAt(got, 741, 531);
    std::printf("calibrate: worst distance error %.4f mm, scale %.6f vs %.6f mm/px (%.3f %%)\n", worst, sGot, sTrue,
                100 * (sGot / sTrue - 1));
    EXPECT_LT(worst, 0.004);
    EXPECT_NEAR(sGot / sTrue, 1, 0.001);
    fs::remove_all(d);
}

// What the measurement needs from a calibration: distances in the end-face plane (7.5 mm
// above the fixture) over the specimen's area, and the local scale at the image centre.
// Returns the worst distance error (mm) and sets *scaleRatio (recovered / true).
double planeError(const host::CameraModel &cam, const vision::PlaneCalibration &p, double *scaleRatio)
{
    vision::PlaneCalibration truth = host::toPlaneCalibration(cam);
    truth.heightMm = 7.5;
    vision::PlaneCalibration got = p;
    got.heightMm = 7.5;
    double worst = 0;
    const auto a0 = vision::pixelToPlane(truth, 741, 531), g0 = vision::pixelToPlane(got, 741, 531);
    for (double y = 150; y <= 950; y += 100)
        for (double x = 250; x <= 1250; x += 100) {
            const auto a = vision::pixelToPlane(truth, x, y), g = vision::pixelToPlane(got, x, y);
            if (!a.valid || !g.valid) return 1e9;
            // Positions are relative to the board origin: compare distances from the centre.
            worst = std::max(worst, std::fabs(std::hypot((a.x - a0.x).toDouble(), (a.y - a0.y).toDouble()) -
                                              std::hypot((g.x - g0.x).toDouble(), (g.y - g0.y).toDouble())));
        }
    *scaleRatio = vision::planeScaleAt(got, 741, 531) / vision::planeScaleAt(truth, 741, 531);
    return worst;
}

// A circle grid (symmetric, dark dots) instead of a chessboard: the same camera back within
// the same stated tolerances, except the principal point (blob centroids are shifted by
// perspective, which the principal point and tilt absorb: 12 px instead of 8).
TEST(Calibrate, CircleGridRecoversTheCameraAndTheFixturePlane)
{
    const host::CameraModel cam = host::exampleTiltedCamera();
    const host::BoardPhotoRenderer r(cam);
    const host::CircleGridSpec g;
    const fs::path d = renderCircleSet("circles", r, g, 14, 0.8);
    const std::string out = (d / "camera.cal").string();
    ASSERT_EQ(runCalibrate(d, out, "circles:9x7:1.4"), "");
    calibration::CalibrationFile c;
    ASSERT_EQ(calibration::readCalibrationFile(out, &c), "");
    const vision::PlaneCalibration &p = c.plane;
    double scale = 0;
    const double worst = planeError(cam, p, &scale);
    std::printf("calibrate circles: %d views, rms %.3f px, fx %.1f (%.1f) fy %.1f (%.1f) cx %.1f (%.1f) cy %.1f "
                "(%.1f) k1 %.4f (%.4f) k2 %.3f (%.3f); worst distance error %.4f mm, scale %.3f %%\n",
                c.views, c.rmsPx, p.fx, cam.fx, p.fy, cam.fy, p.cx, cam.cx, p.cy, cam.cy, p.k1, cam.k1, p.k2, cam.k2,
                worst, 100 * (scale - 1));
    EXPECT_EQ(c.views, 15);
    EXPECT_EQ(c.board, "circles:9x7:1.4");
    EXPECT_LT(c.rmsPx, 0.15);
    EXPECT_NEAR(p.fx / cam.fx, 1, 0.005);
    EXPECT_NEAR(p.fy / cam.fy, 1, 0.005);
    EXPECT_NEAR(p.cx, cam.cx, 12);
    EXPECT_NEAR(p.cy, cam.cy, 12);
    EXPECT_NEAR(p.k1, cam.k1, 0.05);
    EXPECT_LT(worst, 0.004);
    EXPECT_NEAR(scale, 1, 0.001);
    fs::remove_all(d);
}

// Soft views (OpenCV's edge width 3.4–3.9 px, which a fixed 3 px limit refused) that still
// calibrate to a tenth of a pixel are used: the camera comes back as from sharp views.
TEST(Calibrate, AcceptsSoftViewsThatCalibrateWell)
{
    const host::CameraModel cam = host::exampleTiltedCamera();
    const host::BoardPhotoRenderer r(cam);
    const host::ChessboardSpec b;
    const fs::path d = renderSet("soft", r, b, 12, 1.25);
    double lo = 1e9, hi = 0;
    for (const auto &e : fs::directory_iterator(d)) {
        const cv::Mat g = cv::imread(e.path().string(), cv::IMREAD_GRAYSCALE);
        std::vector<cv::Point2f> pts;
        if (e.path().filename() == "flat.png" || !cv::findChessboardCorners(g, {b.cols, b.rows}, pts)) continue;
        const double w = cv::estimateChessboardSharpness(g, {b.cols, b.rows}, pts)[0];
        lo = std::min(lo, w), hi = std::max(hi, w);
    }
    std::printf("soft views: edge width %.2f–%.2f px\n", lo, hi);
    ASSERT_GT(lo, 3.3) << "the set must be soft enough that a 3 px limit refuses every view";
    ASSERT_LT(hi, 4.0);
    const std::string out = (d / "camera.cal").string();
    ASSERT_EQ(runCalibrate(d, out), "");
    calibration::CalibrationFile c;
    ASSERT_EQ(calibration::readCalibrationFile(out, &c), "");
    const vision::PlaneCalibration &p = c.plane, truth = host::toPlaneCalibration(cam);
    std::printf("soft views: %d used, rms %.3f px, fx %.2f (%.2f) fy %.2f (%.2f), tilt %.3f (%.3f) deg\n", c.views,
                c.rmsPx, p.fx, cam.fx, p.fy, cam.fy, tiltDeg(p), tiltDeg(truth));
    EXPECT_EQ(c.views, 13);
    EXPECT_LT(c.rmsPx, 0.2);
    EXPECT_NEAR(p.fx / cam.fx, 1, 0.001);
    EXPECT_NEAR(p.fy / cam.fy, 1, 0.001);
    EXPECT_NEAR(tiltDeg(p), tiltDeg(truth), 0.1);
    // The old fixed limit, asked for explicitly, refuses all but the sharp flat view.
    testing::internal::CaptureStderr();
    const std::string limited =
        runCalibrate(d, (d / "limited.cal").string(), "chessboard:9x7:1.4", {"--max-blur", "3"});
    testing::internal::GetCapturedStderr();
    EXPECT_NE(limited.find("only 1 usable view"), std::string::npos) << limited;
    fs::remove_all(d);
}

// A board that moved while a rolling shutter read it out fits no single pose: the view is
// dropped with its reprojection error named, and the rest calibrate as if it were not there.
TEST(Calibrate, DropsAViewThatDoesNotFit)
{
    const host::CameraModel cam = host::exampleTiltedCamera();
    const host::BoardPhotoRenderer r(cam);
    const host::ChessboardSpec b;
    const fs::path d = renderSet("moving", r, b, 12, 0.8);
    const auto poses = host::calibrationPoses(cam, b, 14, 31);
    const cv::Vec3d r0 = poses.back().first, t0 = poses.back().second;
    const cv::Vec3d r1 = r0 + cv::Vec3d(0.03, -0.02, 0.02), t1 = t0 + cv::Vec3d(0.8, 0.5, 0);
    cv::imwrite((d / "view50.png").string(), r.movingChessboard(b, r0, t0, r1, t1, 0.8, 2.0, 5));
    testing::internal::CaptureStderr();
    const std::string e = runCalibrate(d, (d / "camera.cal").string());
    const std::string why = testing::internal::GetCapturedStderr();
    ASSERT_EQ(e, "");
    std::printf("%s", why.c_str());
    EXPECT_NE(why.find("view50.png: dropped: reprojection error"), std::string::npos) << why;
    calibration::CalibrationFile c;
    ASSERT_EQ(calibration::readCalibrationFile((d / "camera.cal").string(), &c), "");
    EXPECT_EQ(c.views, 13);
    EXPECT_LT(c.rmsPx, 0.15);
    EXPECT_NEAR(c.plane.fx / cam.fx, 1, 0.002);
    EXPECT_NEAR(tiltDeg(c.plane), tiltDeg(host::toPlaneCalibration(cam)), 0.1);
    fs::remove_all(d);
}

TEST(Calibrate, CircleGridRefusesTooFewOrBlurredViews)
{
    const host::BoardPhotoRenderer r(host::exampleTiltedCamera());
    {
        const fs::path d = renderCircleSet("circles-few", r, host::CircleGridSpec{}, 3, 0.8); // 3 + flat = 4
        const std::string e = runCalibrate(d, (d / "camera.cal").string(), "circles:9x7:1.4");
        EXPECT_NE(e.find("only 4 usable views"), std::string::npos) << e;
        EXPECT_FALSE(fs::exists(d / "camera.cal"));
        fs::remove_all(d);
    }
    {
        // With the optional edge-width limit (--max-blur 3), soft dots are refused by name.
        const fs::path d = renderCircleSet("circles-blurred", r, host::CircleGridSpec{}, 8, 3.0); // 8 soft + flat
        testing::internal::CaptureStderr();
        const std::string e = runCalibrate(d, (d / "camera.cal").string(), "circles:9x7:1.4", {"--max-blur", "3"});
        const std::string why = testing::internal::GetCapturedStderr();
        EXPECT_NE(e.find("only 1 usable view"), std::string::npos) << e;
        // Each soft view is named with the reason: too soft to find, or found and refused.
        EXPECT_NE(why.find("view10.png: "), std::string::npos) << why;
        EXPECT_NE(why.find("blurred (dot edge width"), std::string::npos) << why;
        EXPECT_FALSE(fs::exists(d / "camera.cal"));
        fs::remove_all(d);
    }
}

TEST(Calibrate, RefusesTooFewViews)
{
    const host::BoardPhotoRenderer r(host::exampleTiltedCamera());
    const fs::path d = renderSet("few", r, host::ChessboardSpec{}, 3, 0.8); // 3 + flat = 4
    const std::string e = runCalibrate(d, (d / "camera.cal").string());
    EXPECT_NE(e.find("only 4 usable views"), std::string::npos) << e;
    EXPECT_NE(e.find("at least 5"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(d / "camera.cal"));
    fs::remove_all(d);
}

// Views blurred by σ = 4 px: found, all alike, none standing out, but together they
// calibrate to more than a pixel: refused as a whole, no file written.
TEST(Calibrate, RefusesViewsThatDoNotCalibrateWell)
{
    const host::BoardPhotoRenderer r(host::exampleTiltedCamera());
    const fs::path d = renderSet("blurred", r, host::ChessboardSpec{}, 8, 4.0); // 8 soft + sharp flat
    const std::string e = runCalibrate(d, (d / "camera.cal").string());
    EXPECT_NE(e.find("RMS reprojection error of"), std::string::npos) << e;
    EXPECT_NE(e.find("no file written"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(d / "camera.cal"));
    fs::remove_all(d);
}

TEST(CalibrationFile, RoundTripsAndNamesBadLines)
{
    calibration::CalibrationFile c;
    c.plane = host::toPlaneCalibration(host::exampleTiltedCamera());
    c.imageWidth = 1456, c.imageHeight = 1088, c.rmsPx = 0.05, c.views = 12, c.board = "chessboard:9x7:1.4";
    const fs::path d = freshDir("file");
    ASSERT_EQ(calibration::writeCalibrationFile((d / "a.cal").string(), c), "");
    calibration::CalibrationFile back;
    ASSERT_EQ(calibration::readCalibrationFile((d / "a.cal").string(), &back), "");
    EXPECT_EQ(back.plane.fx, c.plane.fx);
    EXPECT_EQ(back.plane.k2, c.plane.k2);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(back.plane.r[i], c.plane.r[i]);
    EXPECT_EQ(back.imageWidth, 1456);
    EXPECT_EQ(back.board, c.board);
    calibration::CalibrationFile x;
    EXPECT_NE(calibration::parseCalibrationText("fx = 1\n", &x).find("missing 'format'"), std::string::npos);
    EXPECT_NE(calibration::parseCalibrationText("format = icacam-calibration-1\nfx 1\n", &x).find("line 2"),
              std::string::npos);
    EXPECT_NE(calibration::parseCalibrationText("format = icacam-calibration-1\nimage_size = 10\n", &x)
                  .find("image_size needs 2 numbers"),
              std::string::npos);
    EXPECT_NE(calibration::readCalibrationFile((d / "missing.cal").string(), &x).find("cannot read"),
              std::string::npos);
    fs::remove_all(d);
}
