#include "vision/contact_tilt.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "vision/contact_knee.h"
#include "vision/radial_profile.h"

namespace icacam::vision {

namespace {

// Every fourth fine ray: 64 rays average the turning marks' ripple and the sensor's noise
// well below a barrel's step (rendered photographs: ripple ±0.005 against a step of 0.1–0.2).
constexpr int kTiltRays = 64;
constexpr double kStepPx = 0.5;
constexpr int kMaxSamples = 160;
// The rise is judged over 2 px (the blur's reach either side), the levels either side of it
// from 2 px to 6 px beyond that: longer than a turning mark's period (3–5 px on 1456 × 1088
// photographs), whose tilt ripples T by ±0.02.
constexpr int kRiseHalf = int(1.0 / kStepPx);
constexpr int kLevelFrom = int(2.0 / kStepPx), kLevelTo = int(6.0 / kStepPx);
// T is in Q16 (1.0 = 65536). A step under 0.02 is no barrel's: a flat face's T drifts by
// less over the search, and the barrel's first degrees step it by 0.05 and more.
constexpr int32_t kMinRiseQ16 = 1311;
// A rise counts as the innermost edge at half the strongest.
constexpr int kInnermostDivisor = 2;
// How far inside the rise's steepest point the knee may lie: a barrel curving away from the
// edge grows its tilt over a few pixels (640 × 480 photographs: the steepest point 4–5 px out).
constexpr double kKneeSearchPx = 6.0;
// T is smoothed over ±2 px where the ring shows no period of its own; bilinear sampling adds
// its own blur (px²).
constexpr int kSmoothHalf = int(2.0 / kStepPx);
constexpr double kBilinearBlurSq = 0.17;
// The turning marks' periods looked for, and how far inside the single frame's contact edge
// the flat ring's samples end (its blur and a ramp's first pixels).
constexpr double kMinPeriodPx = 2.0, kMaxPeriodPx = 10.0, kFlatMarginPx = 4.0;

int32_t levelOf(const int32_t *t, int from, int to)
{
    int64_t s = 0;
    for (int j = from; j <= to; ++j) s += t[j];
    return int32_t(s / (to - from + 1));
}

// Half the width (samples) of the box that smooths T over the turning marks' period: the lag
// of least mean absolute difference over t[0 … flat), from 2 to 10 px, where the flat ring
// shows two periods at least, the lag's difference is under two thirds of half the lag's and
// half the lag's three times the neighbouring samples' (a ripple, not noise); else the
// default box.
int smoothingHalfWidth(const int32_t *t, int flat)
{
    auto amdf = [&](int l) {
        int64_t d = 0;
        for (int k = 0; k + l < flat; ++k) d += std::abs(t[k + l] - t[k]);
        return double(d) / (flat - l);
    };
    if (flat < 2) return kSmoothHalf;
    const double neighbours = amdf(1);
    int best = 0;
    double bestDiff = 0;
    for (int lag = int(kMinPeriodPx / kStepPx); lag <= int(kMaxPeriodPx / kStepPx) && 2 * lag <= flat; ++lag) {
        const double d = amdf(lag), half = amdf(lag / 2);
        if (d < half * 2 / 3 && half >= 3 * neighbours && (best == 0 || d < bestDiff)) best = lag, bestDiff = d;
    }
    return best ? std::max(kSmoothHalf, best / 2) : kSmoothHalf;
}

} // namespace

TiltEdge contactEdgeByTilt(const LitInTurn &lit, const BoundaryFit &outer, double cx, double cy, double innerPx,
                           double outerPx, double blurPx)
{
    TiltEdge out;
    const int segments = lit.count;
    if (segments < kMinTiltSegments || segments > LitInTurn::kMaxSegments) return out;
    const int count = std::min(kMaxSamples, int((innerPx + outerPx) / kStepPx) + 1);
    if (count < 2 * kLevelTo + 4) return out;
    // Each segment's direction in Q14, once per call.
    int32_t segCos[LitInTurn::kMaxSegments], segSin[LitInTurn::kMaxSegments];
    for (int k = 0; k < segments; ++k) {
        const double phi = (lit.azimuth0Deg + 360.0 * k / segments) * std::numbers::pi / 180;
        segCos[k] = int32_t(std::lround(16384 * std::cos(phi)));
        segSin[k] = int32_t(std::lround(16384 * std::sin(phi)));
    }
    int64_t sum[kMaxSamples] = {};
    int32_t seen[kMaxSamples] = {};
    uint16_t samples[LitInTurn::kMaxSegments][kMaxSamples];
    for (int i = 0; i < kTiltRays; ++i) {
        RaySpec ray{Q16_16::fromDouble(cx), Q16_16::fromDouble(cy), {}, {}, {}, Q16_16::fromDouble(kStepPx)};
        rayDirection(i, kTiltRays, &ray.cosT, &ray.sinT);
        const double c = ray.cosT.toDouble(), s = ray.sinT.toDouble();
        ray.r0 = Q16_16::fromDouble(outer.radiusAt(c, s) - innerPx);
        bool inside = true;
        for (int k = 0; k < segments && inside; ++k)
            inside = sampleRay(lit.segment[k], ray, count, samples[k]) == count;
        if (!inside) continue;
        // The weight of segment k on this ray: cos(θ − φ_k) in Q14.
        int32_t w[LitInTurn::kMaxSegments];
        for (int k = 0; k < segments; ++k)
            w[k] = int32_t((int64_t(ray.cosT.raw()) * segCos[k] + int64_t(ray.sinT.raw()) * segSin[k]) >> 14);
        for (int j = 0; j < count; ++j) {
            int64_t num = 0, den = 0;
            for (int k = 0; k < segments; ++k) num += int64_t(w[k]) * samples[k][j], den += samples[k][j];
            if (den <= 0) continue;
            sum[j] += (num << 2) / den; // Q14 · Q8 / Q8 → Q16
            ++seen[j];
        }
        ++out.rays;
    }
    if (out.rays < kTiltRays / 2) return out;
    int32_t mean[kMaxSamples];
    for (int j = 0; j < count; ++j) {
        if (seen[j] < out.rays / 2) return out; // a ray's sample lost in the division's zero
        mean[j] = int32_t(sum[j] / seen[j]);
    }
    // Turning marks ripple T with their own period (a few pixels, as the feed was): T is
    // smoothed over one period, as the flat ring inside the single frame's edge shows it (the
    // lag of least mean difference), and the knee's model blurred as much.
    const int half = smoothingHalfWidth(mean, std::max(0, int((innerPx - kFlatMarginPx) / kStepPx)));
    int32_t level[kMaxSamples];
    for (int k = 0; k < count; ++k) {
        const int a = std::max(0, k - half), b = std::min(count - 1, k + half);
        int64_t box = 0;
        for (int q = a; q <= b; ++q) box += mean[q];
        level[k] = int32_t(box / (b - a + 1));
    }
    const double boxPx = (2 * half + 1) * kStepPx;

    // The rise over 2 px at each sample, where the levels either side fit in the window.
    const int lo = kLevelTo + half, hi = count - 1 - kLevelTo;
    int32_t rise[kMaxSamples] = {};
    int32_t strongest = 0;
    for (int j = lo; j <= hi; ++j) {
        rise[j] = level[j + kRiseHalf] - level[j - kRiseHalf];
        strongest = std::max(strongest, rise[j]);
    }
    if (strongest < kMinRiseQ16) return out;
    int32_t fitted[kMaxSamples];
    for (int k = 0; k < count; ++k) fitted[k] = level[k] + 2 * 65536; // positive: 0 marks off-frame
    // The innermost local maximum of the rise at half the strongest or more, whose levels
    // either side differ by as much: a step that holds.
    for (int j = lo; j <= hi; ++j) {
        if (rise[j] * kInnermostDivisor < strongest) continue;
        if (j > lo && rise[j - 1] > rise[j]) continue;
        if (j < hi && rise[j + 1] > rise[j]) continue;
        const int32_t inside = levelOf(level, j - kLevelTo, j - kLevelFrom);
        const int32_t beyond = levelOf(level, j + kLevelFrom, j + kLevelTo);
        const int32_t step = beyond - inside;
        if (step * kInnermostDivisor < strongest) continue;
        // The rise is the barrel's tilt growing from the edge on, abruptly where the free
        // surface leaves the platen at an angle, over a few pixels where it curves away: the
        // edge is the knee where T leaves the flat face's level (a level, a step and a slope
        // beyond, blurred), searched inside the steepest point of the rise, short of the
        // window's start.
        ContactKneeWindow w;
        w.samplePx = kStepPx;
        w.blurPx = std::sqrt(blurPx * blurPx + kBilinearBlurSq + boxPx * boxPx / 12);
        w.outsideSamples = kLevelFrom;
        w.searchOutPx = 1.0;
        w.stepAlone = true;
        w.insideSamples = std::min(j - half, int((kKneeSearchPx + 3 * w.blurPx + 1) / kStepPx));
        w.searchInPx = std::min((w.insideSamples - 1) * kStepPx, kKneeSearchPx);
        if (w.insideSamples < kLevelFrom) continue;
        const ContactKnee knee = locateContactKnee(fitted, count, j, +1, w);
        // Outward tilt only raises T: a knee stepping down by a quarter of the rise into a
        // ramp is a mark's dip beside the edge, not where the barrel begins.
        if (!knee.found || knee.stepLevel * 4 < -step) continue;
        const double at = j + knee.offsetPx / kStepPx;
        // The smoothed profile's noise from its second differences inside the step (what the
        // box left of the marks, and the sensor's), over the rise's slope per pixel.
        int64_t dev = 0;
        int n = 0;
        for (int k = std::max(1, j - 3 * kLevelTo); k < j - kLevelFrom; ++k, ++n)
            dev += std::abs(level[k + 1] - 2 * level[k] + level[k - 1]);
        const double noise = n ? 1.25 * double(dev) / n / std::sqrt(6.0) : 0;
        const double slopePerPx = double(step) / (2 * kLevelFrom * kStepPx);
        out.found = true;
        out.shiftPx = at * kStepPx - innerPx;
        out.sigmaPx = std::hypot(0.15, slopePerPx > 0 ? noise / slopePerPx : 1.0);
        out.rise = step / 65536.0;
        out.misfit = knee.residual / step;
        return out;
    }
    return out;
}

} // namespace icacam::vision
