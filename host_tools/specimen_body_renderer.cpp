#include "host_tools/specimen_body_renderer.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace icacam::host {

double barrelRadiusMm(double rOuterMm, double rMaxMm, double heightMm, double zMm)
{
    const double t = std::clamp(zMm / heightMm, 0.0, 1.0);
    return rOuterMm + (rMaxMm - rOuterMm) * 4 * t * (1 - t);
}

namespace {

constexpr int kGridStep = 8; // the undistortion is computed on this grid and interpolated
constexpr int kSuper = 4;    // rays per pixel side where an edge may cross the pixel
constexpr int kMarchSteps = 96;

// Undistorted normalized coordinates on a grid, interpolated bilinearly: the lens's map is
// smooth (under 0.01 px from the exact inverse for the lenses rendered here).
class RayGrid {
public:
    explicit RayGrid(const CameraModel &cam)
    {
        gw_ = cam.width / kGridStep + 3, gh_ = cam.height / kGridStep + 3;
        std::vector<cv::Point2d> grid;
        grid.reserve(size_t(gw_) * size_t(gh_));
        for (int j = 0; j < gh_; ++j)
            for (int i = 0; i < gw_; ++i) grid.emplace_back(i * kGridStep - kGridStep, j * kGridStep - kGridStep);
        const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
        const std::vector<double> D{cam.k1, cam.k2, cam.p1, cam.p2, cam.k3};
        cv::undistortPoints(grid, und_, K, D, cv::noArray(), cv::noArray(),
                            cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-14));
    }
    cv::Point2d at(double x, double y) const
    {
        const double gx = x / kGridStep + 1, gy = y / kGridStep + 1;
        const int i = std::clamp(int(gx), 0, gw_ - 2), j = std::clamp(int(gy), 0, gh_ - 2);
        const double fx = gx - i, fy = gy - j;
        const size_t k = size_t(j) * size_t(gw_) + size_t(i);
        return (1 - fy) * ((1 - fx) * und_[k] + fx * und_[k + 1]) +
               fy * ((1 - fx) * und_[k + size_t(gw_)] + fx * und_[k + size_t(gw_) + 1]);
    }

private:
    int gw_ = 0, gh_ = 0;
    std::vector<cv::Point2d> und_;
};

class BodyTracer {
public:
    BodyTracer(const CameraModel &cam, const EndFaceScene &scene, double xMm, double yMm, double heightMm)
            : scene_(scene), h_(heightMm)
    {
        cv::Matx33d R;
        cv::Rodrigues(cam.fixtureRvec, R);
        Rt_ = R.t();
        const cv::Vec3d c = -(Rt_ * cam.fixtureTvec);
        up_ = c[2] >= 0 ? 1.0 : -1.0; // the camera's side of the fixture is "up"
        eye_ = {c[0] - xMm, c[1] - yMm, up_ * c[2]};
        bulge_ = scene.rMaxMm - scene.rOuterMm;
        // The widest the body gets (wobble and edge offset included), for the quick tests.
        reach_ = scene.rMaxMm * 1.012 + std::fabs(scene.edgeOffsetMm[1]);
        // The end face's texture: drawn flat, a little finer than the camera sees it, with
        // the ring carried past the contact edge so that only the body's geometry cuts it
        // (the texture's own edge ramp would pull the edge inwards by a fraction of a texel).
        tex_ = scene;
        tex_.mmPerPx = 0.7 * planeScaleAtPoint(cam, xMm, yMm, heightMm);
        half_ = int(std::ceil((scene.rMaxMm + 1.0) / tex_.mmPerPx));
        tex_.width = tex_.height = 2 * half_ + 1;
        tex_.cxPx = tex_.cyPx = half_;
        tex_.blurSigmaPx = 0, tex_.noiseSigma = 0, tex_.jpegQuality = 0;
        tex_.gradient = tex_.vignetting = 0; // applied in the camera's frame
        tex_.distractor = false;
        tex_.edgeOffsetMm[1] = scene.edgeOffsetMm[1] + 4 * tex_.mmPerPx;
        renderEndFace(tex_).convertTo(texture_, CV_32F);
    }

    double texelMm() const { return tex_.mmPerPx; }

    // Where a ray through undistorted normalized (u, v) meets the end face's plane, in the
    // specimen's frame (mm from the axis), and the ray's horizontal drift per mm of descent.
    void topHit(const cv::Point2d &n, cv::Point2d *q, cv::Point2d *drift) const
    {
        const cv::Vec3d a = Rt_ * cv::Vec3d(n.x, n.y, 1);
        const double dz = up_ * a[2]; // negative: the ray descends
        const double lambda = (h_ - eye_[2]) / dz;
        *q = {eye_[0] + lambda * a[0], eye_[1] + lambda * a[1]};
        *drift = {-a[0] / dz, -a[1] / dz};
    }

    // Shortest distance of the ray from the axis between the end face and the fixture.
    double closestApproach(const cv::Point2d &q, const cv::Point2d &g) const
    {
        const double gg = g.dot(g);
        const double s = gg > 0 ? std::clamp(-q.dot(g) / gg, 0.0, h_) : 0.0;
        return std::hypot(q.x + s * g.x, q.y + s * g.y);
    }

    // The grey level the ray sees: the end face inside the contact edge; else the barrel
    // where the ray enters the body through its side; else the fixture.
    double trace(const cv::Point2d &q, const cv::Point2d &g) const
    {
        const double r = std::hypot(q.x, q.y);
        if (r > reach_ && closestApproach(q, g) > reach_) return scene_.background;
        const double theta = std::atan2(q.y, q.x);
        const double edge = drawnBoundaryMm(scene_, 1, theta);
        if (r <= edge) return faceAt(q);
        // The barrel about this ray: its radius follows the contact edge's wobble at the
        // angle where the ray crosses the end face's plane (the ray turns by well under a
        // degree about the axis across the barrel).
        const double bulge = bulge_ * edge / scene_.rOuterMm;
        auto inside = [&](double s) { // s: depth below the end face (mm)
            const double x = q.x + s * g.x, y = q.y + s * g.y;
            const double t = 1 - s / h_;
            const double rho = edge + bulge * 4 * t * (1 - t);
            return x * x + y * y <= rho * rho;
        };
        const double ds = h_ / kMarchSteps;
        double s0 = 0;
        for (int k = 1; k <= kMarchSteps; ++k) {
            double s1 = k * ds;
            if (inside(s1)) {
                for (int it = 0; it < 20; ++it) {
                    const double m = 0.5 * (s0 + s1);
                    (inside(m) ? s1 : s0) = m;
                }
                return barrelAt(q + s1 * g, h_ - s1, bulge);
            }
            s0 = s1;
        }
        return scene_.background;
    }

    // The end face's texture at a point of its plane (bilinear).
    double faceAt(const cv::Point2d &q) const
    {
        const double x = half_ + q.x / tex_.mmPerPx, y = half_ + q.y / tex_.mmPerPx;
        const int i = int(std::floor(x)), j = int(std::floor(y));
        if (i < 0 || j < 0 || i + 1 >= texture_.cols || j + 1 >= texture_.rows) return scene_.background;
        const double fx = x - i, fy = y - j;
        const float *r0 = texture_.ptr<float>(j), *r1 = texture_.ptr<float>(j + 1);
        return (1 - fy) * ((1 - fx) * r0[i] + fx * r0[i + 1]) + fy * ((1 - fx) * r1[i] + fx * r1[i + 1]);
    }

    // The barrel at the point p (horizontal, mm from the axis) and height z. Lambertian under
    // the ring light around the lens: lit along the line of sight, so the brightness is the
    // cosine between the surface normal and the direction to the lens. The scene's barrel
    // grey is what the barrel shows where that cosine is 0.5 (the upper barrel seen from
    // straight above); a specular band where the normal points almost at the lens.
    double barrelAt(const cv::Point2d &p, double z, double bulge) const
    {
        const double r = std::hypot(p.x, p.y);
        const double t = z / h_;
        const double slope = bulge * 4 * (1 - 2 * t) / h_; // dρ/dz
        cv::Vec3d n(p.x / r, p.y / r, -slope);
        n /= cv::norm(n);
        cv::Vec3d l(eye_[0] - p.x, eye_[1] - p.y, eye_[2] - z);
        l /= cv::norm(l);
        const double c = std::max(0.0, n.dot(l));
        return scene_.barrel * (0.25 + 1.5 * c) + scene_.highlight * std::exp(-0.5 * std::pow((c - 0.75) / 0.06, 2));
    }

private:
    EndFaceScene scene_, tex_;
    double h_ = 0, up_ = 1, bulge_ = 0, reach_ = 0;
    cv::Matx33d Rt_;
    cv::Vec3d eye_;
    int half_ = 0;
    cv::Mat texture_;
};

} // namespace

cv::Mat renderSpecimenBody(const CameraModel &cam, const EndFaceScene &scene, double xMm, double yMm, double heightMm)
{
    const RayGrid rays(cam);
    const BodyTracer body(cam, scene, xMm, yMm, heightMm);
    // A pixel whose centre ray lands this far inside the contact edge, or passes the body
    // this far outside, cannot hold an edge: one ray is enough there (one pixel spans well
    // under 3 texels at 0.7 texel per pixel).
    const double guard = 4 * body.texelMm() / 0.7;
    const double insideAll = scene.rOuterMm * 0.985 - std::fabs(scene.edgeOffsetMm[1]) - guard;
    const double outsideAll = scene.rMaxMm * 1.012 + std::fabs(scene.edgeOffsetMm[1]) + guard;
    cv::Mat f(cam.height, cam.width, CV_32F);
    for (int y = 0; y < cam.height; ++y) {
        float *row = f.ptr<float>(y);
        for (int x = 0; x < cam.width; ++x) {
            cv::Point2d q, g;
            body.topHit(rays.at(x, y), &q, &g);
            const double r = std::hypot(q.x, q.y);
            if (r < insideAll) {
                row[x] = float(body.faceAt(q));
                continue;
            }
            if (r > outsideAll && body.closestApproach(q, g) > outsideAll) {
                row[x] = float(scene.background);
                continue;
            }
            double sum = 0;
            for (int j = 0; j < kSuper; ++j)
                for (int i = 0; i < kSuper; ++i) {
                    body.topHit(rays.at(x + (i + 0.5) / kSuper - 0.5, y + (j + 0.5) / kSuper - 0.5), &q, &g);
                    sum += body.trace(q, g);
                }
            row[x] = float(sum / (kSuper * kSuper));
        }
    }
    std::mt19937 rng(scene.seed ^ 0x5bd1e995u);
    applyIllumination(f, scene.gradient, scene.vignetting, std::uniform_real_distribution<double>(0, 2 * M_PI)(rng));
    if (scene.blurSigmaPx > 0) cv::GaussianBlur(f, f, {0, 0}, scene.blurSigmaPx);
    if (scene.noiseSigma > 0) {
        cv::Mat n(f.size(), CV_32F);
        cv::RNG noise(scene.seed);
        noise.fill(n, cv::RNG::NORMAL, 0, scene.noiseSigma);
        f += n;
    }
    cv::Mat out;
    f.convertTo(out, CV_8U);
    return out;
}

} // namespace icacam::host
