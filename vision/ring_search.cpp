#include "vision/ring_search.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vision/angle_table.h"
#include "vision/boundary_fit.h"
#include "vision/edge_profile.h"
#include "vision/profile_zones.h"
#include "vision/radial_profile.h"
#include "vision/ray_capacity.h"
#include "vision/ring_search_detail.h"

namespace icacam::vision {

using namespace ring_search_detail;

namespace {
// Ring width (px) below which the per-ray search's edges are biased by each other's blur
// (0.4–2 px wide on rendered 2–5 px rings, tests/vision/synth_accuracy_test.cpp).
constexpr double kNarrowRingPx = 6.0;
// The widest ring a step back beyond the drop is read as, its contact edge undecided (pixels).
constexpr double kUndecidedBackPx = 1.5 * kNarrowRingPx;
// Grey levels between the two sides of the original face's edge below which the rays' edge
// is not taken (low_contrast warns below 5; no rendered or photographed face shows under 6).
constexpr double kMinInnerContrast = 2.0;
// Arc between neighbouring fine rays (pixels, at the initial radius) below which more rays
// add little: each ray's derivative is the [1 2 1] sum of it and its neighbours, and with
// the edge's blur and the bilinear footprint, rays closer than this read mostly the same
// pixels. The ray count halves (down to kCoarseRays) until the arc is at least this.
constexpr double kMinRayArcPx = 5.0;
// How far inside the named drop (pixels) the centring must have moved before the drop
// itself is tried again as the contact edge: more than the coarse step's reach.
constexpr double kInwardMovePx = 4.0;
// The contact edge's blur (Gaussian σ, pixels) taken where the profile shows none.
constexpr double kUnknownBlurPx = 1.5;
// Below this fraction of rays a boundary's fit counts as low coverage (the reading flags
// low_coverage at the same fraction).
constexpr double kLowCoverage = 0.6;

// Box step detector: mean of the w samples outside minus the w samples inside sample j,
// for rows of 4×Q8 sums (angular [1 2 1]); out in 1/32 grey level. Ridges (turning marks,
// scratch lines) average out over a box wider than their period; a level change does not.
void boxStep(const int32_t *t, int count, int w, bool allInside, int16_t *d)
{
    // 4·256/32: out in 1/32 grey. |out − in| ≤ w · 4 · 65280, so the step stays within
    // ±8160 and fits int16 as it is.
    const int32_t scale = w * 32;
    if (allInside) {
        // Every t[j] is usable: slide the two boxes (the same integer sums as the prefix
        // path below, at a third of its work).
        for (int j = 0; j < count; ++j) d[j] = 0;
        if (count < 2 * w + 1) return;
        int32_t in = 0, out = 0; // Σ t[j−w … j−1] and Σ t[j+1 … j+w], at most 12 × 261120
        for (int m = 0; m < w; ++m) in += t[m];
        for (int m = w + 1; m <= 2 * w; ++m) out += t[m];
        for (int j = w;; ++j) {
            d[j] = static_cast<int16_t>((out - in) / scale);
            if (j + w + 1 >= count) break;
            out += t[j + w + 1] - t[j + 1];
            in += t[j] - t[j - w];
        }
        return;
    }
    // Sums of at most 640 samples of 4×Q8 (≤ 261120) fit in 32 bits.
    int32_t prefix[kMaxFine + 1];
    int16_t badCount[kMaxFine + 1]; // samples outside the frame up to j
    prefix[0] = 0;
    for (int j = 0; j < count; ++j) prefix[j + 1] = prefix[j] + (t[j] < 0 ? 0 : t[j]);
    badCount[0] = 0;
    for (int j = 0; j < count; ++j) badCount[j + 1] = int16_t(badCount[j] + (t[j] < 0));
    for (int j = 0; j < count; ++j) {
        if (j < w || j + w >= count) {
            d[j] = 0;
            continue;
        }
        if (badCount[j + w + 1] != badCount[j - w]) {
            d[j] = 0;
            continue;
        }
        const int32_t diff = (prefix[j + w + 1] - prefix[j + 1]) - (prefix[j] - prefix[j - w]);
        d[j] = static_cast<int16_t>(diff / scale);
    }
}

} // namespace

RingSearch::MeanEdges RingSearch::meanProfileEdges()
{
    // The coarse rows hold the centre refinement's last pass (see refineCentre).
    const double rA = kCoarseStart * r0;
    const double step = coarseStep(r0);
    const int count = coarseCount(r0);
    uint16_t mean[kMaxCoarse];
    uint32_t sums[kMaxCoarse] = {}, seen[kMaxCoarse] = {};
    uint32_t whole = 0;
    for (int i = 0; i < kCoarseRays; ++i) {
        const uint16_t *row = coarse + size_t(i) * kMaxCoarse;
        addRaySamples(row, count, !anyOutsideFrame(row, count), sums, seen, &whole);
    }
    for (int j = 0; j < count; ++j) {
        const uint32_t nj = seen[j] + whole;
        mean[j] = nj * 4 >= kCoarseRays ? uint16_t(sums[j] / nj) : kOutsideFrame;
        meanProfile[j] = mean[j];
    }
    profileDerivative(mean, count, meanDeriv);
    // Steps are taken out of the profile's noise (its second differences); the silhouette
    // must also stand out of the derivative's own spread, which a photograph's long slopes
    // (the fixture's shadow, a lit barrel) inflate.
    const double minStrength = std::max<double>(kMinCoarseStrength, 6 * robustSigma(meanDeriv, 2, count - 3));
    const double minStep = std::max<double>(kMinCoarseStrength, 6 * derivativeNoise(mean, count));
    auto radiusOf = [&](int i) {
        const Q16_16 off =
            parabolaVertex(std::abs(meanDeriv[i - 1]), std::abs(meanDeriv[i]), std::abs(meanDeriv[i + 1]));
        return rA + (i + off.toDouble()) * step;
    };
    // Mean level over a band of w samples starting `gap` samples from i (negative: inside).
    const int w = std::max(4, int(0.03 * r0 / step));
    auto level = [&](int i, int dir) {
        int64_t sum = 0;
        int n = 0;
        for (int k = 3; k < 3 + w; ++k) {
            const int j = i + dir * k;
            if (j >= 0 && j < count && mean[j] != kOutsideFrame) {
                sum += mean[j];
                ++n;
            }
        }
        return n ? double(sum) / n : 0.0;
    };
    MeanEdges e;
    const int lo = std::max(2, int((0.9 * r0 - rA) / step));
    const int hi = std::min(count - 3, int((1.75 * r0 - rA) / step));
    const ProfileEdges edges = findProfileEdges(mean, meanDeriv, count, lo, hi, int32_t(minStep));
    // The zones beyond each edge name the contact edge (profile_zones.h); the window judged
    // beyond an edge is about the narrowest ring the coarse step still resolves.
    const int window = std::max(3, int(0.05 * r0 / step));
    const int named = contactEdgeByZones(mean, count, edges, window);
    // How far inside the contact edge it may be searched for before the original face's
    // edge, where that steps the same way, is nearer: half way to it. Outside, the search
    // takes the innermost clear step (innermostClearEdge), so the outline is not taken, and
    // a tilted view needs the room: its contact edge is not concentric with the coarse rays,
    // and its smeared step shows several extrema. An edge whose flank spans the contact
    // edge is that step, not another one. (pe: the edges of a profile sampled from fromPx at
    // stepPx, d its derivative.)
    auto reachInside = [&](const int32_t *d, const ProfileEdges &pe, double fromPx, double stepPx) {
        const double at = (e.rOuter - fromPx) / stepPx;
        for (int j = 0; j < pe.count; ++j) {
            const ProfileEdge &o = pe.edge[j];
            if (o.sign != e.signOuter || (o.flankLo <= at && at <= o.flankHi)) continue;
            const Q16_16 off = parabolaVertex(std::abs(d[o.index - 1]), std::abs(d[o.index]), std::abs(d[o.index + 1]));
            const double r = fromPx + (o.index + off.toDouble()) * stepPx;
            if (r < e.rOuter - 1.5 * stepPx) e.reachInPx = 0.5 * (e.rOuter - r);
        }
    };
    // The edge k of pe that the zones named (window: the samples judged beyond an edge).
    auto takeNamed = [&](const uint16_t *lv, const int32_t *d, int n, const ProfileEdges &pe, int k, int win,
                         double fromPx, double stepPx) {
        auto radiusAt = [&](int i) {
            const Q16_16 off = parabolaVertex(std::abs(d[i - 1]), std::abs(d[i]), std::abs(d[i + 1]));
            return fromPx + (i + off.toDouble()) * stepPx;
        };
        const ProfileEdge &c = pe.edge[k];
        e.found = true;
        e.namedByZones = true;
        e.rOuter = radiusAt(c.index);
        e.signOuter = c.sign;
        e.strengthOuter = int32_t(c.strength * (step / stepPx)) / 16; // coarse → fine units
        e.undecided = k == 1 && zoneBeyond(lv, n, pe, 1, win) == ZoneKind::Short && opensBand(lv, n, pe, 1);
        // A step of its sign beyond the next, the other way, more than twice as strong (a lit
        // shoulder, then the outline rising from the dark barrel): the centring, which takes
        // the innermost step at least half the strongest, must stop short of it.
        if (k + 2 < pe.count && pe.edge[k + 1].sign != c.sign && pe.edge[k + 2].sign == c.sign &&
            pe.edge[k + 2].strength > 2 * c.strength)
            e.reachOutPx = fromPx + pe.edge[k + 1].flankHi * stepPx - e.rOuter;
        reachInside(d, pe, fromPx, stepPx);
    };
    if (named >= 0) {
        takeNamed(mean, meanDeriv, count, edges, named, window, rA, step);
    } else if (edges.count >= 2 && zoneBeyond(mean, count, edges, 0, window) == ZoneKind::Short) {
        // The first edges lie too close together at the coarse step for the zone between
        // them to be judged (a ring of a few samples between two flanks): the profile is read
        // again at half the step from just inside the first, and named there if it can be.
        // It starts at the first edge's flank: farther in, the face's grain, sharper at the
        // half step, would pass for an edge before it.
        const double stepF = 0.5 * step;
        const int from = std::max(lo, edges.edge[0].flankLo - 3);
        const double fromPx = rA + from * step;
        const int n = std::min(kMaxFine, 2 * (hi - from) + 6);
        uint16_t fineMean[kMaxFine];
        int32_t fineDeriv[kMaxFine];
        finerMeanProfile(fromPx, stepF, n, fineMean);
        profileDerivative(fineMean, n, fineDeriv);
        const double minStepF = std::max<double>(kMinCoarseStrength * stepF / step, 6 * derivativeNoise(fineMean, n));
        const ProfileEdges fineEdges = findProfileEdges(fineMean, fineDeriv, n, 2, n - 3, int32_t(minStepF));
        const int windowF = std::max(3, int(0.05 * r0 / stepF));
        const int namedF = contactEdgeByZones(fineMean, n, fineEdges, windowF);
        if (namedF >= 0) takeNamed(fineMean, fineDeriv, n, fineEdges, namedF, windowF, fromPx, stepF);
    }
    // Where the zones do not tell (three levels in a row, as a drawing paints the barrel),
    // the contact edge is where the flat, bright end face gives way to the steep barrel,
    // dark under a ring light: the falling edge with the largest drop between the bands on
    // either side (a highlight's flank or the face/ICA edge drops less). If nothing falls
    // (an unusual light), the rising edge with the largest rise.
    for (int sign = -1; sign <= 1 && !e.found; sign += 2) {
        int32_t strongest = 0;
        for (int i = lo; i <= hi; ++i)
            if (isExtremum(meanDeriv, i) && sign * meanDeriv[i] > strongest) strongest = sign * meanDeriv[i];
        if (strongest < minStep) continue;
        double bestDrop = 0;
        for (int i = lo; i <= hi; ++i) {
            if (!isExtremum(meanDeriv, i) || sign * meanDeriv[i] < 0.3 * strongest) continue;
            const double drop = sign * (level(i, +1) - level(i, -1));
            if (!e.found || drop > bestDrop) {
                bestDrop = drop;
                e.found = true;
                e.rOuter = radiusOf(i);
                e.signOuter = sign;
                e.strengthOuter = std::abs(meanDeriv[i]) / 16; // coarse → fine units
            }
        }
    }
    if (!e.found) return e;
    if (!e.namedByZones) reachInside(meanDeriv, edges, rA, step);
    const double at = (e.rOuter - rA) / step;
    // Silhouette: the outermost clear edge within a barrel's width outside the contact edge.
    const int so = int((e.rOuter + std::max(4.0, 0.03 * r0) - rA) / step);
    const int eo = std::min(count - 3, int((e.rOuter + 0.5 * r0 - rA) / step));
    const double silhouetteMin = std::max({minStrength, 0.035 * e.strengthOuter * 16.0});
    for (int i = eo; i >= so; --i)
        if (isExtremum(meanDeriv, i) && std::abs(meanDeriv[i]) >= silhouetteMin) {
            e.rMax = radiusOf(i);
            break;
        }
    // Beyond the edge named: the next edge (or, if that is the outermost, the outline) and the
    // edges of the other sign inside the outline, the steps back.
    if (!e.namedByZones)
        for (int k = 0; k < edges.count; ++k) {
            const ProfileEdge &o = edges.edge[k];
            const double r = radiusOf(o.index);
            if (o.flankLo <= at || r < e.rOuter + 1.5 * step) continue;
            if (k == edges.count - 1) { // the outermost step: the outline (but see run())
                if (!(e.rNext > 0)) {
                    e.rOutline = r;
                    e.signOutline = o.sign;
                    e.strengthOutline = o.strength / 16;
                }
                break;
            }
            if (!(e.rNext > 0)) {
                e.rNext = r;
                e.signNext = o.sign;
                e.strengthNext = o.strength / 16;
            }
            if (o.sign != e.signOuter && e.backs < MeanEdges::kMaxBacks) {
                e.rBack[e.backs] = r;
                e.strengthBack[e.backs++] = o.strength / 16;
            }
        }
    return e;
}

namespace {
// How near the step back the contact edge found about it must lie (pixels): the mean
// profile's peak against the rays' fit, a pixel's sampling apart.
constexpr double kBackAgreesPx = 1.0;
// Two edges closer than this many blur σ show one derivative peak: a ring no wider is not
// resolved (reading: kResolvedRingBlurs).
constexpr double kUnresolvedBlurs = 2.0;
} // namespace

bool RingSearch::stepBack(const MeanEdges &me, MeanEdges *back)
{
    // From a few pixels inside the edge to as far beyond the silhouette as that lies beyond
    // the edge (a tenth of R0 beyond the edge where none was seen): the fall after the step
    // back must show.
    const double stepPx = kFineStepPx; // the fine rays' own, whose thresholds the strength sets
    const double fromPx = me.rOuter - 3;
    const double toPx = me.rMax > me.rOuter ? 2 * me.rMax - me.rOuter : me.rOuter + 0.1 * r0;
    const int n = std::min(kMaxFine, int((toPx - fromPx) / stepPx) + 1);
    if (n < 12) return false;
    uint16_t mean[kMaxFine];
    int32_t d[kMaxFine];
    finerMeanProfile(fromPx, stepPx, n, mean);
    if (mean[0] == kOutsideFrame) return false;
    profileDerivative(mean, n, d);
    const int s = me.signOuter;
    // The edge's own peak within a pixel or two of it, and the end of its flank beyond.
    int peak = -1;
    for (int i = 2; i < std::min(n - 2, int(5 / stepPx)); ++i)
        if (mean[i] != kOutsideFrame && (peak < 0 || s * d[i] > s * d[peak])) peak = i;
    if (peak < 0 || !(s * d[peak] > 0)) return false;
    int i = peak;
    while (i + 1 < n - 2 && s * d[i + 1] > 0) ++i;
    const int flankEnd = i;
    // The step back: the other sign's strongest sample before the profile turns the edge's
    // way again as strongly; that turn must come (the outline or the shoulder's fall). A
    // shoulder that falls off more gently than the ring's far edge rose (a turn half as steep)
    // may as well be the barrel's shading beyond the outline: read so, the contact edge is
    // undecided.
    auto turn = [&](int from, int steeper, int *at) {
        int t = -1, k = from;
        for (; k < n - 2 && mean[k] != kOutsideFrame; ++k) {
            if (-s * d[k] > 0 && (t < 0 || -s * d[k] > -s * d[t])) t = k;
            if (t >= 0 && steeper * s * d[k] >= -s * d[t]) break;
        }
        *at = k;
        return t >= 2 && k < n - 2 && mean[k] != kOutsideFrame ? t : -1;
    };
    bool undecided = false;
    int top = turn(i + 1, 1, &i);
    if (top < 0) {
        top = turn(flankEnd + 1, 2, &i);
        undecided = true;
    }
    if (top < 0) return false;
    const int32_t strength = -s * d[top];
    // The level across it: from the ring's extreme inside to the shoulder's beyond.
    int32_t ring = mean[flankEnd], shoulder = mean[top];
    for (int k = flankEnd; k <= top; ++k)
        ring = s > 0 ? std::max<int32_t>(ring, mean[k]) : std::min<int32_t>(ring, mean[k]);
    for (int k = top; k <= i; ++k)
        shoulder = s > 0 ? std::min<int32_t>(shoulder, mean[k]) : std::max<int32_t>(shoulder, mean[k]);
    const int32_t rise = -s * (shoulder - ring), drop = s * (ring - int32_t(mean[0]));
    // A step back under the zones' ripple share of the drop is a ripple on the barrel (a
    // highlight line on a drawn band: 8 %), not a shoulder beyond a ring (the bench's dark
    // ring: 34 %).
    if (rise < kRippleShareOfStep * drop || rise < kMinZoneStep) return false;
    const Q16_16 off = parabolaVertex(std::abs(d[top - 1]), std::abs(d[top]), std::abs(d[top + 1]));
    const double rBack = fromPx + (top + off.toDouble()) * stepPx;
    // Only a ring too narrow for its two edges' blurs to part is missed so; a wider band
    // beyond the edge taken is the barrel's, and its far side a highlight's, or a ring the
    // zones took the drop into for the contact edge (a dark ring of 6–7 px beside a lit
    // shoulder): up to half as wide again, the contact edge is undecided.
    if (!(rBack - me.rOuter < kNarrowRingPx)) undecided = true;
    if (!(rBack - me.rOuter < kUndecidedBackPx)) return false;
    *back = me;
    back->rOuter = rBack;
    back->signOuter = -s;
    back->strengthOuter = int32_t(int64_t(me.strengthOuter) * strength / (s * d[peak]));
    back->reachInPx = 0.5 * (back->rOuter - me.rOuter);
    // The centring stops half way to the silhouette: beyond it the fixture's faint steps
    // either way would pass for the ring's edge.
    back->reachOutPx = me.rMax > back->rOuter ? 0.5 * (me.rMax - back->rOuter) : 0;
    back->namedByZones = true; // the centring must not go back to the drop
    back->undecided = undecided;
    back->rNext = back->rOutline = 0;
    return true;
}

bool RingSearch::stepsBackBeyond(const MeanEdges &me)
{
    // The profile about the coarse centre at the fine step, from the face inside the drop to
    // a band beyond the step back: a ring of a few coarse samples shows its own level there,
    // and a highlight line across a barrel band adds little to the band's mean.
    // A margin either side of each step clears its blur and the derivative's reach.
    const double margin = std::max(2.0, 0.012 * r0), band = std::max(3.0, 0.03 * r0);
    const double fromPx = me.rOuter - margin - band;
    if (!(me.rNext - me.rOuter > 2 * margin + 1)) return false;
    const int n = std::min(kMaxFine, int((me.rNext + margin + band - fromPx) / kFineStepPx) + 1);
    uint16_t mean[kMaxFine];
    finerMeanProfile(fromPx, kFineStepPx, n, mean);
    auto at = [&](double r) { return std::clamp(int((r - fromPx) / kFineStepPx + 0.5), 0, n - 1); };
    auto level = [&](double a, double b, int32_t *out) {
        int64_t sum = 0;
        int k = 0;
        for (int j = at(a); j <= at(b); ++j, ++k) {
            if (mean[j] == kOutsideFrame) return false;
            sum += mean[j];
        }
        *out = k ? int32_t(sum / k) : 0;
        return k > 0;
    };
    // Beyond the step back a level over the band (a fold, a lit shoulder), not a line's peak.
    int32_t face = 0, ring = 0, beyond = 0;
    if (!level(fromPx, me.rOuter - margin, &face) || !level(me.rOuter + margin, me.rNext - margin, &ring) ||
        !level(me.rNext + margin, me.rNext + margin + band, &beyond))
        return false;
    const int32_t fall = std::abs(face - ring), rise = me.signNext * (beyond - ring);
    return rise >= kMinZoneStep && rise >= kRippleShareOfStep * fall;
}

void RingSearch::finerMeanProfile(double fromPx, double stepPx, int count, uint16_t *mean)
{
    uint32_t sum[kMaxFine] = {}, n[kMaxFine] = {};
    const int stride = rays_ / kCoarseRays;
    uint16_t *row = fine; // the fine stage fills the fine rows afresh
    const RaySpec along{Q16_16::fromDouble(cx),     Q16_16::fromDouble(cy),    {}, {},
                        Q16_16::fromDouble(fromPx), Q16_16::fromDouble(stepPx)};
    uint32_t whole = 0;
    for (int i = 0; i < kCoarseRays; ++i) {
        RaySpec ray = along;
        ray.cosT = rayCosQ_[i * stride], ray.sinT = raySinQ_[i * stride];
        addRaySamples(row, count, sampleRay(*frame, ray, count, row) == count, sum, n, &whole);
    }
    for (int j = 0; j < count; ++j) n[j] += whole;
    for (int j = 0; j < count; ++j) mean[j] = n[j] * 4 >= kCoarseRays ? uint16_t(sum[j] / n[j]) : kOutsideFrame;
}

void RingSearch::sampleWindow(const double *start, double step, int count, int boxHalf, EndFaceGeometry *m)
{
    fineStep_ = step;
    fineCount_ = count;
    uint32_t saturated = 0, inside = 0;
    // The centre and the step are the same on every ray: converted once.
    const Q16_16 qx = Q16_16::fromDouble(cx), qy = Q16_16::fromDouble(cy), qStep = Q16_16::fromDouble(step);
    for (int i = 0; i < rays_; ++i) {
        fineStart_[i] = start[i];
        RaySpec ray{qx, qy, rayCosQ_[i], raySinQ_[i], Q16_16::fromDouble(start[i]), qStep};
        uint16_t *row = fine + size_t(i) * kMaxFine;
        inside += uint32_t(sampleRay(*frame, ray, count, row));
    }
    if (inside < uint32_t(count) * uint32_t(rays_)) m->imageFlags |= kImageSpecimenClipped;

    // Derivative across a [1 2 1] angular smoothing of neighbouring rays (the boundaries
    // vary slowly with angle; the noise does not). Samples at the same index of adjacent
    // rays lie at the same offset from the window's start curve. Stored as slope in 1/128
    // grey per px.
    int32_t t[kMaxFine];
    const bool allInside = inside == uint32_t(count) * uint32_t(rays_);
    for (int i = 0; i < rays_; ++i) {
        const uint16_t *a = fine + size_t((i + rays_ - 1) % rays_) * kMaxFine;
        const uint16_t *b = fine + size_t(i) * kMaxFine;
        const uint16_t *c = fine + size_t((i + 1) % rays_) * kMaxFine;
        // Two loops the compiler vectorises (one mixing the count and the sums does not).
        for (int j = 0; j < count; ++j) t[j] = int32_t(a[j]) + 2 * int32_t(b[j]) + int32_t(c[j]);
        uint16_t full = 0; // at most kMaxFine: counted in 16-bit lanes
        for (int j = 0; j < count; ++j) full = uint16_t(full + (b[j] == kFullScaleQ8));
        saturated += full;
        if (!allInside) // a sum touching a sample outside the frame is marked unusable
            for (int j = 0; j < count; ++j)
                if (a[j] == kOutsideFrame || b[j] == kOutsideFrame || c[j] == kOutsideFrame) t[j] = -1;
        int16_t *d = deriv + size_t(i) * kMaxFine;
        if (boxHalf > 0) {
            boxStep(t, count, boxHalf, allInside, d);
            continue;
        }
        d[0] = d[1] = 0;
        if (count >= 2) d[count - 1] = d[count - 2] = 0;
        // |g| ≤ 3 · 4 · 65280, so g >> 6 stays within ±12 240: it fits int16 as it is (no clamp,
        // and the loop vectorises).
        for (int j = 2; j + 2 < count; ++j) {
            const int32_t g = t[j + 2] + 2 * t[j + 1] - 2 * t[j - 1] - t[j - 2];
            d[j] = static_cast<int16_t>(g >> 6);
        }
        if (!allInside)
            for (int j = 2; j + 2 < count; ++j)
                if (t[j - 2] < 0 || t[j - 1] < 0 || t[j + 1] < 0 || t[j + 2] < 0) d[j] = 0;
    }
    samplesInside_ += inside;
    samplesSaturated_ += saturated;
    m->saturatedFraction = samplesInside_ ? double(samplesSaturated_) / samplesInside_ : 0;
}

bool RingSearch::locateOnRays(int sign, int fallbackSign, const double *loPx, const double *hiPx, int32_t minStrength,
                              EdgeSample *pts, bool interior, double reachPx, BoundaryFit *fit, double *curveOut,
                              double *contrastOut)
{
    double radius[kRays], steps[kRays];
    bool valid[kRays];
    int nSteps = 0;
    const int reach = std::max(1, int(reachPx / fineStep_ + 0.5));
    if (!pts) {
        // A first pass only places the second pass's narrow windows: every other ray (32 or
        // more, still far more than the curve's 9 coefficients need), then the curve at all
        // rays.
        const int half = rays_ / 2;
        for (int h = 0; h < half; ++h) {
            const int i = 2 * h;
            const int lo = int(std::floor((loPx[i] - fineStart_[i]) / fineStep_));
            const int hi = int(std::ceil((hiPx[i] - fineStart_[i]) / fineStep_));
            const EdgePeak p = strongestEdge(deriv + size_t(i) * kMaxFine, fineCount_, lo, hi, sign, interior);
            valid[h] = p.found && p.value >= minStrength;
            radius[h] = fineStart_[i] + p.position.toDouble() * fineStep_;
        }
        if (!fitBoundary(radius, valid, half, cx, cy, FitOptions{}, fit)) return false;
        radiiAt(*fit, rayCos_, raySin_, rays_, curveOut);
        return true;
    }
    for (int i = 0; i < rays_; ++i) {
        const int lo = int(std::floor((loPx[i] - fineStart_[i]) / fineStep_));
        const int hi = int(std::ceil((hiPx[i] - fineStart_[i]) / fineStep_));
        const int16_t *d = deriv + size_t(i) * kMaxFine;
        EdgePeak p = strongestEdge(d, fineCount_, lo, hi, sign, interior);
        if (fallbackSign && !(p.found && p.value >= minStrength))
            p = strongestEdge(d, fineCount_, lo, hi, fallbackSign, interior);
        valid[i] = p.found && p.value >= minStrength;
        radius[i] = fineStart_[i] + p.position.toDouble() * fineStep_;
        pts[i] = {Q16_16::fromDouble(cx + radius[i] * rayCos_[i]), Q16_16::fromDouble(cy + radius[i] * raySin_[i]),
                  Q16_16::fromDouble(radius[i]), p.value, valid[i]};
        if (!valid[i]) continue;
        const uint16_t *row = fine + size_t(i) * kMaxFine;
        const int j = int(p.position.toDouble() + 0.5);
        if (j - reach >= 0 && j + reach < fineCount_ && row[j - reach] != kOutsideFrame &&
            row[j + reach] != kOutsideFrame)
            steps[nSteps++] = (double(row[j + reach]) - double(row[j - reach])) / 256.0;
    }
    if (!fitBoundary(radius, valid, rays_, cx, cy, FitOptions{}, fit, curveOut)) return false;
    // Points the robust fit rejected are shown as such (overlays, diagnostics).
    const double keep = std::max(0.75, 3 * fit->scatterPx);
    for (int i = 0; i < rays_; ++i) pts[i].valid = pts[i].valid && std::fabs(radius[i] - curveOut[i]) <= keep;
    // A boundary fitted on under kLowCoverage of the rays is as uncertain as the edge the
    // fit threw away: when the rejected points sit together at another radius (the edge
    // taken on part of the ring is a neighbouring one, or the curve is), either could be the
    // boundary on that part, and the equivalent radius moves by the unused fraction times
    // their offset. Its σ takes that in, so that a reading on such an edge is wide enough to
    // cover the truth, not only flagged.
    if (fit->coverage < kLowCoverage) {
        double offsets[kRays];
        int n = 0;
        for (int i = 0; i < rays_; ++i)
            if (valid[i] && !pts[i].valid) offsets[n++] = std::fabs(radius[i] - curveOut[i]);
        if (n > 0) {
            std::nth_element(offsets, offsets + n / 2, offsets + n);
            fit->rEqSigmaPx = std::hypot(fit->rEqSigmaPx, (1 - fit->coverage) * offsets[n / 2]);
        }
    }
    if (nSteps) {
        std::nth_element(steps, steps + nSteps / 2, steps + nSteps);
        *contrastOut = steps[nSteps / 2];
    }
    return true;
}

double RingSearch::centreOnContactEdge(const MeanEdges &me)
{
    // What an oblique view does to the contact edge's profile along a ray: foreshortening
    // (cos θ across the edge, 2 % at 12°) and the lens's local scale stretch the profile
    // about the step, and the camera's blur is the same on both sides, so the derivative's
    // peak stays on the step (measured with the true camera: R_o within 0.02 % median). What
    // changes is which edge a ray meets near the expected radius, below.
    // Through a tilted lens the contact edge and the silhouette are not concentric: the axis
    // meets the end face and the barrel's widest circle (half-way down) at image points up
    // to about 1 mm apart, and the barrel shows wide on the side facing the camera but hides
    // behind the end face on the far side. The coarse centre, fitted to whichever edge was
    // strongest on each ray, lies between them, and a circle about it can miss the contact
    // edge by tens of pixels. The named edge on 32 rays, searched ±15 % of R0 about the
    // named radius, and a robust fit move the centre onto the contact edge itself; rays where
    // the edge has the other polarity (the fixture brighter than the ring beside it) find
    // nothing or another edge, and the fit drops them. The first pass reads the coarse rays
    // already sampled: a straight view, where the two centres agree within 1.5 px, keeps its
    // centre at that cost; an oblique one casts fresh rays from the moved centre (twice at
    // most) until it settles. The fit's mean radius replaces the mean profile's (which the
    // two edges' offset smears) as the radius the fine stage searches about, where they
    // differ by 3 px or more.
    if (me.kneeOnRamp) return me.rOuter;
    constexpr int kCentringRays = 32, kFirstPassRays = 16; // the first pass: every fourth coarse ray
    constexpr int kCoarseStride = kCoarseRays / kFirstPassRays;
    const int fineStride = rays_ / kCentringRays;
    // The window stops half way to the original face's edge: where that steps the same way
    // as the contact edge, a wider one would take it.
    const double w = 0.15 * r0;
    const double wIn = me.reachInPx > 0 ? std::min(w, std::max(4.0, me.reachInPx)) : w;
    // Nor past a lit shoulder's far flank, where the outline beyond it would outshine the
    // contact edge (MeanEdges::reachOutPx; the bench's dark rings: the shoulder's rise 20
    // grey levels, the outline's 45).
    const double wOut = me.reachOutPx > 0 ? std::min(w, std::max(4.0, me.reachOutPx)) : w;
    int32_t d[kMaxCoarse], peaks[kCentringRays], sorted[kCentringRays];
    double radius[kCentringRays];
    bool valid[kCentringRays];
    double r = me.rOuter;
    for (int pass = 0; pass < 3; ++pass) {
        // Pass 0: the coarse rows (from kCoarseStart·R0 at the coarse step); then fresh rays
        // at 2 px steps from r − w, sampled into the fine rows (the fine stage refills them).
        const bool coarseRows = pass == 0;
        const double rA = coarseRows ? kCoarseStart * r0 : r - w;
        const double step = coarseRows ? coarseStep(r0) : 2.0;
        const int count = coarseRows ? coarseCount(r0) : std::min(kMaxFine, int(2 * w / step) + 7);
        // Where an edge of the contact edge's sign lies inside, the window's inner end stays
        // half way to it as the radius settles: a mean radius pulled inwards by rays that took
        // something inside would otherwise walk the window onto it, pass by pass.
        const double inner = me.reachInPx > 0 ? std::max(r, me.rOuter) - wIn : r - wIn;
        const int lo = std::max(3, int((inner - rA) / step));
        const int hi = std::min(count - 4, int((r + wOut - rA) / step) + 1);
        if (hi - lo < 4) break;
        // Where the steps named the edge (the largest drop: a guess, which a highlight's
        // flank merged into the outline can win), a stronger step inside it, within the
        // whole window, is taken instead, as the step down from the flat face it names.
        const int loWide = me.namedByZones ? lo : std::max(3, int((r - w - rA) / step));
        const double at = (r - rA) / step;
        const int rays = coarseRows ? kFirstPassRays : kCentringRays;
        const RaySpec along{Q16_16::fromDouble(cx), Q16_16::fromDouble(cy),  {}, {},
                            Q16_16::fromDouble(rA), Q16_16::fromDouble(step)};
        int found = 0;
        for (int k = 0; k < rays; ++k) {
            const uint16_t *row;
            if (coarseRows) {
                row = coarse + size_t(k * kCoarseStride) * kMaxCoarse;
            } else {
                const int i = k * fineStride;
                uint16_t *out = fine + size_t(k) * kMaxFine;
                RaySpec ray = along;
                ray.cosT = rayCosQ_[i], ray.sinT = raySinQ_[i];
                sampleRay(*frame, ray, count, out);
                row = out;
            }
            // The derivative over the window only (profileDerivative's kernel); a ray leaving
            // the frame there is not used (a vectorisable scan, then a branch-free loop).
            if (anyOutsideFrame(row + loWide - 3, hi - loWide + 7)) {
                valid[k] = false;
                continue;
            }
            for (int j = loWide - 1; j <= hi + 1; ++j)
                d[j] = int32_t(row[j + 2]) + 2 * int32_t(row[j + 1]) - 2 * int32_t(row[j - 1]) - int32_t(row[j - 2]);
            // The flat face ends at the contact edge: where the outline steps the same way beyond
            // it (a tilted view shows the barrel wide on the side facing the camera), the
            // contact edge is the first of the two at least half as strong.
            EdgePeak p = innermostClearEdge(d, count, lo, hi, me.signOuter, 2);
            if (!me.namedByZones) {
                const EdgePeak strongest = strongestEdge(d, count, loWide, hi, me.signOuter);
                if (strongest.found && strongest.position.toDouble() < at - 1 && strongest.value > p.value)
                    p = strongest;
            }
            valid[k] = p.found;
            radius[k] = rA + p.position.toDouble() * step;
            if (p.found) peaks[found++] = p.value;
        }
        if (found < 8) break;
        // Weak peaks are noise on rays without the edge: below a third of the typical one.
        std::copy(peaks, peaks + found, sorted);
        std::nth_element(sorted, sorted + found / 2, sorted + found);
        const int32_t floor = sorted[found / 2] / 3;
        for (int k = 0, j = 0; k < rays; ++k)
            if (valid[k]) valid[k] = peaks[j++] >= floor;
        BoundaryFit fit;
        FitOptions opt;
        opt.maxHarmonics = 2;
        opt.minRejectPx = 2.0;
        if (!fitBoundary(radius, valid, rays, cx, cy, opt, &fit) || fit.coverage < 0.3) break;
        const bool still = std::hypot(fit.centreX - cx, fit.centreY - cy) < 1.5;
        if (still && std::fabs(fit.a0 - r) < 3.0) break; // a straight view: as it was
        r = fit.a0;
        if (still) break;
        cx = fit.centreX, cy = fit.centreY;
    }
    return r;
}

RingSearch::MeanEdges RingSearch::castRays()
{
    static_assert(kRays == AngleTable::kSize && kRays <= kMaxRayTable, "fine ray i is at most table angle i");
    rays_ = kRays;
    while (rays_ > kCoarseRays && 2 * std::numbers::pi * r0 / rays_ < kMinRayArcPx) rays_ /= 2;
    const AngleTable &angles = angleTable();
    const int stride = AngleTable::kSize / rays_;
    for (int i = 0; i < rays_; ++i) {
        rayCosBuf_[i] = angles.cos[i * stride], raySinBuf_[i] = angles.sin[i * stride];
        rayCosQBuf_[i] = angles.cosQ[i * stride], raySinQBuf_[i] = angles.sinQ[i * stride];
    }
    rayCos_ = rayCosBuf_;
    raySin_ = raySinBuf_;
    rayCosQ_ = rayCosQBuf_;
    raySinQ_ = raySinQBuf_;
    return meanProfileEdges();
}

ErrorCode RingSearch::runBeyondDrop(EndFaceGeometry *m)
{
    const MeanEdges me = castRays();
    if (!me.found) return ErrorCode::OuterEdgeNotFound;
    MeanEdges back;
    if (!stepBack(me, &back)) return ErrorCode::InnerEdgeNotFound;
    const ErrorCode e = ringAbout(back, m);
    // The ring's far edge is where the profile stepped back. A ring the fits read elsewhere
    // (a two-step fit across a ring that is no level, a V between the face and the
    // shoulder, moving both steps inside) is not the one the step back showed.
    if (e == ErrorCode::None && !(std::fabs(m->outer.rEqPx - back.rOuter) <= kBackAgreesPx))
        return ErrorCode::InnerEdgeNotFound;
    return e;
}

ErrorCode RingSearch::run(EndFaceGeometry *m)
{
    const MeanEdges me = castRays();
    if (!me.found) return ErrorCode::OuterEdgeNotFound;
    const double cx0 = cx, cy0 = cy;
    const bool staircase = me.rNext > 0 && me.signNext == me.signOuter;
    // On a staircase a ring no ray saw the original face's edge of is as likely the face's
    // edge itself (below): the profile's two-step fit, the search's costliest part, waits
    // until the ring about the next step has been tried.
    bool deferred = false;
    ErrorCode e = ringAbout(me, m, !staircase, &deferred);
    auto again = [&](const MeanEdges &about) {
        cx = cx0, cy = cy0;
        samplesInside_ = samplesSaturated_ = 0;
        m->imageFlags = 0;
        m->saturatedFraction = 0;
        m->edgeWidthPx = 0;
        m->innerEdgeWidthPx = 0;
        m->contactRampPx = 0;
        return ringAbout(about, m);
    };
    // The ring about the profile's next step beyond the named one, at radius r.
    auto nextStep = [&me](double r, int sign, int32_t strength) {
        MeanEdges next = me;
        next.rOuter = r;
        next.signOuter = sign;
        next.strengthOuter = strength;
        next.reachInPx = 0.5 * (r - me.rOuter);
        next.reachOutPx = 0;
        next.namedByZones = true; // by elimination: the centring must not go back to the drop
        next.rNext = 0;
        return next;
    };
    const MeanEdges next = nextStep(me.rNext, me.signNext, me.strengthNext);
    // The largest drop named an edge with no original face's edge inside it, and the only
    // step of its sign beyond it is the one taken for the outline. Seen obliquely, the barrel
    // shows on the side facing the camera and hides behind the end face on the far side,
    // where the contact edge bounds the specimen: the mean profile then shows the contact
    // edge's step where it expects the outline, and the outline's own smeared into the
    // background. The ring is searched once more about that step, as an oblique view's.
    auto onOutlineStep = [&] {
        if (me.rNext > 0 || !(me.rOutline > 0) || me.signOutline != me.signOuter) return e;
        MeanEdges onOutline = nextStep(me.rOutline, me.signOutline, me.strengthOutline);
        onOutline.seenObliquely = true;
        const ErrorCode e2 = again(onOutline);
        return e2 == ErrorCode::None ? e2 : e;
    };
    // The largest drop is the profile's outermost edge, nothing named beyond it, and the
    // ring's level ends well inside it, the profile ramping down from there to the drop: the
    // drop may be the outline at the foot of a barrel that turns from the light over tens of
    // pixels (a side flat about its widest section, on a dark fixture), the contact edge where
    // the ring's level ends (levelEndInsideDrop). Read about the drop, the ring then spans the
    // ramp, R_o on the outline, and no outline shows beyond it: there the ring is read again
    // about the knee. A reading that found an outline beyond its contact edge stands, as one
    // whose barrel band swings round the ring (a tilted view, whose mean profile, smeared
    // across the ellipse, ramps as well). The ring about the knee is taken where both its
    // boundaries hold on most rays and, against a ring read about the drop, where its contact
    // edge lies inside the ramp, not where the drop's did.
    const bool dropOutermost = !me.namedByZones && !(me.rNext > 0) && !(me.rOutline > 0) && !(me.rMax > 0);
    MeanEdges onRamp;
    // outerMaxPx: the farthest out its contact edge may lie.
    auto readOnRamp = [&](double outerMaxPx) {
        return again(onRamp) == ErrorCode::None && std::min(m->inner.coverage, m->outer.coverage) >= kLowCoverage &&
               m->outer.rEqPx <= outerMaxPx;
    };
    if (e == ErrorCode::None && dropOutermost && !(m->rMaxPx > 0) && !(m->imageFlags & kImageBarrelOblique) &&
        levelEndInsideDrop(me, &onRamp))
        return readOnRamp(m->outer.rEqPx - onRamp.reachOutPx) ? ErrorCode::None : again(me);
    // The profile's steps back beyond the drop, nearest first (a turned ring's grooves step both
    // ways before the step back onto a shoulder): the first whose ring the rays read with its
    // original face's edge on the drop, where the step back's own check allows (below).
    auto readAboutStepBack = [&] {
        for (int b = 0; b < me.backs; ++b) {
            MeanEdges via = me;
            via.rNext = me.rBack[b], via.signNext = -me.signOuter, via.strengthNext = me.strengthBack[b];
            if (stepsBackBeyond(via) && again(nextStep(via.rNext, via.signNext, via.strengthNext)) == ErrorCode::None &&
                !(m->imageFlags & kImageNarrowRingFit) && std::fabs(m->inner.rEqPx - me.rOuter) <= kBackAgreesPx)
                return true;
        }
        return false;
    };
    // A ring the profile's fit about the drop reads narrower than two blurs is no ring resolved
    // (the reading says so): where the profile steps back beyond the drop, the ring about the
    // step back is read instead, and the fit stands where none is (a dark ring's grooves at
    // 2028 × 1520, 10 px apart and 17 grey levels deep: the fit read the first of them as the
    // contact edge, 1.9 px out, μ 0.23 low; the step back beyond them, 74 px out, is the edge).
    if (e == ErrorCode::None && (m->imageFlags & kImageNarrowRingFit) && !staircase && me.backs > 0 &&
        m->outer.rEqPx - m->inner.rEqPx < kUnresolvedBlurs * std::max(m->edgeWidthPx, 0.5)) {
        if (readAboutStepBack()) return ErrorCode::None;
        return again(me);
    }
    if (deferred) {
        // No ray saw an original face's edge inside the largest drop: on a staircase the drop
        // is as likely the original face's edge itself, two steps of one face edge not round
        // about the centre passing for a narrow ring. Where the rays find the ring about the
        // next step, that reading stands; else the profile's fit about the drop, and where
        // that fails too, the search about the next step as it went.
        if (again(next) == ErrorCode::None && !(m->imageFlags & kImageNarrowRingFit)) return ErrorCode::None;
        const ErrorCode fitted = again(me);
        if (fitted != ErrorCode::InnerEdgeNotFound) return fitted;
        return again(next);
    }
    if (e != ErrorCode::InnerEdgeNotFound) return e;
    if (!staircase) {
        const bool movedInward = centredRadius_ < me.rOuter - kInwardMovePx;
        // The largest drop named an edge with no original face's edge inside it, and the
        // profile steps back the other way beyond it: the drop is the original face's own
        // edge and the step back the contact edge, where the barrel beside it is brighter than
        // the ring (a lit shoulder beside a dark ring; the fold of a barrel flatter about its
        // widest section than the FE's, which leaves the platen nearly flat and faces the
        // light: face, ring and fold three levels, then the fall). The ring about that step
        // stands where its original face's edge is the drop, to the sampling that the step
        // back's own check allows, and where the step back is more than a highlight line's
        // ripple on a drawn barrel band.
        if (!me.namedByZones && readAboutStepBack()) return ErrorCode::None;
        // The same where the step back is the profile's last step, taken for the outline (a
        // ring of a few coarse samples, its lit shoulder and the outline beyond it one rise).
        // That step may as well be the outline itself beyond a face with no ring of its own:
        // the image does not decide, and the reading says so (a tilted view's 5 px ring read
        // so was 0.0136 off in μ).
        if (!me.namedByZones && !(me.rNext > 0) && me.rOutline > 0 && me.signOutline != me.signOuter) {
            MeanEdges viaOutline = me;
            viaOutline.rNext = me.rOutline, viaOutline.signNext = me.signOutline;
            viaOutline.strengthNext = me.strengthOutline;
            MeanEdges onLast = nextStep(me.rOutline, me.signOutline, me.strengthOutline);
            onLast.undecided = true;
            if (stepsBackBeyond(viaOutline) && again(onLast) == ErrorCode::None &&
                std::fabs(m->inner.rEqPx - me.rOuter) <= kBackAgreesPx)
                return ErrorCode::None;
        }
        // No ray found an original face's edge inside a drop that is the outline at a ramp's
        // foot (above).
        if (dropOutermost && !movedInward && levelEndInsideDrop(me, &onRamp) && readOnRamp(me.rOuter))
            return ErrorCode::None;
        if (me.namedByZones || !movedInward) return onOutlineStep();
        // The largest drop named an edge, the centring took a sharper step of its sign inside
        // it instead, and no original face's edge lies inside that one: it is the original
        // face's edge itself. A ring whose barrel ramps away into a dark fixture shows so, its
        // contact edge smeared by the ramp into one descent with the outline: the ring is
        // searched again on the drop itself. The zones did not tell the two apart, so the
        // geometry says so (a drawn barrel band beyond a ring of the face's grey looks alike).
        MeanEdges onDrop = me;
        onDrop.namedByZones = true;                            // the centring must not go back inside, nor
        onDrop.reachInPx = 0.5 * (me.rOuter - centredRadius_); // half way to that edge
        onDrop.undecided = true;
        const ErrorCode e2 = again(onDrop);
        return e2 == ErrorCode::None ? e2 : e;
    }
    // The largest drop named an edge with no original face's edge inside it, and the profile
    // steps the same way again beyond it, inside the outline: a staircase (face above ring
    // above barrel, or below each), whose first step, the original face's edge, drops the
    // most where the face is far from the ring's grey and the ring is too narrow at the
    // coarse step to show as a level. The ring is searched again about that next step.
    return again(next);
}

ErrorCode RingSearch::ringAbout(const MeanEdges &me, EndFaceGeometry *m, bool profileFit, bool *deferred)
{
    coarseCx_ = cx, coarseCy_ = cy;
    const double rOuter = centreOnContactEdge(me);
    centredRadius_ = rOuter;
    m->centreX = cx, m->centreY = cy;

    // Stage 1, the contact edge on every fine ray: a window about the mean profile's radius
    // wide enough for its departure from a circle, short of the silhouette.
    const double margin = std::max(8.0, 0.035 * r0);
    const double outerHi = me.rMax > 0 ? std::min(margin, 0.5 * (me.rMax - me.rOuter)) : margin;
    double start[kRays];
    const int outerCount = std::min(kMaxFine, int(margin + outerHi) + 6);
    for (int i = 0; i < rays_; ++i) start[i] = rOuter - margin - 3;
    sampleWindow(start, kFineStepPx, outerCount, 0, m);
    if (m->saturatedFraction > 0.5) return ErrorCode::Saturated;

    double lo[kRays], hi[kRays];
    BoundaryFit outer, inner;
    double outerR[kRays], innerR[kRays]; // the fitted curves at every fine ray
    double contrastOuter = 0, contrastInner = 0;
    // A knee on a ramp is searched for no farther in than half the level it ends: a ring a
    // few margins wide would reach the original face's edge, the one clear step there.
    const double inside = me.kneeOnRamp ? std::min(margin, std::max(3.0, me.reachInPx)) : margin;
    for (int i = 0; i < rays_; ++i) {
        lo[i] = rOuter - inside;
        hi[i] = rOuter + outerHi;
    }
    const int32_t outerMin = std::max<int32_t>(8, int32_t(0.3 * me.strengthOuter));
    if (!locateOnRays(me.signOuter, 0, lo, hi, outerMin, nullptr, false, 3.0, &outer, outerR, nullptr) ||
        outer.coverage < 0.3)
        return ErrorCode::OuterEdgeNotFound;
    // Pass 2: close to the fitted curve, so a stain edge nearby cannot win.
    for (int i = 0; i < rays_; ++i) {
        lo[i] = outerR[i] - 3.0;
        hi[i] = outerR[i] + 3.0;
    }
    if (!locateOnRays(me.signOuter, -me.signOuter, lo, hi, outerMin, outerPts, false, 3.0, &outer, outerR,
                      &contrastOuter) ||
        outer.coverage < 0.3)
        return ErrorCode::OuterEdgeNotFound;

    // Stage 2, naming the original face edge on a mean profile of every eighth ray sampled at
    // fixed offsets from the fitted contact edge. Following the edge keeps a narrow ring
    // sharp where the contact edge is not a circle.
    AlignedProfile profile;
    if (!alignedProfile(outerR, &profile)) return ErrorCode::BadSpecimen;
    const double alignedOnPx = outer.rEqPx; // the contact edge the profile's sample K follows
    const double edgeWidth = contactEdgeWidth(profile, me.signOuter);
    if (edgeWidth >= 0) m->edgeWidthPx = edgeWidth;
    const OriginalFaceName name = nameOriginalFace(profile);

    // Stage 3, the original face's edge on every fine ray. Below kNarrowRingPx the two edges'
    // blurs overlap and pull each other's derivative peaks apart on every ray: there the
    // profile's two-step fit, which models both, is taken wherever it holds.
    // An "edge" the rays place with under kMinInnerContrast between its two sides is noise
    // that the derivative happened to peak on, not the original face.
    if (originalFaceOnRays(name, profile, outerR, m, &inner, innerR, &contrastInner) &&
        std::fabs(contrastInner) >= kMinInnerContrast) {
        if (outer.rEqPx - inner.rEqPx < kNarrowRingPx) {
            narrowRingFromProfile(profile, me.signOuter, outer.rEqPx - inner.rEqPx, &outer, &inner, &contrastInner);
        } else {
            // The original face's blur against the contact edge's, both within half the ring
            // (at most 6 px) so that neither reaches the other edge.
            AlignedProfile atInner;
            const double reach = std::min(6.0, 0.5 * (outer.rEqPx - inner.rEqPx));
            // The derivative's kernel reaches two samples: the moments' window stays three inside.
            const int halfSpan = int(reach / kFineStepPx) + 4;
            const double wi =
                alignedProfile(innerR, &atInner, true, halfSpan) ? stepWidth(atInner, name.sign, reach) : -1;
            const double wo = stepWidth(profile, me.signOuter, reach);
            if (wi > 0 && wo >= 0) {
                m->innerEdgeWidthPx = wi;
                m->contactRampPx = std::sqrt(std::max(0.0, wo * wo - wi * wi));
                const double ringPx = outer.rEqPx - inner.rEqPx;
                bool atKnee = false;
                if (obliqueView || me.seenObliquely) {
                    const double widest =
                        contactEdgeAtKneeBySector(outerR, me.signOuter, wi, reach, ringPx, &outer, &atKnee);
                    m->contactRampPx = std::max(m->contactRampPx, widest);
                } else {
                    atKnee = contactEdgeAtKnee(profile, me.signOuter, wi, m->contactRampPx, ringPx, &outer);
                }
                if (toneGamma > 1) undoToneCurve(atInner, profile, wi, reach, atKnee, &inner, &outer);
            }
        }
    } else if (!profileFit) {
        *deferred = true;
        return ErrorCode::InnerEdgeNotFound;
    } else if (narrowRingFromProfile(profile, me.signOuter, 0.0, &outer, &inner, &contrastInner)) {
        // No ray saw the original face's edge: the profile alone says the ring is narrow,
        // and the reading says so (warn).
        m->imageFlags |= kImageNarrowRingFit;
    } else {
        return !name.sign && m->saturatedFraction > 0.1 ? ErrorCode::Saturated : ErrorCode::InnerEdgeNotFound;
    }
    if (!(inner.rEqPx < outer.rEqPx) || (me.rMax > 0 && !(outer.rEqPx < me.rMax + 2)))
        return ErrorCode::InconsistentRing;
    inner.contrast = contrastInner;
    outer.contrast = contrastOuter;
    m->inner = inner;
    m->outer = outer;
    // The silhouette per coarse ray refines the mean profile's estimate (the mean profile
    // blurs a weak barrel/background step and can name a highlight's flank instead).
    OutlineRaysSeen seen;
    double outlineR[kCoarseRays];
    double perRay = silhouetteFromRays(outerR, edgeWidth >= 0 ? edgeWidth : kUnknownBlurPx, m, outlineR, &seen);
    // An outline too faint for the rays' own fit, which the mean profile shows, is sought on
    // the sectors' pooled rays about it.
    bool fromSectors = false;
    if (seen.faint && me.rMax > 0 && !me.kneeOnRamp) {
        perRay = silhouetteFromSectors(me.rMax, m, outlineR);
        fromSectors = true;
    }
    // Where some rays stepped on a bright line, the fit is held against one on their aligned
    // mean: the outline lies beyond a highlight line, or is not seen (settleOutline).
    perRay = settleOutline(me, outerR, edgeWidth >= 0 ? edgeWidth : kUnknownBlurPx, seen.lopsided,
                           perRay > 0 && (seen.linesSeen || fromSectors), perRay, outlineR, m);
    if (seen.lopsided) m->imageFlags |= kImageBarrelOblique;
    // A contact edge rising onto lighter ground with no step anywhere beyond it, on any ray
    // searched there, may be the barrel's outline against the fixture: the ring read is then
    // the barrel's dark band and the original face's edge the contact edge (the bench's
    // tilted-s4 0020: a face and ring 13 grey levels apart read as one face, μ 0.095 low). A
    // ring darker than a lit barrel whose outline the fixture hides looks alike; the image
    // cannot tell them apart, and the reading says so.
    if (!(m->rMaxPx > 0) && contrastOuter > 0 && seen.stepped == 0 && 2 * seen.searched >= kCoarseRays)
        m->imageFlags |= kImageContactEdgeUndecided | kImageUndecidedNoStepBeyond;
    // The original face is one finish: a face read with an edge of its own inside it is the
    // specimen's face and ring together, the ring read a band beyond them (the bench's full-size
    // tilted seed 11 record 8: a dark ring of 49 px read as face, a lit shoulder of 6 px as
    // the ring, μ 0.19 low).
    if (faceHoldsEdge(profile, profile.K - (alignedOnPx - inner.rEqPx) / kFineStepPx, contrastInner,
                      m->innerEdgeWidthPx))
        m->imageFlags |= kImageContactEdgeUndecided | kImageUndecidedFaceHoldsEdge;
    if (m->rMaxPx > 0 && outlineRivalled(m->rMaxPx)) {
        m->imageFlags |= kImageOutlineAmbiguous;
        // Only an outline the rays agree on to a coarse step is one smeared outline; a
        // ragged one may be anything.
        if (perRay > 0 && m->silhouetteScatterPx <= coarseStep(r0) && !outlineRivalledAlong(outlineR))
            m->imageFlags |= kImageOutlineSmeared;
    }
    if (me.undecided) m->imageFlags |= kImageContactEdgeUndecided;
    m->innerPoints = innerPts;
    m->outerPoints = outerPts;
    m->rayCount = rays_;
    return ErrorCode::None;
}

} // namespace icacam::vision
