#include "host_tools/end_face_renderer.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace icacam::host {

namespace {
double wobbleAt(const EndFaceScene &s, int b, double t)
{
    double w = 1;
    for (int k = 0; k < 3; ++k) w += s.wobble[b][k] * std::cos((k + 2) * t + s.wobblePhase[b][k]);
    return w;
}
double eqFactor(const EndFaceScene &s, int b)
{
    double p = 1;
    for (int k = 0; k < 3; ++k) p += 0.5 * s.wobble[b][k] * s.wobble[b][k];
    return std::sqrt(p);
}
double smoothStep(double x)
{
    return std::clamp(x + 0.5, 0.0, 1.0);
} // 1 px linear ramp
} // namespace

double EndFaceScene::rInnerEqMm() const
{
    return rInnerMm * eqFactor(*this, 0);
}
double EndFaceScene::rOuterEqMm() const
{
    return rOuterMm * eqFactor(*this, 1);
}

double drawnBoundaryMm(const EndFaceScene &s, int b, double theta)
{
    return (b == 0 ? s.rInnerMm : s.rOuterMm) * wobbleAt(s, b, theta) + s.edgeOffsetMm[b];
}

EndFaceScene nominalScene(double uMm)
{
    EndFaceScene s;
    s.rOuterMm = 6.2;
    s.rInnerMm = 6.2 - uMm;
    s.rMaxMm = 5.0 * std::sqrt(2.0) * (1.008 + 0.034 * uMm);
    s.blurSigmaPx = 1.0;
    s.noiseSigma = 2;
    return s;
}

EndFaceScene randomScene(std::mt19937 &rng, double uMm, double rOuterMm, double rMaxMm, bool hard)
{
    auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    EndFaceScene s;
    const bool big = U(0, 1) < 0.5;
    s.width = big ? 2028 : 1456;
    s.height = big ? 1520 : 1088;
    s.mmPerPx = U(0.0118, 0.0215) * (big ? 1.0 : 1.0);
    const double rMaxPx = rMaxMm / s.mmPerPx;
    s.cxPx = U(rMaxPx + 20, std::max(rMaxPx + 21, s.width - rMaxPx - 20));
    s.cyPx = U(rMaxPx + 20, std::max(rMaxPx + 21, s.height - rMaxPx - 20));
    s.rOuterMm = rOuterMm;
    s.rInnerMm = rOuterMm - uMm;
    s.rMaxMm = rMaxMm;
    for (int b = 0; b < 2; ++b)
        for (int k = 0; k < 3; ++k) {
            s.wobble[b][k] = U(0, 0.004) / (k + 1);
            s.wobblePhase[b][k] = U(0, 2 * M_PI);
        }
    const bool darkBg = U(0, 1) < 0.5;
    s.background = darkBg ? U(15, 60) : U(170, 235);
    s.barrel = U(20, 70);
    s.ica = U(110, 200);
    const double contrast = (hard ? U(10, 40) : U(15, 50)) * (U(0, 1) < 0.5 ? -1 : 1);
    s.face = std::clamp(s.ica + contrast, 5.0, 250.0);
    s.fade = U(0, hard ? 0.6 : 0.3);
    s.turningMarks = U(0, 1) < 0.4 ? U(2, 6) : 0;
    s.stains = int(U(0, hard ? 10 : 5));
    s.scratches = int(U(0, 3));
    s.gradient = U(0, 0.25);
    s.vignetting = U(0, 0.25);
    s.highlight = U(0, 1) < 0.5 ? U(10, 40) : 0;
    s.distractor = U(0, 1) < 0.3;
    s.blurSigmaPx = U(0.5, hard ? 1.6 : 1.2);
    s.noiseSigma = U(1, hard ? 5 : 3);
    s.jpegQuality = U(0, 1) < 0.5 ? int(U(80, 95)) : 0;
    s.seed = uint32_t(rng());
    return s;
}

void applyIllumination(cv::Mat &f, double gradient, double vignetting, double angle)
{
    const double diag = std::hypot(f.cols / 2.0, f.rows / 2.0);
    for (int y = 0; y < f.rows; ++y) {
        float *row = f.ptr<float>(y);
        for (int x = 0; x < f.cols; ++x) {
            const double X = x - f.cols / 2.0, Y = y - f.rows / 2.0;
            const double g = 1 + gradient * (X * std::cos(angle) + Y * std::sin(angle)) / diag;
            const double vg = 1 - vignetting * (X * X + Y * Y) / (diag * diag);
            row[x] = float(row[x] * g * vg);
        }
    }
}

cv::Mat renderEndFace(const EndFaceScene &s)
{
    std::mt19937 rng(s.seed);
    auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    cv::Mat f(s.height, s.width, CV_32F);
    const double ri = s.rInnerMm / s.mmPerPx, ro = s.rOuterMm / s.mmPerPx, rm = s.rMaxMm / s.mmPerPx;
    const double fadePhase = U(0, 2 * M_PI), markPeriod = U(2.5, 5.0);
    const double dx0 = s.width * 0.3, dy0 = s.distractor ? s.height * 0.2 : 0;
    const double distractR = rm * U(0.5, 0.9);
    const double gAngle = U(0, 2 * M_PI);
    for (int y = 0; y < s.height; ++y) {
        float *row = f.ptr<float>(y);
        for (int x = 0; x < s.width; ++x) {
            const double X = x - s.cxPx, Y = y - s.cyPx;
            const double r = std::hypot(X, Y), t = std::atan2(Y, X);
            double v = s.background;
            if (s.distractor) {
                const double dr = std::hypot(x - dx0, y - dy0);
                v += 25 * std::exp(-0.5 * std::pow((dr - distractR) / 2.0, 2));
            }
            if (r < rm + 2) {
                const double inBarrel = smoothStep(rm - r);
                double barrel =
                    s.barrel + s.highlight * std::exp(-0.5 * std::pow((r - (0.4 * ro + 0.6 * rm)) / 3.0, 2));
                v = v * (1 - inBarrel) + barrel * inBarrel;
                const double roT = ro * wobbleAt(s, 1, t) + s.edgeOffsetMm[1] / s.mmPerPx;
                const double riT = ri * wobbleAt(s, 0, t) + s.edgeOffsetMm[0] / s.mmPerPx;
                const double inContact = smoothStep(roT - r);
                const double fadeK = 1 - s.fade * 0.5 * (1 + std::cos(t - fadePhase));
                double icaLevel = s.ica + s.turningMarks * std::sin(2 * M_PI * r / markPeriod);
                const double faceLevel = s.ica + (s.face - s.ica) * fadeK;
                const double inFace = smoothStep(riT - r);
                const double top = icaLevel * (1 - inFace) + faceLevel * inFace;
                v = v * (1 - inContact) + top * inContact;
            }
            row[x] = float(v);
        }
    }
    // Stains and lubricant blotches: soft dark or bright spots on the end face.
    // Each spot is blurred in its own neighbourhood (4 σ beyond its rim, where the Gaussian
    // kernel ends): the frame-sized blur it replaces cost most of a large texture's render.
    for (int i = 0; i < s.stains; ++i) {
        const double a = U(0, 2 * M_PI), rr = U(0.2, 1.0) * ro;
        const cv::Point c(int(s.cxPx + rr * std::cos(a)), int(s.cyPx + rr * std::sin(a)));
        const double level = U(-30, 15);
        const int radius = int(U(0.02, 0.08) * ro);
        const double sigma = U(3, 10);
        const int reach = radius + int(std::ceil(4 * sigma)) + 3;
        const cv::Rect box =
            cv::Rect(c.x - reach, c.y - reach, 2 * reach + 1, 2 * reach + 1) & cv::Rect(0, 0, f.cols, f.rows);
        if (box.empty()) continue;
        cv::Mat spot = cv::Mat::zeros(box.size(), CV_32F);
        cv::circle(spot, c - box.tl(), radius, cv::Scalar(level), -1, cv::LINE_AA);
        cv::GaussianBlur(spot, spot, {0, 0}, sigma);
        f(box) += spot;
    }
    for (int i = 0; i < s.scratches; ++i) {
        const double a = U(0, 2 * M_PI), rr = U(0, 0.8) * ro, len = U(0.1, 0.6) * ro, b = U(0, 2 * M_PI);
        const cv::Point p(int(s.cxPx + rr * std::cos(a)), int(s.cyPx + rr * std::sin(a)));
        const cv::Point q(int(p.x + len * std::cos(b)), int(p.y + len * std::sin(b)));
        cv::line(f, p, q, cv::Scalar(U(-40, 40) + 0), 1, cv::LINE_AA);
    }
    applyIllumination(f, s.gradient, s.vignetting, gAngle);
    if (s.blurSigmaPx > 0) cv::GaussianBlur(f, f, {0, 0}, s.blurSigmaPx);
    if (s.noiseSigma > 0) {
        cv::Mat n(f.size(), CV_32F);
        cv::theRNG().state = s.seed;
        cv::randn(n, 0, s.noiseSigma);
        f += n;
    }
    cv::Mat out;
    f.convertTo(out, CV_8U); // rounds and saturates
    return out;
}

std::vector<uint8_t> encodeEndFace(const EndFaceScene &s, const cv::Mat &img)
{
    std::vector<uint8_t> buf;
    if (s.jpegQuality > 0)
        cv::imencode(".jpg", img, buf, {cv::IMWRITE_JPEG_QUALITY, s.jpegQuality});
    else
        cv::imencode(".png", img, buf);
    return buf;
}

} // namespace icacam::host
