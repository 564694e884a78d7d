// The truth of a record as the camera sees it: where the end face's centre lies, the
// specimen's outline (the body's widest projection, which a close camera sees inside
// R_max × scale), and the grey levels of the zones in the developed photograph.
#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "host_tools/photo/photo_record.h"

namespace icacam::host::photo {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int binOf(const cv::Point2d &d)
{
    double a = std::atan2(d.y, d.x);
    if (a < 0) a += 2 * M_PI;
    return std::min(kTruthBins - 1, int(a / (2 * M_PI) * kTruthBins));
}

// Bins no projected point fell in take their neighbours' value.
void fillGaps(std::vector<double> &bins)
{
    for (int pass = 0; pass < kTruthBins; ++pass) {
        bool any = false;
        for (int i = 0; i < kTruthBins; ++i)
            if (bins[size_t(i)] <= 0) {
                const double a = bins[size_t((i + kTruthBins - 1) % kTruthBins)],
                             b = bins[size_t((i + 1) % kTruthBins)];
                bins[size_t(i)] = std::max(a, b);
                any = true;
            }
        if (!any) return;
    }
}

double median(std::vector<double> v)
{
    if (v.empty()) return kNaN;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + long(mid), v.end());
    return v[mid];
}

double sample(const cv::Mat &grey, const cv::Point2d &p)
{
    const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
    if (x < 0 || y < 0 || x + 1 >= grey.cols || y + 1 >= grey.rows) return kNaN;
    const double fx = p.x - x, fy = p.y - y;
    auto at = [&](int xx, int yy) { return double(grey.at<uint8_t>(yy, xx)); };
    return (1 - fy) * ((1 - fx) * at(x, y) + fx * at(x + 1, y)) +
           fy * ((1 - fx) * at(x, y + 1) + fx * at(x + 1, y + 1));
}

} // namespace

PhotoTruth projectTruth(const PhotoScene &s)
{
    PhotoTruth t;
    const PinholeCamera &c = s.camera;
    const double h = s.faceHeightMm;
    t.centrePx = c.project(s.toScene(0, 0, h));
    t.outerBinPx.assign(kTruthBins, 0);
    t.outlineBinPx.assign(kTruthBins, 0);
    // The outline: the farthest projection, per direction, of the body's rim and of its barrel
    // at every height the FE profile resolves (both halves), densely round the axis.
    const int around = 4 * kTruthBins;
    std::vector<double> heights;
    for (int k = 0; k <= 200; ++k) heights.push_back(h * k / 200.0);
    for (int i = 0; i < around; ++i) {
        const double th = 2 * M_PI * (i + 0.5) / around;
        const cv::Point2d rim = c.project(s.toScene(s.rOuterMm, th, h)) - t.centrePx;
        double &o = t.outerBinPx[size_t(binOf(rim))];
        o = std::max(o, std::hypot(rim.x, rim.y));
        for (double y : heights) {
            const cv::Point2d p = c.project(s.toScene(s.barrelRadiusAt(y), th, y)) - t.centrePx;
            double &b = t.outlineBinPx[size_t(binOf(p))];
            b = std::max(b, std::hypot(p.x, p.y));
        }
    }
    fillGaps(t.outerBinPx);
    // The boundaries' projected areas (shoelace over a dense polygon).
    auto projectedEqRadius = [&](bool inner) {
        double area = 0;
        cv::Point2d prev;
        const int m = 4 * kTruthBins;
        for (int i = 0; i <= m; ++i) {
            const double th = 2 * M_PI * i / m;
            const double r = inner ? s.innerRadiusAt(th) : s.rOuterMm;
            const cv::Point2d p = c.project(s.toScene(r, th, h));
            if (i > 0) area += prev.x * p.y - p.x * prev.y;
            prev = p;
        }
        return std::sqrt(std::fabs(area) / 2 / M_PI);
    };
    t.innerPx = projectedEqRadius(true);
    t.outerPx = projectedEqRadius(false);
    fillGaps(t.outlineBinPx);
    double sum2 = 0;
    for (double r : t.outlineBinPx) sum2 += r * r;
    t.outlinePx = std::sqrt(sum2 / kTruthBins);
    return t;
}

ZoneLevels zoneLevels(const cv::Mat &image, const PhotoScene &s, const PhotoTruth &t, double mmPerPx)
{
    cv::Mat grey;
    if (image.channels() == 3)
        cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    else
        grey = image;
    const PinholeCamera &c = s.camera;
    const double h = s.faceHeightMm;
    std::vector<double> face, ring, barrel, background;
    const double riEq = s.rInnerEqMm(), u = s.rOuterMm - riEq, pxMm = 1 / mmPerPx;
    for (int i = 0; i < 360; ++i) {
        const double th = 2 * M_PI * i / 360;
        const double ri = s.innerRadiusAt(th);
        for (double f = 0.1; f <= 0.85; f += 0.075) face.push_back(sample(grey, c.project(s.toScene(f * ri, th, h))));
        if (u * pxMm >= 4)
            for (double f = 0.3; f <= 0.7; f += 0.1)
                ring.push_back(sample(grey, c.project(s.toScene(ri + f * (s.rOuterMm - ri), th, h))));
    }
    for (int b = 0; b < kTruthBins; ++b) {
        const double a = 2 * M_PI * (b + 0.5) / kTruthBins;
        const cv::Point2d dir(std::cos(a), std::sin(a));
        const double ro = t.outerBinPx[size_t(b)], out = t.outlineBinPx[size_t(b)];
        for (double r = ro + 2; r <= out - 2; r += 1) barrel.push_back(sample(grey, t.centrePx + dir * r));
        for (double r = out + 1.5 * pxMm; r <= out + 2.5 * pxMm; r += 2)
            background.push_back(sample(grey, t.centrePx + dir * r));
    }
    auto clean = [](std::vector<double> &v) {
        v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
    };
    for (auto *v : {&face, &ring, &barrel, &background}) clean(*v);
    return {median(face), median(ring), median(barrel), median(background)};
}

} // namespace icacam::host::photo
