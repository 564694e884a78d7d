#include "host_tools/calibration_renderer.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace icacam::host {

namespace {

constexpr double kDeg = M_PI / 180;

cv::Matx33d rotation(const cv::Vec3d &rvec)
{
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    return R;
}

// Integral of the ±1 square wave of period 2 (+1 on [0,1)): a triangle wave.
double squareIntegral(double a)
{
    const double m = a - 2 * std::floor(a / 2);
    return m < 1 ? m : 2 - m;
}
// The square wave box-filtered over width w (both in square units): exact anti-aliasing.
double filteredSquare(double a, double w)
{
    if (w < 1e-9) return (int64_t(std::floor(a)) & 1) ? -1 : 1;
    return (squareIntegral(a + w / 2) - squareIntegral(a - w / 2)) / w;
}
// A unit step at a0 box-filtered over width w.
double filteredStep(double a, double a0, double w)
{
    return std::clamp((a - a0) / w + 0.5, 0.0, 1.0);
}

void addNoise(cv::Mat &f, double blurPx, double noise, uint32_t seed)
{
    if (blurPx > 0) cv::GaussianBlur(f, f, {0, 0}, blurPx);
    if (noise > 0) {
        cv::Mat n(f.size(), CV_64F);
        cv::RNG rng(seed);
        rng.fill(n, cv::RNG::NORMAL, 0, noise);
        f += n;
    }
}

} // namespace

CameraModel exampleTiltedCamera()
{
    CameraModel c;
    c.fx = 4000, c.fy = 4006, c.cx = 741, c.cy = 531;
    c.k1 = -0.25, c.k2 = 0.6, c.p1 = 0.0008, c.p2 = -0.0006, c.k3 = 0;
    // Tilt: 8° about x, then 5° about y.
    const cv::Matx33d R = rotation({8 * kDeg, 0, 0}) * rotation({0, 5 * kDeg, 0});
    cv::Vec3d rvec;
    cv::Rodrigues(R, rvec);
    c.fixtureRvec = rvec;
    c.fixtureTvec = {0.4, -0.3, 62};
    return c;
}

vision::PlaneCalibration toPlaneCalibration(const CameraModel &cam)
{
    vision::PlaneCalibration p;
    p.fx = cam.fx, p.fy = cam.fy, p.cx = cam.cx, p.cy = cam.cy;
    p.k1 = cam.k1, p.k2 = cam.k2, p.p1 = cam.p1, p.p2 = cam.p2, p.k3 = cam.k3;
    const cv::Matx33d R = rotation(cam.fixtureRvec);
    for (int i = 0; i < 9; ++i) p.r[i] = R.val[i];
    for (int i = 0; i < 3; ++i) p.t[i] = cam.fixtureTvec[i];
    return p;
}

std::vector<cv::Point3f> chessboardCorners(const ChessboardSpec &b)
{
    std::vector<cv::Point3f> pts;
    for (int j = 0; j < b.rows; ++j)
        for (int i = 0; i < b.cols; ++i) pts.emplace_back(float(i * b.squareMm), float(j * b.squareMm), 0.f);
    return pts;
}

BoardPhotoRenderer::BoardPhotoRenderer(const CameraModel &cam) : cam_(cam)
{
    std::vector<cv::Point2d> px;
    px.reserve(size_t(cam.width) * size_t(cam.height));
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) px.emplace_back(x, y);
    const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
    const std::vector<double> D{cam.k1, cam.k2, cam.p1, cam.p2, cam.k3};
    std::vector<cv::Point2d> und;
    cv::undistortPoints(px, und, K, D, cv::noArray(), cv::noArray(),
                        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-14));
    rays_ = cv::Mat(cam.height, cam.width, CV_64FC2);
    std::copy(und.begin(), und.end(), rays_.ptr<cv::Point2d>(0));
}

void BoardPhotoRenderer::intersect(const cv::Matx33d &R, const cv::Vec3d &t, double zMm, cv::Mat *X, cv::Mat *Y,
                                   cv::Mat *footprint) const
{
    const cv::Matx33d Rt = R.t();
    const cv::Vec3d b = Rt * t;
    X->create(cam_.height, cam_.width, CV_64F);
    Y->create(cam_.height, cam_.width, CV_64F);
    if (footprint) footprint->create(cam_.height, cam_.width, CV_64F);
    for (int y = 0; y < cam_.height; ++y) {
        const cv::Point2d *r = rays_.ptr<cv::Point2d>(y);
        double *xo = X->ptr<double>(y), *yo = Y->ptr<double>(y);
        for (int x = 0; x < cam_.width; ++x) {
            const cv::Vec3d a = Rt * cv::Vec3d(r[x].x, r[x].y, 1);
            const double lambda = (zMm + b[2]) / a[2];
            xo[x] = lambda * a[0] - b[0];
            yo[x] = lambda * a[1] - b[1];
            // One pixel's size on the plane, stretched by the obliquity.
            if (footprint) footprint->at<double>(y, x) = lambda / cam_.fx * cv::norm(a) / std::fabs(a[2]);
        }
    }
}

cv::Mat BoardPhotoRenderer::chessboard(const ChessboardSpec &b, const cv::Vec3d &rvec, const cv::Vec3d &tvec,
                                       double blurPx, double noise, uint32_t seed) const
{
    cv::Mat X, Y, fp;
    intersect(rotation(rvec), tvec, 0, &X, &Y, &fp);
    const double dark = 35, white = 215, surround = 110;
    const double s = b.squareMm;
    cv::Mat f(cam_.height, cam_.width, CV_64F);
    for (int y = 0; y < cam_.height; ++y)
        for (int x = 0; x < cam_.width; ++x) {
            const double bx = X.at<double>(y, x) / s, by = Y.at<double>(y, x) / s;
            const double w = fp.at<double>(y, x) / s;
            // Squares span [-1, cols] × [-1, rows] in square units; paper to 1 square beyond.
            const double inX = filteredStep(bx, -1, w) * (1 - filteredStep(bx, b.cols, w));
            const double inY = filteredStep(by, -1, w) * (1 - filteredStep(by, b.rows, w));
            const double paperX = filteredStep(bx, -2, w) * (1 - filteredStep(bx, b.cols + 1, w));
            const double paperY = filteredStep(by, -2, w) * (1 - filteredStep(by, b.rows + 1, w));
            const double checker = filteredSquare(bx, w) * filteredSquare(by, w); // +1 white
            const double squares = 0.5 * (dark + white) + 0.5 * (white - dark) * checker;
            const double board = white + (squares - white) * inX * inY;
            f.at<double>(y, x) = surround + (board - surround) * paperX * paperY;
        }
    addNoise(f, blurPx, noise, seed);
    cv::Mat out;
    f.convertTo(out, CV_8U);
    return out;
}

cv::Mat BoardPhotoRenderer::movingChessboard(const ChessboardSpec &b, const cv::Vec3d &rvec0, const cv::Vec3d &tvec0,
                                             const cv::Vec3d &rvec1, const cv::Vec3d &tvec1, double blurPx,
                                             double noise, uint32_t seed) const
{
    // Sharp frames at poses along the path, blended row by row at each row's exposure time.
    constexpr int kSteps = 8;
    std::vector<cv::Mat> frames;
    for (int k = 0; k <= kSteps; ++k) {
        const double a = double(k) / kSteps;
        cv::Mat f;
        chessboard(b, (1 - a) * rvec0 + a * rvec1, (1 - a) * tvec0 + a * tvec1, 0, 0, 0).convertTo(f, CV_64F);
        frames.push_back(f);
    }
    cv::Mat f(cam_.height, cam_.width, CV_64F);
    for (int y = 0; y < cam_.height; ++y) {
        const double tau = double(y) / std::max(1, cam_.height - 1) * kSteps;
        const int k = std::min(kSteps - 1, int(tau));
        const double w = tau - k;
        cv::Mat row = f.row(y);
        cv::addWeighted(frames[size_t(k)].row(y), 1 - w, frames[size_t(k) + 1].row(y), w, 0, row);
    }
    addNoise(f, blurPx, noise, seed);
    cv::Mat out;
    f.convertTo(out, CV_8U);
    return out;
}

cv::Mat BoardPhotoRenderer::circleGrid(const CircleGridSpec &g, const cv::Vec3d &rvec, const cv::Vec3d &tvec,
                                       double blurPx, double noise, uint32_t seed) const
{
    cv::Mat X, Y, fp;
    intersect(rotation(rvec), tvec, 0, &X, &Y, &fp);
    const double dark = 35, white = 215, surround = 110;
    const double s = g.spacingMm, r = 0.5 * g.dotDiameterMm;
    cv::Mat f(cam_.height, cam_.width, CV_64F);
    for (int y = 0; y < cam_.height; ++y)
        for (int x = 0; x < cam_.width; ++x) {
            const double bx = X.at<double>(y, x), by = Y.at<double>(y, x), w = fp.at<double>(y, x);
            // The nearest dot: the grid is sparse (dots half a pitch wide), so only one
            // dot can touch a pixel's footprint.
            const double i = std::clamp(std::round(bx / s), 0.0, double(g.cols - 1));
            const double j = std::clamp(std::round(by / s), 0.0, double(g.rows - 1));
            const double d = std::hypot(bx - i * s, by - j * s);
            const double ink = 1 - filteredStep(d, r, w); // 1 inside the dot, box-filtered edge
            const double paperX = filteredStep(bx, -1.5 * s, w) * (1 - filteredStep(bx, (g.cols - 0.5) * s, w));
            const double paperY = filteredStep(by, -1.5 * s, w) * (1 - filteredStep(by, (g.rows - 0.5) * s, w));
            const double board = white + (dark - white) * ink;
            f.at<double>(y, x) = surround + (board - surround) * paperX * paperY;
        }
    addNoise(f, blurPx, noise, seed);
    cv::Mat out;
    f.convertTo(out, CV_8U);
    return out;
}

cv::Mat BoardPhotoRenderer::disc(double diameterMm, double xMm, double yMm, double heightMm, double discGrey,
                                 double fixtureGrey, double blurPx, double noise, uint32_t seed) const
{
    const cv::Matx33d R = rotation(cam_.fixtureRvec);
    const cv::Vec3d b = R.t() * cam_.fixtureTvec;
    const double up = -b[2] >= 0 ? 1.0 : -1.0; // the camera's side of the fixture
    cv::Mat X, Y, fp;
    intersect(R, cam_.fixtureTvec, up * heightMm, &X, &Y, &fp);
    cv::Mat f(cam_.height, cam_.width, CV_64F);
    for (int y = 0; y < cam_.height; ++y)
        for (int x = 0; x < cam_.width; ++x) {
            const double d = std::hypot(X.at<double>(y, x) - xMm, Y.at<double>(y, x) - yMm);
            const double inside = 1 - filteredStep(d, 0.5 * diameterMm, fp.at<double>(y, x));
            f.at<double>(y, x) = fixtureGrey + (discGrey - fixtureGrey) * inside;
        }
    addNoise(f, blurPx, noise, seed);
    cv::Mat out;
    f.convertTo(out, CV_8U);
    return out;
}

cv::Mat BoardPhotoRenderer::endFace(const EndFaceScene &scene, double xMm, double yMm, double heightMm, double blurPx,
                                    double noise, uint32_t seed) const
{
    // The end face rendered flat and clean at a fine scale, as a texture in mm.
    EndFaceScene tex = scene;
    tex.mmPerPx = 0.005;
    const int half = int(std::ceil((scene.rMaxMm + 1.0) / tex.mmPerPx));
    tex.width = tex.height = 2 * half + 1;
    tex.cxPx = tex.cyPx = half;
    tex.blurSigmaPx = 0, tex.noiseSigma = 0, tex.jpegQuality = 0;
    tex.distractor = false;
    cv::Mat texture;
    renderEndFace(tex).convertTo(texture, CV_32F);

    const cv::Matx33d R = rotation(cam_.fixtureRvec);
    const cv::Vec3d b = R.t() * cam_.fixtureTvec;
    const double up = -b[2] >= 0 ? 1.0 : -1.0; // the camera's side of the fixture
    cv::Mat X1, Y1, X2, Y2;
    intersect(R, cam_.fixtureTvec, up * heightMm, &X1, &Y1, nullptr);
    intersect(R, cam_.fixtureTvec, up * heightMm / 2, &X2, &Y2, nullptr);
    cv::Mat mapX(cam_.height, cam_.width, CV_32F), mapY(cam_.height, cam_.width, CV_32F);
    const double split = 0.5 * (scene.rOuterMm + scene.rMaxMm);
    for (int y = 0; y < cam_.height; ++y)
        for (int x = 0; x < cam_.width; ++x) {
            double dx = X1.at<double>(y, x) - xMm, dy = Y1.at<double>(y, x) - yMm;
            if (std::hypot(dx, dy) > split) dx = X2.at<double>(y, x) - xMm, dy = Y2.at<double>(y, x) - yMm;
            mapX.at<float>(y, x) = float(half + dx / tex.mmPerPx);
            mapY.at<float>(y, x) = float(half + dy / tex.mmPerPx);
        }
    cv::Mat warped;
    // INTER_AREA is not available for remap; the texture is 2.7× finer than the camera, so
    // average a 3×3 neighbourhood first to keep the edges' ramps from aliasing.
    cv::Mat smooth;
    cv::blur(texture, smooth, {3, 3});
    cv::remap(smooth, warped, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(scene.background));
    cv::Mat f;
    warped.convertTo(f, CV_64F);
    addNoise(f, blurPx, noise, seed);
    cv::Mat out;
    f.convertTo(out, CV_8U);
    return out;
}

CameraModel tiltedCamera(int width, int height, double fPx, double cxPx, double cyPx, double k1, double tiltDeg,
                         double azimuthDeg, double fixtureDistanceMm)
{
    CameraModel c;
    c.width = width, c.height = height;
    c.fx = c.fy = fPx, c.cx = cxPx, c.cy = cyPx;
    c.k1 = k1, c.k2 = 0, c.p1 = c.p2 = c.k3 = 0;
    const double t = tiltDeg * kDeg, a = azimuthDeg * kDeg;
    c.fixtureRvec = {t * std::cos(a), t * std::sin(a), 0};
    c.fixtureTvec = {0, 0, fixtureDistanceMm};
    return c;
}

namespace {
// +1 when the camera is on the fixture's +z side: the plane h above the fixture is z = up·h.
double upSign(const cv::Matx33d &R, const cv::Vec3d &t)
{
    return -(R.t() * t)[2] >= 0 ? 1.0 : -1.0;
}
} // namespace

cv::Point2d axisOnPlane(const CameraModel &cam, double heightMm)
{
    const cv::Matx33d R = rotation(cam.fixtureRvec);
    const cv::Vec3d b = R.t() * cam.fixtureTvec, a = R.t() * cv::Vec3d(0, 0, 1);
    const double lambda = (upSign(R, cam.fixtureTvec) * heightMm + b[2]) / a[2];
    return {lambda * a[0] - b[0], lambda * a[1] - b[1]};
}

cv::Point2d projectFromPlane(const CameraModel &cam, double xMm, double yMm, double heightMm)
{
    const cv::Matx33d R = rotation(cam.fixtureRvec);
    const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
    const std::vector<double> D{cam.k1, cam.k2, cam.p1, cam.p2, cam.k3};
    const std::vector<cv::Point3d> p{{xMm, yMm, upSign(R, cam.fixtureTvec) * heightMm}};
    std::vector<cv::Point2d> img;
    cv::projectPoints(p, cam.fixtureRvec, cam.fixtureTvec, K, D, img);
    return img[0];
}

double planeScaleAtPoint(const CameraModel &cam, double xMm, double yMm, double heightMm)
{
    const double d = 0.05;
    const cv::Point2d o = projectFromPlane(cam, xMm, yMm, heightMm);
    const cv::Point2d ex = projectFromPlane(cam, xMm + d, yMm, heightMm) - o;
    const cv::Point2d ey = projectFromPlane(cam, xMm, yMm + d, heightMm) - o;
    return d / std::sqrt(std::fabs(ex.x * ey.y - ex.y * ey.x));
}

std::vector<std::pair<cv::Vec3d, cv::Vec3d>> calibrationPoses(const CameraModel &cam, const ChessboardSpec &b,
                                                              int count, uint32_t seed)
{
    std::mt19937 rng(seed);
    auto U = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
    const std::vector<double> D{cam.k1, cam.k2, cam.p1, cam.p2, cam.k3};
    const double s = b.squareMm;
    const std::vector<cv::Point3d> outline{{-2 * s, -2 * s, 0},
                                           {(b.cols + 1) * s, -2 * s, 0},
                                           {-2 * s, (b.rows + 1) * s, 0},
                                           {(b.cols + 1) * s, (b.rows + 1) * s, 0}};
    const cv::Vec3d centre((b.cols - 1) * s / 2, (b.rows - 1) * s / 2, 0);
    std::vector<std::pair<cv::Vec3d, cv::Vec3d>> poses;
    for (int tries = 0; int(poses.size()) < count && tries < 100 * count; ++tries) {
        const double dir = U(0, 2 * M_PI), tilt = (poses.size() < 2 ? U(0, 6) : U(10, 28)) * kDeg;
        const cv::Matx33d R =
            rotation({tilt * std::cos(dir), tilt * std::sin(dir), 0}) * rotation({0, 0, U(-15, 15) * kDeg});
        // Positions drawn for a 62 mm camera and scaled to this one's distance.
        const double k = std::fabs(cam.fixtureTvec[2]) / 62;
        const cv::Vec3d pos(U(-2.5, 2.5) * k, U(-2, 2) * k, U(52, 66) * k);
        const cv::Vec3d t = pos - R * centre;
        cv::Vec3d rvec;
        cv::Rodrigues(R, rvec);
        std::vector<cv::Point2d> img;
        cv::projectPoints(outline, rvec, t, K, D, img);
        bool inside = true;
        for (const auto &p : img)
            inside = inside && p.x > 10 && p.y > 10 && p.x < cam.width - 10 && p.y < cam.height - 10;
        if (inside) poses.emplace_back(rvec, t);
    }
    return poses;
}

} // namespace icacam::host
