#include "host_tools/loop/loop_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace icacam::host::loop {

namespace {
cv::Scalar bgr(unsigned rgb)
{
    return {double(rgb & 0xff), double((rgb >> 8) & 0xff), double((rgb >> 16) & 0xff)};
}
std::string fmt(double v)
{
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", v);
    return b;
}
} // namespace

bool scatterPlot(const std::string &path, const std::string &title, const std::string &xLabel,
                 const std::string &yLabel, const std::vector<Series> &series, const std::vector<std::string> &xTicks,
                 bool identity)
{
    const int W = 900, H = 640, L = 110, R = 30, T = 50, B = 80;
    cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Series &s : series)
        for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            x0 = std::min(x0, s.x[i]);
            x1 = std::max(x1, s.x[i]);
            y0 = std::min(y0, s.y[i]);
            y1 = std::max(y1, s.y[i]);
        }
    if (x0 > x1) {
        x0 = 0;
        x1 = 1;
        y0 = 0;
        y1 = 1;
    }
    if (identity) {
        x0 = y0 = std::min(x0, y0);
        x1 = y1 = std::max(x1, y1);
    }
    if (!xTicks.empty()) {
        x0 = -0.5;
        x1 = double(xTicks.size()) - 0.5;
    }
    if (x1 - x0 < 1e-12) {
        x0 -= 0.5;
        x1 += 0.5;
    }
    if (y1 - y0 < 1e-12) {
        y0 -= 0.5;
        y1 += 0.5;
    }
    const double px = 0.05 * (x1 - x0) * (xTicks.empty() ? 1 : 0), py = 0.05 * (y1 - y0);
    x0 -= px;
    x1 += px;
    y0 -= py;
    y1 += py;
    auto X = [&](double x) { return int(std::lround(L + (x - x0) / (x1 - x0) * (W - L - R))); };
    auto Y = [&](double y) { return int(std::lround(H - B - (y - y0) / (y1 - y0) * (H - T - B))); };
    const cv::Scalar black(0, 0, 0), grey(210, 210, 210);
    for (int i = 0; i <= 5; ++i) {
        const double yv = y0 + (y1 - y0) * i / 5;
        cv::line(img, {L, Y(yv)}, {W - R, Y(yv)}, grey, 1);
        cv::putText(img, fmt(yv), {5, Y(yv) + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1, cv::LINE_AA);
    }
    if (xTicks.empty()) {
        for (int i = 0; i <= 5; ++i) {
            const double xv = x0 + (x1 - x0) * i / 5;
            cv::line(img, {X(xv), T}, {X(xv), H - B}, grey, 1);
            cv::putText(img, fmt(xv), {X(xv) - 20, H - B + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1, cv::LINE_AA);
        }
    } else {
        for (size_t i = 0; i < xTicks.size(); ++i)
            cv::putText(img, xTicks[i], {X(double(i)) - 10, H - B + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1,
                        cv::LINE_AA);
    }
    if (y0 < 0 && y1 > 0) cv::line(img, {L, Y(0)}, {W - R, Y(0)}, {120, 120, 120}, 1);
    if (identity) cv::line(img, {X(x0), Y(x0)}, {X(x1), Y(x1)}, {120, 120, 120}, 1, cv::LINE_AA);
    cv::rectangle(img, {L, T}, {W - R, H - B}, black, 1);
    cv::putText(img, title, {L, 30}, cv::FONT_HERSHEY_SIMPLEX, 0.65, black, 1, cv::LINE_AA);
    cv::putText(img, xLabel, {W / 2 - 80, H - 25}, cv::FONT_HERSHEY_SIMPLEX, 0.55, black, 1, cv::LINE_AA);
    cv::putText(img, yLabel, {5, 14}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1, cv::LINE_AA);
    int legendY = T + 20;
    for (const Series &s : series) {
        const cv::Scalar c = bgr(s.colour);
        if (s.line) {
            std::vector<std::pair<double, double>> p;
            for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
                if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) p.emplace_back(s.x[i], s.y[i]);
            std::sort(p.begin(), p.end());
            for (size_t i = 1; i < p.size(); ++i)
                cv::line(img, {X(p[i - 1].first), Y(p[i - 1].second)}, {X(p[i].first), Y(p[i].second)}, c, 2,
                         cv::LINE_AA);
        } else {
            for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
                if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
                    cv::circle(img, {X(s.x[i]), Y(s.y[i])}, 4, c, -1, cv::LINE_AA);
        }
        if (!s.label.empty()) {
            cv::circle(img, {L + 15, legendY - 5}, 5, c, -1, cv::LINE_AA);
            cv::putText(img, s.label, {L + 27, legendY}, cv::FONT_HERSHEY_SIMPLEX, 0.5, black, 1, cv::LINE_AA);
            legendY += 20;
        }
    }
    return cv::imwrite(path, img);
}

} // namespace icacam::host::loop
