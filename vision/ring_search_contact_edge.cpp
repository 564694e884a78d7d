// The contact edge's profile aligned on its per-ray fit: the step's width against the original
// face's, and where the ring's level ends on a ramp or beside a lit shoulder (the knee).
#include "vision/ring_search.h"

#include <algorithm>
#include <cmath>

#include "vision/boundary_fit.h"
#include "vision/contact_knee.h"
#include "vision/edge_profile.h"
#include "vision/radial_profile.h"
#include "vision/ring_search_detail.h"

namespace icacam::vision {

using namespace ring_search_detail;

namespace {
// How many rays the edge-following mean profile samples (it only names the face edge; the
// fine rays locate it).
constexpr int kAlignRays = kFineRays / 8;
// How far beyond the derivative's peak the knee's fit reads the profile (pixels): the fall up
// to its steepest point and a little past it, where a straight fall still holds (over the
// bench's ten 640 × 480 sets, 156 right readings at 3 px; 153 at 2 px, 142 at 5 px, where
// the fall bends towards the barrel's own shading).
constexpr int kKneeOutsidePx = 3;
// Beside a lit shoulder (a contact edge rising onto a band that falls again) the fit reads
// the profile this far inside the derivative's peak (pixels, at most half the ring) and
// searches the step this far either side of it; the shoulder's fall over kKneeOutsidePx
// must be at least kShoulderFall of the step, the zones' ripple share (kRippleShareOfStep).
// On the bench's dark_ring photographs the peak lies 0.4–0.75 px inside the edge, the fall
// 0.24–0.45 of the step (at 0.3, three rings whose shoulder falls by 0.24–0.27 read 0.7–0.75 px
// inside, μ 0.010–0.014 low, ok); no drawn ring, development-set or reference photograph
// rising onto its barrel shows such a fall (they read as the derivative locates them, at
// 0.15 as at 0.3).
constexpr double kShoulderInsidePx = 6.0, kShoulderSearchPx = 1.5, kShoulderFall = 0.15;
// The bench's shoulders fit with an RMS residual of 0.2–1.2 % of their step; a tilted view
// whose ring varies by ±7 grey levels inside the edge, 2.6 %.
constexpr double kShoulderResidual = 0.02;
// Bilinear sampling's own blur on a profile's levels (px²; stepWidth removes it with the
// derivative kernel's).
constexpr double kBilinearBlurSq = 0.17;
// A contact edge wider than the original face's by more than this is taken where the ring's
// level ends, not at the derivative's peak. The bench's bright rings, whose lit barrel rolls
// away from the ring over a pixel or two, measure 0.9–1.6 px and peak 0.4–3.3 px outside the
// edge; a narrow ring's barrel falling away over several pixels measures less, because the
// width is taken within half the ring (straight-s3 0001: a 9 px ring, a fall over 8 px,
// 0.7 px, the peak 2.5 px outside). A drawn step measures 0–0.97 px: at the knee the few
// over this (9 of 240 frames of seeds 101 and 102) read within 0.0013 of μ at the peak.
// (The reading's finding and the ramp's share of u's error begin a little above
// kContactRampPx, reading/interpretation_steps.cpp.)
constexpr double kKneeRampPx = 0.5;
} // namespace

bool RingSearch::alignedProfile(const double *outerR, AlignedProfile *p, bool onInner, int halfSpan, int sector) const
{
    const int first = sector < 0 ? 0 : sector * (rays_ / kRampSectors);
    const int end = sector < 0 ? rays_ : first + rays_ / kRampSectors;
    const int stride = sector < 0 ? rays_ / kAlignRays : 1;
    const int rays = (end - first) / stride; // both divide: rays_ is a power of two of 64 or more
    p->K = halfSpan > 0 ? halfSpan : int(kWidestRingOfR0 * r0 + 2);
    if (halfSpan > 0) p->M = halfSpan;
    if (p->count() > AlignedProfile::kSpan) return false;
    const int K = p->K, count = p->count();
    uint32_t sum[AlignedProfile::kSpan], n[AlignedProfile::kSpan];
    std::fill_n(sum, count, 0u);
    std::fill_n(n, count, 0u);
    uint16_t row[AlignedProfile::kSpan];
    uint32_t whole = 0;
    const Q16_16 qx = Q16_16::fromDouble(cx), qy = Q16_16::fromDouble(cy);
    for (int i = first; i < end; i += stride) {
        if (!(onInner ? innerPts[i] : outerPts[i]).valid) continue;
        const double ro = outerR[i];
        RaySpec ray{qx, qy, rayCosQ_[i], raySinQ_[i], Q16_16::fromDouble(ro - K), Q16_16::fromInt(1)};
        addRaySamples(row, count, sampleRay(*frame, ray, count, row) == count, sum, n, &whole);
    }
    for (int k = 0; k < count; ++k) n[k] += whole;
    uint16_t mean[AlignedProfile::kSpan] = {}; // count ≤ kSpan are set; zeroed for GCC's flow analysis at -O0
    for (int k = 0; k < count; ++k) {
        mean[k] = n[k] * 2 >= uint32_t(rays) ? uint16_t(sum[k] / n[k]) : kOutsideFrame;
        p->level[k] = mean[k] == kOutsideFrame ? 0 : mean[k];
    }
    // Same units as the fine derivative rows (the [1 2 1] angular weights sum to 4).
    profileDerivative(mean, count, p->deriv);
    for (int k = 0; k < count; ++k) p->deriv[k] = (p->deriv[k] * 4) >> 6;
    return true;
}

double RingSearch::contactEdgeWidth(const AlignedProfile &p, int signOuter) const
{
    return stepWidth(p, signOuter, 6);
}

double RingSearch::stepWidth(const AlignedProfile &p, int sign, double reachPx) const
{
    // The second moment of the derivative peak (the kernel adds 0.75 px² and bilinear
    // sampling about 0.17 px²).
    double s0 = 0, s1 = 0, s2 = 0;
    const int w = std::min(p.K, int(reachPx / kFineStepPx) + 1);
    for (int k = -w; k <= std::min(w, p.M); ++k) {
        const double val = std::max(0, sign * p.deriv[k + p.K]);
        s0 += val;
        s1 += val * k * kFineStepPx;
        s2 += val * k * k * kFineStepPx * kFineStepPx;
    }
    if (!(s0 > 0)) return -1;
    const double var = s2 / s0 - (s1 / s0) * (s1 / s0) - kLocatorBlurSq;
    return std::sqrt(std::max(0.0, var));
}

bool RingSearch::kneeOffset(const AlignedProfile &p, int signOuter, double blurPx, double rampPx, double ringPx,
                            bool onRamp, double *offsetPx) const
{
    ContactKneeWindow w;
    w.outsideSamples = int(kKneeOutsidePx / kFineStepPx);
    w.blurPx = std::sqrt(blurPx * blurPx + kBilinearBlurSq);
    w.samplePx = kFineStepPx;
    int fallSign = signOuter;
    if (onRamp) {
        // The knee lies inside the derivative's peak by up to about the ramp's width: twice it
        // (twice kContactRampPx at least) is searched, and the profile read that far in and
        // the blur's reach beyond, for the ring's level, but not past half the ring (the
        // original face's edge); the search stays short of the window's first sample (a knee
        // there has no level to end).
        const double searchPx = 2 * std::max(rampPx, kContactRampPx);
        w.insideSamples = int(std::min(0.5 * ringPx, searchPx + 3 * blurPx + 1) / kFineStepPx);
        w.searchInPx = std::min((w.insideSamples - 1) * kFineStepPx, searchPx);
    } else if (signOuter > 0) {
        // A contact edge rising onto a lit shoulder: the shoulder falls again just beyond, and
        // its fall, blurred into the step, moves the derivative's peak inside the edge. The
        // step and the fall beyond it are fitted alike, the fall going the other way.
        w.insideSamples = int(std::min(0.5 * ringPx, kShoulderInsidePx) / kFineStepPx);
        w.searchInPx = w.searchOutPx = kShoulderSearchPx;
        fallSign = -signOuter;
    } else {
        return false;
    }
    const ContactKnee knee = locateContactKnee(p.level, p.count(), p.K, fallSign, w);
    if (!knee.found) return false;
    // A shoulder that falls by less than kShoulderFall of the step within the window is no
    // shoulder, and a ring that is no level inside the step (the fit's residual beyond
    // kShoulderResidual of the step) not the model fitted: the step stands as the derivative
    // located it.
    if (fallSign != signOuter && !(std::fabs(knee.slope) * kKneeOutsidePx > kShoulderFall * std::fabs(knee.stepLevel) &&
                                   knee.residual < kShoulderResidual * std::fabs(knee.stepLevel)))
        return false;
    *offsetPx = knee.offsetPx;
    return true;
}

bool RingSearch::contactEdgeAtKnee(const AlignedProfile &p, int signOuter, double blurPx, double rampPx, double ringPx,
                                   BoundaryFit *outer)
{
    double offset = 0;
    if (!kneeOffset(p, signOuter, blurPx, rampPx, ringPx, rampPx > kKneeRampPx, &offset)) return false;
    shiftBoundary(offset, outer, outerPts);
    return true;
}

double RingSearch::contactEdgeAtKneeBySector(const double *outerR, int signOuter, double blurPx, double reachPx,
                                             double ringPx, BoundaryFit *outer, bool *moved)
{
    // Seen obliquely, the barrel's shoulder (the rounded corner between the end face and the
    // barrel, a few pixels wide) spreads out on the side facing the camera and shows edge-on
    // on the far side. Where it spreads, its shading falls off gradually beyond the contact
    // edge and the derivative peaks outside the edge; where it shows edge-on, a thin dark
    // line between the ring and a lighter background, the peak lies on the edge. The bench's
    // tilted-s1 record 6 (12.5°), against its projected contact edge: 1.7–3.3 px outside on
    // the side facing the camera, 0.3–0.5 px on the far side; the arcs' ramps 2.4–2.6 px
    // there and 0 here, the whole ring's 1.0, under kContactRampPx, so that neither the knee
    // nor the reading's finding would see it. Each arc of the ring is judged on its own.
    const int span = rays_ / kRampSectors;
    double offset[kRampSectors] = {}, widest = 0;
    *moved = false;
    for (int s = 0; s < kRampSectors; ++s) {
        AlignedProfile p;
        if (!alignedProfile(outerR, &p, false, 0, s)) continue;
        const double wo = stepWidth(p, signOuter, reachPx);
        if (wo < 0) continue;
        const double ramp = std::sqrt(std::max(0.0, wo * wo - blurPx * blurPx));
        widest = std::max(widest, ramp);
        // A sector's few rays measure its ramp too noisily to decide on it: every sector whose
        // contact edge falls is followed to where its level ends. Where the shoulder is seen
        // edge-on the level ends at the step itself, and the fit finds the knee there or none.
        if (kneeOffset(p, signOuter, blurPx, ramp, ringPx, ramp > kContactRampPx || signOuter < 0, &offset[s]))
            *moved = true;
    }
    if (!*moved) return widest;
    // Between the sectors' middles the offset follows the ring linearly.
    double radius[kRays];
    bool valid[kRays];
    for (int i = 0; i < rays_; ++i) {
        const double at = (i + 0.5) / span - 0.5; // in sectors from sector 0's middle
        const int s0 = int(std::floor(at));
        const double f = at - s0;
        const double o = (1 - f) * offset[(s0 + kRampSectors) % kRampSectors] + f * offset[(s0 + 1) % kRampSectors];
        radius[i] = outerPts[i].radius.toDouble() + o;
        valid[i] = outerPts[i].valid;
        outerPts[i].radius = Q16_16::fromDouble(radius[i]);
        outerPts[i].x = Q16_16::fromDouble(cx + radius[i] * rayCos_[i]);
        outerPts[i].y = Q16_16::fromDouble(cy + radius[i] * raySin_[i]);
    }
    BoundaryFit fit;
    if (fitBoundary(radius, valid, rays_, cx, cy, FitOptions{}, &fit)) {
        // The first fit's σ may hold a low coverage's share (locateOnRays), which a fit
        // through the same points moved does not see again.
        fit.rEqSigmaPx = std::max(fit.rEqSigmaPx, outer->rEqSigmaPx);
        *outer = fit;
    }
    return widest;
}

} // namespace icacam::vision
