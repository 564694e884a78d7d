#include "firmware/aim_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "firmware/font5x7.h"

namespace icacam::fw {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Bayer 4 × 4 thresholds (0…15): an ordered dither keeps the picture's shading readable in
// one bit and looks the same from picture to picture (no error diffusion crawling).
constexpr int kBayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};

struct Fit {
    int width = 0, height = 0; // picture size on the display
    double scale = 1;          // frame pixels per display pixel
};

Fit fitOf(const vision::LumaView &v)
{
    Fit f;
    f.scale = std::max(double(v.width) / hal::MonoBitmap::kWidth, double(v.height) / hal::MonoBitmap::kHeight);
    f.width = std::min(hal::MonoBitmap::kWidth, int(v.width / f.scale));
    f.height = std::min(hal::MonoBitmap::kHeight, int(v.height / f.scale));
    return f;
}

// Mean of a block of frame pixels (at most 8 × 8 samples of it).
int blockMean(const vision::LumaView &v, int x0, int y0, int x1, int y1)
{
    const int sx = std::max(1, (x1 - x0) / 8), sy = std::max(1, (y1 - y0) / 8);
    long sum = 0, n = 0;
    for (int y = y0; y < y1; y += sy)
        for (int x = x0; x < x1; x += sx) sum += v.at(x, y), ++n;
    return n ? int(sum / n) : 0;
}

void invertCircle(hal::MonoBitmap *bmp, const Fit &f, double cx, double cy, double r)
{
    if (r <= 0) return;
    const double dr = r / f.scale;
    const int steps = std::max(24, int(2 * kPi * dr * 1.5));
    int lastX = -1, lastY = -1;
    for (int i = 0; i < steps; ++i) {
        const double a = 2 * kPi * i / steps;
        const int x = int(std::lround((cx + r * std::cos(a)) / f.scale));
        const int y = int(std::lround((cy + r * std::sin(a)) / f.scale));
        if ((x == lastX && y == lastY) || x < 0 || y < 0 || x >= f.width || y >= f.height) continue;
        bmp->set(x, y, !bmp->get(x, y));
        lastX = x, lastY = y;
    }
}

} // namespace

double focusScore(const vision::LumaView &v, const reading::Reading &m)
{
    int x0 = v.width / 4, x1 = v.width * 3 / 4, y0 = v.height / 4, y1 = v.height * 3 / 4;
    const vision::EndFaceGeometry &g = m.geometry;
    const double r = m.hasValue() ? std::max(g.rMaxPx, g.outer.rEqPx) : 0;
    if (r > 4) {
        x0 = std::max(1, int(g.centreX - r)), x1 = std::min(v.width - 1, int(g.centreX + r));
        y0 = std::max(1, int(g.centreY - r)), y1 = std::min(v.height - 1, int(g.centreY + r));
    }
    x0 = std::max(x0, 1), y0 = std::max(y0, 1);
    x1 = std::min(x1, v.width - 1), y1 = std::min(y1, v.height - 1);
    if (x1 <= x0 || y1 <= y0) return 0;
    const int sx = std::max(1, (x1 - x0) / 160), sy = std::max(1, (y1 - y0) / 160);
    // Gradient magnitudes (grey levels per pixel, Sobel's gain of 8 taken out) in a histogram
    // of whole levels; the score is the mean of the strongest 2 %: the edges' steepness,
    // which a defocus lowers, not the noise or the texture between them.
    constexpr int kBins = 256;
    long count[kBins] = {};
    double sum[kBins] = {};
    long n = 0;
    for (int y = y0; y < y1; y += sy)
        for (int x = x0; x < x1; x += sx) {
            const int gx = (v.at(x + 1, y - 1) + 2 * v.at(x + 1, y) + v.at(x + 1, y + 1)) -
                           (v.at(x - 1, y - 1) + 2 * v.at(x - 1, y) + v.at(x - 1, y + 1));
            const int gy = (v.at(x - 1, y + 1) + 2 * v.at(x, y + 1) + v.at(x + 1, y + 1)) -
                           (v.at(x - 1, y - 1) + 2 * v.at(x, y - 1) + v.at(x + 1, y - 1));
            const double mag = std::sqrt(double(gx) * gx + double(gy) * gy) / 8.0;
            const int bin = std::min(kBins - 1, int(mag));
            ++count[bin];
            sum[bin] += mag;
            ++n;
        }
    if (n == 0) return 0;
    const long want = std::max(1L, n / 50);
    long taken = 0;
    double total = 0;
    for (int b = kBins - 1; b >= 0 && taken < want; --b) {
        const long take = std::min(count[b], want - taken);
        total += count[b] ? sum[b] * double(take) / double(count[b]) : 0;
        taken += take;
    }
    return total / double(taken);
}

AimReading aimReading(const vision::LumaView &v, const reading::Reading &m)
{
    AimReading r;
    r.focus = focusScore(v, m);
    const vision::EndFaceGeometry &g = m.geometry;
    r.found = m.hasValue() || g.outer.rEqPx > 0;
    if (!r.found) {
        r.hint = "no specimen: centre it";
        return r;
    }
    r.centreX = g.centreX, r.centreY = g.centreY;
    r.rOuterPx = g.outer.rEqPx, r.rInnerPx = g.inner.rEqPx, r.rMaxPx = g.rMaxPx;
    r.edgeSigmaPx = g.edgeWidthPx;
    const double dx = g.centreX - 0.5 * (v.width - 1), dy = g.centreY - 0.5 * (v.height - 1);
    const double across = 2 * std::max(g.rMaxPx, g.outer.rEqPx);
    const double tol = 0.08 * std::min(v.width, v.height);
    if (std::fabs(dx) > tol && std::fabs(dx) >= std::fabs(dy))
        r.hint = dx > 0 ? "move left" : "move right";
    else if (std::fabs(dy) > tol)
        r.hint = dy > 0 ? "move up" : "move down";
    else if (across < 0.4 * v.height)
        r.hint = "closer";
    else if (across > 0.95 * v.height || (m.flags & reading::kFlagSpecimenClipped))
        r.hint = "farther";
    else if ((m.flags & reading::kFlagBlurred) || m.error == vision::ErrorCode::Blurred)
        r.hint = "focus";
    else
        r.hint = "ok";
    return r;
}

void drawAim(hal::MonoBitmap *bmp, const vision::LumaView &v, const AimReading &r)
{
    bmp->clear();
    const Fit f = fitOf(v);
    // Stretch between the picture's darkest and brightest blocks.
    int lo = 255, hi = 0;
    for (int y = 0; y < f.height; y += 4)
        for (int x = 0; x < f.width; x += 4) {
            const int m =
                blockMean(v, int(x * f.scale), int(y * f.scale), int((x + 1) * f.scale), int((y + 1) * f.scale));
            lo = std::min(lo, m), hi = std::max(hi, m);
        }
    const int span = std::max(1, hi - lo);
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            const int m =
                blockMean(v, int(x * f.scale), int(y * f.scale), std::max(int((x + 1) * f.scale), int(x * f.scale) + 1),
                          std::max(int((y + 1) * f.scale), int(y * f.scale) + 1));
            const int level = (m - lo) * 16 / span; // 0…16
            bmp->set(x, y, level > kBayer[y & 3][x & 3]);
        }
    if (r.found) {
        invertCircle(bmp, f, r.centreX, r.centreY, r.rOuterPx);
        invertCircle(bmp, f, r.centreX, r.centreY, r.rInnerPx);
    }
    // The words to the right of the picture (at least 7 columns of cells on a 4:3 frame).
    const int col = (f.width + kCellWidth - 1) / kCellWidth;
    char line[32];
    std::snprintf(line, sizeof line, "F%.1f", r.focus);
    drawText(bmp, col, 0, line);
    if (r.found && r.edgeSigmaPx > 0) {
        std::snprintf(line, sizeof line, "e%.1fpx", r.edgeSigmaPx);
        drawText(bmp, col, 1, line);
    }
    // The hint, wrapped into the columns left.
    std::string_view h = r.hint;
    const int width = std::max(1, kColumns - col);
    for (int row = 3; row < kRows && !h.empty(); ++row) {
        size_t take = std::min(h.size(), size_t(width));
        if (take < h.size()) {
            const size_t sp = h.substr(0, take + 1).rfind(' ');
            if (sp != std::string_view::npos && sp > 0) take = sp;
        }
        drawText(bmp, col, row, h.substr(0, take));
        h.remove_prefix(take);
        while (!h.empty() && h.front() == ' ') h.remove_prefix(1);
    }
}

} // namespace icacam::fw
