#include "vision/segment_bearing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vision/radial_profile.h"

namespace icacam::vision {

namespace {

// The moment needs no fine sampling, only the annulus's breadth: 32 rays of at most 48
// samples each (a few thousand samples; the committed 640 × 480 records' bearings fit
// within 2–4°).
constexpr int kRays = 32;
constexpr int kMaxSamples = 48;
// A moment this small (the share swinging by under 1 % about its mean) is noise, not light.
constexpr double kMinContrast = 0.01;
// The fit holds when every bearing lies this close to it: N segments' bearings are 360/N
// apart, and a bearing further off than a quarter of that is not the segment's own.
constexpr double kMaxResidualOfSpacing = 0.25;

double wrap180(double deg)
{
    deg = std::fmod(deg, 360.0);
    if (deg > 180) deg -= 360;
    if (deg <= -180) deg += 360;
    return deg;
}

double wrap360(double deg)
{
    deg = std::fmod(deg, 360.0);
    return deg < 0 ? deg + 360 : deg;
}

} // namespace

SegmentBearings segmentBearings(const LitInTurn &lit, double cx, double cy, double rFromPx, double rToPx)
{
    SegmentBearings out;
    const int n = lit.count;
    if (n < kMinTiltSegments || n > LitInTurn::kMaxSegments || !(rToPx > rFromPx) || !(rFromPx >= 0)) return out;
    out.count = n;
    const double step = std::max(1.0, (rToPx - rFromPx) / (kMaxSamples - 1));
    const int count = std::min(kMaxSamples, int((rToPx - rFromPx) / step) + 1);
    double mx[LitInTurn::kMaxSegments] = {}, my[LitInTurn::kMaxSegments] = {};
    uint16_t samples[LitInTurn::kMaxSegments][kMaxSamples];
    for (int i = 0; i < kRays; ++i) {
        RaySpec ray{Q16_16::fromDouble(cx),      Q16_16::fromDouble(cy),  {}, {},
                    Q16_16::fromDouble(rFromPx), Q16_16::fromDouble(step)};
        rayDirection(i, kRays, &ray.cosT, &ray.sinT);
        // The part of the ray inside every frame.
        int inside = count;
        for (int k = 0; k < n; ++k) inside = std::min(inside, sampleRay(lit.segment[k], ray, count, samples[k]));
        const double c = ray.cosT.toDouble(), s = ray.sinT.toDouble();
        for (int j = 0; j < inside; ++j) {
            int64_t sum = 0;
            for (int k = 0; k < n; ++k) sum += samples[k][j];
            if (sum <= 0) continue;
            const double toShare = double(n) / double(sum);
            for (int k = 0; k < n; ++k) {
                const double excess = double(samples[k][j]) * toShare - 1;
                mx[k] += excess * c, my[k] += excess * s;
            }
            ++out.samples;
        }
    }
    if (out.samples < kRays * 4) return out; // the annulus lies mostly outside the frame
    bool clear = true;
    for (int k = 0; k < n; ++k) {
        out.bearingDeg[k] = wrap360(std::atan2(my[k], mx[k]) * 180 / std::numbers::pi);
        // The moment of a share swinging as A·cos(θ − φ) is A/2 per sample.
        out.contrast[k] = 2 * std::hypot(mx[k], my[k]) / out.samples;
        clear &= out.contrast[k] >= kMinContrast;
    }
    // Segment 0's azimuth for either way round, as the circular mean of what each bearing
    // says it is; the way whose bearings scatter less about it.
    for (int way : {+1, -1}) {
        double sx = 0, sy = 0;
        for (int k = 0; k < n; ++k) {
            const double a = (out.bearingDeg[k] - way * 360.0 * k / n) * std::numbers::pi / 180;
            sx += std::cos(a), sy += std::sin(a);
        }
        const double phi0 = std::atan2(sy, sx) * 180 / std::numbers::pi;
        double worst = 0;
        for (int k = 0; k < n; ++k)
            worst = std::max(worst, std::fabs(wrap180(out.bearingDeg[k] - way * 360.0 * k / n - phi0)));
        if (out.way == 0 || worst < out.worstDeg) out.way = way, out.worstDeg = worst, out.segment0Deg = wrap360(phi0);
    }
    out.found = clear && out.worstDeg <= kMaxResidualOfSpacing * 360.0 / n;
    return out;
}

double bearingOffsetDeg(const SegmentBearings &b, double segment0Deg)
{
    return std::fabs(wrap180(segment0Deg - b.segment0Deg));
}

} // namespace icacam::vision
