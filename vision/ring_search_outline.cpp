// The barrel's outline on the coarse rays: where each ray leaves the barrel for the background,
// whether the band is lopsided (an oblique view), whether the fixture's shadow rivals it.
#include "vision/ring_search.h"

#include <algorithm>
#include <cmath>

#include "vision/boundary_fit.h"
#include "vision/edge_profile.h"
#include "vision/radial_profile.h"
#include "vision/ring_search_detail.h"

namespace icacam::vision {

using namespace ring_search_detail;

namespace {

// Whether offsets (pixels beyond an outline, one per ray) lie on one circle rather than
// anywhere: their robust spread within two coarse steps or a quarter of their median.
bool onOneCircle(double *offsets, int n, double step)
{
    if (n < 3) return true;
    std::nth_element(offsets, offsets + n / 2, offsets + n);
    const double mid = offsets[n / 2];
    for (int k = 0; k < n; ++k) offsets[k] = std::fabs(offsets[k] - mid);
    std::nth_element(offsets, offsets + n / 2, offsets + n);
    return 1.4826 * offsets[n / 2] <= std::max(2 * step, 0.25 * mid);
}

// On a derivative row d of count samples with the outline at sample `at`: the outline's own
// step is the strongest within the derivative's reach of it (which may be a highlight's flank
// just inside); a rival is an extremum of its sign at least half as strong beyond that reach
// of the outline itself, up to sample end, so that the outline's own step is not one.
bool rivalBeyond(const int32_t *d, int count, int at, int end)
{
    if (at < 2 || at > count - 3) return false;
    int k = at;
    for (int j = std::max(2, at - 2); j <= std::min(count - 3, at + 2); ++j)
        if (std::abs(d[j]) > std::abs(d[k])) k = j;
    const int32_t outline = d[k];
    if (outline == 0) return false;
    for (int j = std::max(k, at) + 3; j <= std::min(end, count - 3); ++j)
        if (isExtremum(d, j) && (d[j] > 0) == (outline > 0) && 2 * std::abs(d[j]) >= std::abs(outline)) return true;
    return false;
}

// Whether a ray's step at sample `at` (its detector w samples a side) is a bright line's outer
// flank: the w samples inside it rise above both the barrel band from barrelFrom to 2w inside
// it (its median) and the w samples beyond, by kMinLineRise and by twice the band's own step
// to beyond.
bool stepOnHighlight(const uint16_t *row, int barrelFrom, int at, int w)
{
    const int to = at - 2 * w;
    if (to - barrelFrom < w) return false;
    double nearSum = 0, outSum = 0;
    for (int j = at - w; j < at; ++j) nearSum += row[j];
    for (int j = at + 1; j <= at + w; ++j) outSum += row[j];
    const double near = nearSum / w, out = outSum / w;
    if (near - out < kMinLineRise) return false; // no brighter than beyond it: no line
    uint16_t band[kMaxCoarse];
    int nb = 0;
    for (int j = barrelFrom; j <= to; ++j) band[nb++] = row[j];
    std::nth_element(band, band + nb / 2, band + nb);
    const double level = band[nb / 2];
    const double rise = near - std::max(level, out);
    return rise >= kMinLineRise && rise >= 2 * std::fabs(level - out);
}

// The silhouette's fit as the geometry reports it; its equivalent radius.
double outlineTaken(const BoundaryFit &fit, EndFaceGeometry *m)
{
    m->silhouetteCoverage = fit.coverage;
    m->silhouetteScatterPx = fit.scatterPx;
    m->silhouetteCentreX = fit.centreX;
    m->silhouetteCentreY = fit.centreY;
    return fit.rEqPx;
}

// No silhouette: the geometry reports none of a fit.
void noOutlineTaken(EndFaceGeometry *m)
{
    m->silhouetteCoverage = m->silhouetteScatterPx = 0;
    m->silhouetteCentreX = m->silhouetteCentreY = 0;
}

} // namespace

bool RingSearch::outlineRivalled(double rMaxPx) const
{
    // The fixture's shadow around the foot is a second step of the outline's sign outside
    // it (lit fixture beyond a dark shadow beyond a dark barrel): where the mean profile
    // shows one at least half as strong within a third of R0, the step taken for the
    // outline could be either.
    const double rA = kCoarseStart * r0, step = coarseStep(r0);
    const int count = coarseCount(r0);
    return rivalBeyond(meanDeriv, count, int((rMaxPx - rA) / step + 0.5), int((rMaxPx + r0 / 3 - rA) / step));
}

void RingSearch::outlineAlignedMean(const double *outlineR, int from, int n, double *mean) const
{
    const double rA = kCoarseStart * r0, step = coarseStep(r0);
    const int count = coarseCount(r0);
    for (int k = 0; k < n; ++k) {
        double sum = 0;
        int used = 0;
        for (int i = 0; i < kCoarseRays; ++i) {
            const double at = (outlineR[i] - rA) / step + (k + from);
            const int j = int(std::floor(at));
            const uint16_t *row = coarse + size_t(i) * kMaxCoarse;
            if (j < 0 || j + 1 >= count || row[j] == kOutsideFrame || row[j + 1] == kOutsideFrame) continue;
            sum += row[j] + (at - j) * (row[j + 1] - row[j]);
            ++used;
        }
        mean[k] = 4 * used >= kCoarseRays ? sum / used : -1;
    }
}

bool RingSearch::outlineRivalledAlong(const double *outlineR) const
{
    // The same on the coarse rays' mean with each ray aligned on the fitted outline
    // (outlineR: its radius at each coarse ray about the coarse centre), so that an outline
    // whose centre the view drew aside shows as the one step it is.
    constexpr int kInside = 6;
    const double step = coarseStep(r0);
    const int span = std::min(kMaxCoarse, kInside + int(r0 / 3 / step) + 4);
    double aligned[kMaxCoarse];
    outlineAlignedMean(outlineR, -kInside, span, aligned);
    uint16_t mean[kMaxCoarse];
    int32_t d[kMaxCoarse];
    for (int k = 0; k < span; ++k) mean[k] = aligned[k] >= 0 ? uint16_t(aligned[k] + 0.5) : kOutsideFrame;
    profileDerivative(mean, span, d);
    return rivalBeyond(d, span, kInside, span - 3);
}

bool RingSearch::highlightsOuterFlank(double rPx, int w) const
{
    // On the mean profile: the levels w samples either side of rPx and 3w inside it. A
    // highlight is brighter than what lies either side of it, by half the step at least.
    const double rA = kCoarseStart * r0, step = coarseStep(r0);
    const int count = coarseCount(r0);
    const int a = int((rPx - rA) / step + 0.5);
    if (a - 3 * w < 0 || a + w >= count) return false;
    const int32_t in = meanProfile[a - w], out = meanProfile[a + w], farIn = meanProfile[a - 3 * w];
    if (in == kOutsideFrame || out == kOutsideFrame || farIn == kOutsideFrame) return false;
    return 2 * (in - farIn) >= in - out && in - out > 0;
}

bool RingSearch::silhouetteOnRay(const uint16_t *row, int lo, int hi, int searchHi, int w, int barrelFrom,
                                 double *atSample, bool *onBound) const
{
    // Running sums from the first sample the detector reads (lo − w): prefix[k] holds
    // Σ row[base … k − 1], so differences are the same as from sample 0.
    int32_t prefix[kMaxCoarse + 1];
    const int wn = std::max(1, w / 4); // the locating detector's half-width
    const int base = lo - w;
    prefix[base] = 0;
    for (int j = base; j <= hi + w; ++j) prefix[j + 1] = prefix[j] + row[j];
    // Step across r: mean of the h samples outside minus the h samples inside (Q8, as sums
    // over h). The inside reads the barrel only: from barrelFrom, beyond the contact edge's
    // blur, its mean scaled to h samples. Reading into the contact edge, the detector would
    // take its tail for an outline at the window's start (at a 2 px step and h = 4, a
    // window 0.04 R0 outside the contact edge reads 4 px inside it).
    auto across = [&](int j, int h) {
        const int from = std::max(j - h, barrelFrom), n = j - from;
        const int32_t sum = prefix[j] - prefix[from];
        const int32_t inside = n == h ? sum : sum * h / n; // a division only where clipped
        return (prefix[j + 1 + h] - prefix[j + 1]) - inside;
    };
    auto stepAt = [&](int j) { return across(j, w); };
    // The same step over wn samples a side: it locates the edge the wide one detects.
    auto narrowAt = [&](int j) { return across(j, wn); };
    // Noise: the step detector's spread over the outer quarter (background, mostly); the
    // narrow one's is that of a sum over wn samples a side rather than w: √(wn/w) of it.
    int32_t tmp[kMaxCoarse];
    int nt = 0;
    for (int j = std::max(lo, hi - (hi - lo) / 4); j <= hi; ++j) tmp[nt++] = std::abs(stepAt(j));
    std::nth_element(tmp, tmp + nt / 2, tmp + nt);
    const double noise = 1.4826 * tmp[nt / 2];
    const double threshold = std::max(3.0 * noise, 4.0 * 256 * w);
    const double narrowThreshold = std::max(3.0 * noise * std::sqrt(double(wn) / w), 4.0 * 256 * wn);
    // From the top down to where the detector's inside first reaches barrelFrom it is never
    // clipped: there the step is the plain difference of two sums (the search's inner loop).
    const int top = std::min(hi, searchHi), unclipped = std::max(lo, barrelFrom + w);
    auto plainStep = [&](int j) { return (prefix[j + 1 + w] - prefix[j + 1]) - (prefix[j] - prefix[j - w]); };
    int j = top;
    while (j >= unclipped && std::abs(plainStep(j)) < threshold) --j;
    if (j < unclipped) {
        j = std::min(top, unclipped - 1);
        while (j >= lo && std::abs(stepAt(j)) < threshold) --j;
    }
    if (j < lo) return false;
    // The outermost clear step lies within w samples inside where the wide detector
    // first sees it. A highlight band on the barrel just inside its outline is a
    // stronger step of the same sign, and the wide detector's peak would slide onto
    // its flank (1–2 % short): the edge is the narrow detector's strongest peak over
    // those w samples. Only where the narrow one sees nothing clear there does the
    // wide one's own peak stand.
    const int sign = stepAt(j) > 0 ? 1 : -1;
    int best = -1;
    int32_t bestA = 0;
    for (int k = std::min(hi - 1, j + 1); k >= std::max(lo + 1, j - w); --k) {
        const int32_t a = sign * narrowAt(k);
        if (a > bestA && a >= sign * narrowAt(k - 1) && a >= sign * narrowAt(k + 1)) {
            best = k;
            bestA = a;
        }
    }
    if (bestA < narrowThreshold) best = -1;
    double offset = 0;
    if (best >= 0) {
        offset = parabolaVertex(sign * narrowAt(best - 1), sign * narrowAt(best), sign * narrowAt(best + 1)).toDouble();
    } else {
        best = j;
        while (best - 1 >= lo && std::abs(stepAt(best - 1)) >= std::abs(stepAt(best))) --best;
    }
    // The detectors are centred on sample k (samples k + 1 … against … k − 1).
    *atSample = best + offset;
    *onBound = best == lo;
    return true;
}

bool RingSearch::barrelBandLopsided(const double *radius, const bool *valid, const double *outerR) const
{
    // Least squares of width = w0 + a cos θ + b sin θ over the coarse rays with a silhouette.
    constexpr int kCoarse = kCoarseRays;
    double n = 0, sc = 0, ss = 0, scc = 0, sss = 0, scs = 0, sw = 0, swc = 0, sws = 0;
    for (int i = 0; i < kCoarse; ++i) {
        if (!valid[i]) continue;
        const int fineIdx = i * (rays_ / kCoarse);
        const double c = rayCos_[fineIdx], sn = raySin_[fineIdx];
        const double width = radius[i] - (outerR[fineIdx] + (cx - coarseCx_) * c + (cy - coarseCy_) * sn);
        n += 1, sc += c, ss += sn, scc += c * c, sss += sn * sn, scs += c * sn;
        sw += width, swc += width * c, sws += width * sn;
    }
    // Solve the 3 × 3 normal equations by Cramer's rule.
    const double m[3][3] = {{n, sc, ss}, {sc, scc, scs}, {ss, scs, sss}};
    auto det3 = [](const double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double det = det3(m);
    if (!(n >= 8 && std::fabs(det) > 1e-9)) return false;
    const double rhs[3] = {sw, swc, sws};
    double sol[3];
    for (int k = 0; k < 3; ++k) {
        double mk[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) mk[r][c] = c == k ? rhs[r] : m[r][c];
        sol[k] = det3(mk) / det;
    }
    return !(sol[0] > 0) || std::hypot(sol[1], sol[2]) > 0.5 * sol[0];
}

void RingSearch::outlineInsideRivals(OutlineRays *rays) const
{
    // Around the foot the ring light's shadow on the fixture is a second step of the
    // outline's sign beyond it (a lit fixture beyond the shadow's dark lobes), and on the rays
    // that cross a lobe's edge it is the outermost clear step: those rays read the outline
    // tens of pixels out (the reference photographs photo-003 and photo-004: a third of the
    // rays, 10–65 px beyond the rest, a silhouette 2–8 px large with a scatter of 7–13 px).
    // Where most rays agree on an outline, the rays far beyond it are searched again inside
    // it: the outline is the barrel's own step there too, and where a ray shows none it is
    // left out.
    constexpr int kCoarse = kCoarseRays;
    const double rA = kCoarseStart * r0, step = coarseStep(r0);
    double *radius = rays->radius;
    bool *valid = rays->valid;
    double sorted[kCoarse];
    int n = 0;
    for (int i = 0; i < kCoarse; ++i)
        if (valid[i]) sorted[n++] = radius[i];
    if (n < 16) return;
    std::nth_element(sorted, sorted + n / 2, sorted + n);
    const double median = sorted[n / 2];
    // Where most rays take the outer flank of a highlight line on the barrel (a drawn
    // barrel's: a band brighter than either side), the rays beyond may be the ones that see
    // the faint outline behind it (the development set's devset-016: 11 of 64 rays, 8–16 px
    // out): they are left to the fit.
    if (highlightsOuterFlank(median, rays->w)) return;
    // The rays that agree: within a twentieth of R0 of the median (wider than an outline
    // drawn towards the axis by a close camera's perspective, a few pixels).
    const double agree = std::max(4 * step, 0.05 * r0);
    bool core[kCoarse];
    int nCore = 0;
    for (int i = 0; i < kCoarse; ++i) nCore += core[i] = valid[i] && std::fabs(radius[i] - median) <= agree;
    if (2 * nCore < n + 1 || nCore == n) return;
    BoundaryFit fit;
    FitOptions opt;
    opt.maxHarmonics = 1;
    opt.minRejectPx = 2.0;
    double curve[kCoarse];
    if (!fitBoundary(radius, core, kCoarse, coarseCx_, coarseCy_, opt, &fit, curve)) return;
    const double tol = std::max({3 * step, 3 * fit.scatterPx, 0.02 * r0});
    // The fixture's shading lies anywhere beyond the outline: its rays scatter over tens of
    // pixels. Rays that agree on one circle beyond it see a second boundary (a drawn
    // background's ring), which the fit weighs as before.
    double beyond[kCoarse];
    int nBeyond = 0;
    for (int i = 0; i < kCoarse; ++i)
        if (valid[i] && radius[i] > curve[i] + tol) beyond[nBeyond++] = radius[i] - curve[i];
    if (nBeyond == 0 || onOneCircle(beyond, nBeyond, step)) return;
    for (int i = 0; i < kCoarse; ++i) {
        if (!valid[i] || radius[i] <= curve[i] + tol) continue;
        const uint16_t *row = coarse + size_t(i) * kMaxCoarse;
        const int searchHi = int((curve[i] + tol - rA) / step);
        double at = 0;
        valid[i] = searchHi > rays->lo[i] &&
                   silhouetteOnRay(row, rays->lo[i], rays->hi, searchHi, rays->w, rays->barrelFrom[i], &at,
                                   &rays->onBound[i]) &&
                   std::fabs(rA + at * step - curve[i]) <= tol;
        if (valid[i]) radius[i] = rA + at * step;
    }
}

double RingSearch::silhouetteFromRays(const double *outerR, double blurPx, EndFaceGeometry *m, double *outlineR,
                                      OutlineRaysSeen *seenBy)
{
    *seenBy = OutlineRaysSeen{};
    noOutlineTaken(m);
    constexpr int kCoarse = kCoarseRays;
    const double rA = kCoarseStart * r0;
    const double step = coarseStep(r0);
    const int count = coarseCount(r0);
    OutlineRays rays{};
    rays.w = std::max(4, int(0.035 * r0 / step)); // step detector half-width
    rays.hi = count - rays.w - 2;
    const int w = rays.w, hi = rays.hi;
    double *radius = rays.radius;
    bool *valid = rays.valid;
    // Rays whose step is a highlight line's flank did not see the outline beyond it; where
    // fewer than half do, the others did (a faint outline, clear on some rays only), and the
    // line's rays are left out. Where most do, the line is what the fit finds, and
    // outlineBeyondHighlight reads the outline beyond it.
    bool onLine[kCoarse];
    int seen = 0, lines = 0;
    for (int i = 0; i < kCoarse; ++i) {
        valid[i] = onLine[i] = false;
        const uint16_t *row = coarse + size_t(i) * kMaxCoarse;
        if (anyOutsideFrame(row, count)) continue; // a ray leaving the frame is not used
        // The contact edge's radius seen from the coarse rays' centre (to first order in
        // the contact edge's centre offset).
        const int fineIdx = i * (rays_ / kCoarse);
        const double ro = outerR[fineIdx] + (cx - coarseCx_) * rayCos_[fineIdx] + (cy - coarseCy_) * raySin_[fineIdx];
        // The barrel begins beyond the contact edge's blur (three of its σ, at least 2 px).
        const int barrelFrom = std::max(0, int(std::ceil((ro + std::max(2.0, 3 * blurPx) - rA) / step)));
        const int lo = std::max({w, int((ro + 0.04 * r0 - rA) / step), barrelFrom + 1});
        if (hi - lo < 2 * w) continue;
        ++seenBy->searched;
        rays.lo[i] = lo, rays.barrelFrom[i] = std::max(barrelFrom, lo - w);
        double at = 0;
        if (silhouetteOnRay(row, lo, hi, hi, w, rays.barrelFrom[i], &at, &rays.onBound[i])) {
            radius[i] = rA + at * step;
            valid[i] = true;
            ++seen;
            lines += onLine[i] = stepOnHighlight(row, rays.barrelFrom[i], int(at + 0.5), w);
        }
    }
    seenBy->linesSeen = lines > 0;
    seenBy->stepped = seen;
    if (lines > 0 && 2 * lines < seen)
        for (int i = 0; i < kCoarse; ++i) valid[i] = valid[i] && !onLine[i];
    outlineInsideRivals(&rays);
    // Seen straight on, the barrel shows as a band of even width outside the contact edge.
    // Seen obliquely (a tilted camera, or one close enough that the rays fan out by tens of
    // degrees), it shows wide on the side facing the camera and hides behind the end face on
    // the far side: what bounds the specimen there is the contact edge itself, and no circle
    // through it is the barrel's widest one. A band whose width swings by more than half its
    // mean around the ring is not taken.
    if (barrelBandLopsided(radius, valid, outerR)) {
        seenBy->lopsided = true;
        return 0;
    }
    // A step still rising where the search ends, just outside the contact edge, is an outline
    // that close to it or the barrel's shading falling off from the contact edge onto a dark
    // fixture (rendered photographs: a lit barrel on a black fixture, its step at the bound
    // on 48–61 of 64 rays and the outline's centre, drawn towards the axis by the view, read
    // on the contact edge's). Where it is so on half the rays or more, the rays show no
    // outline of their own, and the view has no silhouette (an oblique view's hidden side, the
    // band ending on the contact edge, is told above).
    int found = 0, onBound = 0;
    for (int i = 0; i < kCoarse; ++i)
        if (valid[i]) ++found, onBound += rays.onBound[i];
    if (found > 0 && 2 * onBound >= found) return 0;
    BoundaryFit fit;
    FitOptions opt;
    opt.maxHarmonics = 2;
    opt.minRejectPx = 2.0;
    // Beyond the outline the fixture's texture and shading step by a few grey levels too, and
    // the outermost clear step on a ray can be one of them: on a reference photograph (a dark
    // barrel 75 grey levels below a light fixture) a fresh draw of 1 grey level of sensor
    // noise took such steps 10–50 px beyond the outline on 18 of 64 rays. Through them the
    // least-squares fit's scatter read 7.8 px instead of 0.4 and its radius 0.8 % short,
    // which the reading took for a scale 1.9 % off (μ 0.013 low, warn). The rays far from
    // the others' median radius are left out before the first fit.
    opt.medianRejectSigma = opt.rejectSigma;
    if (!fitBoundary(radius, valid, kCoarse, coarseCx_, coarseCy_, opt, &fit, outlineR) || fit.coverage < 0.4) {
        seenBy->faint = true;
        return 0;
    }
    return outlineTaken(fit, m);
}

double RingSearch::silhouetteFromSectors(double rMeanPx, EndFaceGeometry *m, double *outlineR) const
{
    // A step of a few grey levels in a noisy frame (a dark barrel on a dark fixture) clears
    // the step detector on a few rays only, while the mean profile shows it. Pooled over a
    // sector's rays, each about its middle ray so that the sectors keep the rays' even
    // spacing, the step stands out of the pooled noise near where the mean profile places it.
    // Searched over a few samples only, it needs three times the derivative's noise (the mean
    // profile's free search, six); half the sectors must show it, round about the specimen
    // (the fit's robust rejection): a shadow lobe or a highlight's flank does not.
    constexpr int kPerSector = kCoarseRays / kOutlineSectors, kHalf = kPerSector / 2;
    const double rA = kCoarseStart * r0, step = coarseStep(r0);
    const int count = coarseCount(r0);
    const int at = int((rMeanPx - rA) / step + 0.5);
    const int reach = std::max(3, int(0.03 * r0 / step + 0.5));
    if (at - reach < 3 || at + reach > count - 4) return 0;
    // The outline's step's sign, as the mean profile shows it there.
    const int32_t around = meanDeriv[at - 1] + meanDeriv[at] + meanDeriv[at + 1];
    if (around == 0) return 0;
    const int sign = around > 0 ? 1 : -1;
    double radius[kOutlineSectors];
    bool valid[kOutlineSectors];
    for (int s = 0; s < kOutlineSectors; ++s) {
        valid[s] = false;
        uint32_t sum[kMaxCoarse];
        std::fill_n(sum, count, 0u);
        bool inside = true;
        for (int k = -kHalf; k <= kHalf && inside; ++k) {
            const uint16_t *row = coarse + size_t((s * kPerSector + k + kCoarseRays) % kCoarseRays) * kMaxCoarse;
            inside = !anyOutsideFrame(row, count);
            for (int j = 0; j < count && inside; ++j) sum[j] += row[j];
        }
        if (!inside) continue;
        constexpr uint32_t n = 2 * kHalf + 1;
        uint16_t pooled[kMaxCoarse];
        for (int j = 0; j < count; ++j) pooled[j] = uint16_t((sum[j] + n / 2) / n);
        int32_t d[kMaxCoarse];
        profileDerivative(pooled, count, d);
        const EdgePeak p = strongestEdge(d, count, at - reach, at + reach, sign, true);
        if (!p.found || p.value < kSectorOutlineSigmas * derivativeNoise(pooled, count)) continue;
        radius[s] = rA + p.position.toDouble() * step;
        valid[s] = true;
    }
    BoundaryFit fit;
    FitOptions opt;
    opt.maxHarmonics = 1;
    opt.minRejectPx = 2.0;
    // The pooled peaks of a real outline lie on one circle to the coarse rays' own step; peaks
    // that noise or a ragged edge placed near the mean profile's radius scatter beyond it.
    if (!fitBoundary(radius, valid, kOutlineSectors, coarseCx_, coarseCy_, opt, &fit) ||
        fit.coverage < kSectorOutlineCoverage || fit.scatterPx > step)
        return 0;
    double cosT[kCoarseRays], sinT[kCoarseRays];
    for (int i = 0; i < kCoarseRays; ++i) {
        const int fineIdx = i * (rays_ / kCoarseRays);
        cosT[i] = rayCos_[fineIdx], sinT[i] = raySin_[fineIdx];
    }
    radiiAt(fit, cosT, sinT, kCoarseRays, outlineR);
    return outlineTaken(fit, m);
}

RingSearch::HighlightOutline RingSearch::outlineBeyondHighlight(const double *outerR, const double *outlineR,
                                                                double blurPx) const
{
    // Lit along the line of sight, a barrel is darkest at its limb, where its surface turns
    // edge-on to the camera and the ring light; a bright line on it is a highlight where the
    // surface faces the lens, inside the outline. A step found at such a line's outer flank
    // (the coarse rays aligned on it: a peak above both the barrel band inside it and the
    // level beyond) is the highlight's edge, not the barrel's. The outline is then the step
    // from the band's level to the level beyond, outside the line, where the two differ; where
    // they do not, the barrel meets a background of its own shade and shows no outline.
    constexpr int kCoarse = kCoarseRays;
    const double step = coarseStep(r0);
    const int w = std::max(4, int(0.035 * r0 / step));
    const int kOut = w + std::max(4, int(0.06 * r0 / step + 0.5)); // how far beyond the line the outline is sought
    const double barrelFrom = std::max(2.0, 3 * blurPx);
    // How far inside the outline the band reaches on most rays (past the contact edge's blur).
    double span[kCoarse];
    int ns = 0;
    for (int i = 0; i < kCoarse; ++i) {
        const int fineIdx = i * (rays_ / kCoarse);
        const double ro = outerR[fineIdx] + (cx - coarseCx_) * rayCos_[fineIdx] + (cy - coarseCy_) * raySin_[fineIdx];
        span[ns++] = (outlineR[i] - ro - barrelFrom) / step;
    }
    std::nth_element(span, span + ns / 2, span + ns);
    const int kIn = std::min(kMaxCoarse / 2, int(span[ns / 2]));
    HighlightOutline none{};
    if (kIn < 3 * w) return none; // too narrow a band to tell a line inside it
    // The rays' mean aligned on the outline, sample k − kIn at offset k − kIn coarse steps.
    const int n = kIn + kOut + 1;
    double mean[kMaxCoarse];
    outlineAlignedMean(outlineR, -kIn, n, mean);
    for (int k = 0; k < n; ++k)
        if (mean[k] < 0) return none;
    auto median = [&](int a, int b) {
        double tmp[kMaxCoarse];
        int m = 0;
        for (int k = a; k <= b; ++k) tmp[m++] = mean[k];
        std::nth_element(tmp, tmp + m / 2, tmp + m);
        return tmp[m / 2];
    };
    const double band = median(0, kIn - 2 * w), beyond = median(n - 1 - w, n - 1);
    int top = kIn - w;
    for (int k = kIn - w; k <= kIn; ++k)
        if (mean[k] > mean[top]) top = k;
    const double rise = mean[top] - std::max(band, beyond), stepSize = std::fabs(band - beyond);
    if (!(rise >= kMinLineRise && rise >= 2 * stepSize)) return none;
    HighlightOutline h{};
    h.isLine = true;
    if (stepSize < kMinOutlineStep) return h; // the barrel's shade beyond the line is the background's
    // The outline: beyond the line, where the profile crosses half way from the band's level
    // to the level beyond (falling to a darker background; rising to a lighter one after the
    // barrel's dark limb).
    const double half = 0.5 * (band + beyond);
    const bool falls = beyond < band;
    int k = top + 1;
    if (!falls)
        while (k < n - w && mean[k] >= half) ++k;
    for (; k < n - w; ++k) {
        if ((mean[k] < half) == falls) {
            const double f = (mean[k - 1] - half) / (mean[k - 1] - mean[k]);
            h.shiftPx = (k - 1 + f - kIn) * step;
            h.found = true;
            return h;
        }
    }
    return h;
}

double RingSearch::settleOutline(const MeanEdges &me, const double *outerR, double blurPx, bool lopsided,
                                 bool onLineSuspected, double perRay, double *outlineR, EndFaceGeometry *m) const
{
    // A step read on a highlight line's outer flank is the line's, not the barrel's: the
    // outline is the step beyond it, or none (outlineBeyondHighlight).
    if (perRay > 0) {
        if (onLineSuspected) {
            const HighlightOutline h = outlineBeyondHighlight(outerR, outlineR, blurPx);
            if (h.isLine && h.found) {
                perRay += h.shiftPx;
                for (int i = 0; i < kCoarseRays; ++i) outlineR[i] += h.shiftPx;
            } else if (h.isLine) {
                perRay = 0;
                noOutlineTaken(m);
            }
        }
        m->rMaxPx = perRay;
        return perRay;
    }
    // A barrel fading down its ramp into a dark fixture steps down fastest inside its outline:
    // where the rays show none, the drop at the ramp's foot is not taken for it.
    if (lopsided || me.kneeOnRamp || !(me.rMax > 0)) {
        m->rMaxPx = 0;
        return 0;
    }
    std::fill_n(outlineR, kCoarseRays, me.rMax);
    const HighlightOutline h = outlineBeyondHighlight(outerR, outlineR, blurPx);
    m->rMaxPx = !h.isLine ? me.rMax : h.found ? me.rMax + h.shiftPx : 0;
    return 0;
}

} // namespace icacam::vision
