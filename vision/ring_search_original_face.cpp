// The original face's edge: named on the aligned profile (which step ends the original face),
// located on every fine ray, or, for a ring too narrow for the rays, fitted on the profile.
#include "vision/ring_search.h"

#include <algorithm>
#include <cmath>

#include "vision/narrow_ring.h"
#include "vision/ring_search_detail.h"

namespace icacam::vision {

using namespace ring_search_detail;

namespace {

// The robust σ of the face's level changes over 4 px, level[0 … to] (0 if too few).
double faceTexture(const int32_t *level, int to)
{
    int32_t change[RingSearch::AlignedProfile::kSpan];
    int n = 0;
    for (int j = 4; j <= to; ++j) change[n++] = level[j] - level[j - 4];
    return n < 8 ? 0 : robustSigma(change, 0, n - 1);
}

// A step across the original face read of this share of its edge's own contrast is an edge of
// its own: the face is one finish. Measured on the mean profile about the centre over the
// drawn and rendered sets (about 2 300 readings), no right reading's face steps by more than
// 0.31 of it over 4 px, while faces read with the specimen's ring inside them step by
// 0.44–0.93 (their original face's edge).
constexpr double kFaceStepShare = 0.4;
constexpr int kFaceLevelSamples = 4, kFaceGapSamples = 2;
// The step stands this many of the face's own step σ out of its texture, over at least this
// many samples of face.
constexpr double kFaceStepNoise = 5.0;
constexpr int kFaceMinSteps = 8;
// The face is read up to this far inside R_i (pixels, or three of the edge's blur σ).
constexpr double kFaceEdgeClearPx = 4.0;

} // namespace

bool RingSearch::faceHoldsEdge(const AlignedProfile &p, double innerAt, double contrastInner, double innerBlurPx)
{
    // The face's level on either side of each sample, over kFaceLevelSamples each, a blur's
    // gap between them: a single bright grain or groove does not make a step.
    const int n = kFaceLevelSamples, gap = kFaceGapSamples;
    const double clear = std::max(kFaceEdgeClearPx, 3 * innerBlurPx) / kFineStepPx;
    const int last = std::min(p.count() - n, int(innerAt - clear) - n + 1);
    int32_t step[AlignedProfile::kSpan];
    int count = 0;
    for (int k = n + gap; k <= last; ++k) {
        int32_t before = 0, after = 0;
        bool onFrame = true;
        for (int j = 0; j < n; ++j) {
            const int32_t a = p.level[k - gap - 1 - j], b = p.level[k + j];
            onFrame = onFrame && a > 0 && b > 0;
            before += a, after += b;
        }
        if (onFrame) step[count++] = after - before;
    }
    if (count < kFaceMinSteps) return false;
    // A share of the edge's contrast, and out of the face's own texture (its σ, the costlier
    // part, only where the share is reached). The texture is read on the steps whose windows
    // do not reach across the largest one: an edge 4 px wide moves a third of a 27-sample
    // face's steps, and their median σ with them (a dark ring read with the face on a
    // JPEG-compressed bench photograph: the step 4.6 σ of a texture it had inflated to
    // 37 grey levels).
    int32_t largest = 0;
    int at = 0;
    for (int k = 0; k < count; ++k)
        if (std::abs(step[k]) > largest) largest = std::abs(step[k]), at = k;
    if (!(largest >= kFaceStepShare * std::fabs(contrastInner) * 256 * n)) return false;
    int32_t texture[AlignedProfile::kSpan];
    int m = 0;
    for (int k = 0; k < count; ++k)
        if (std::abs(k - at) > n + gap) texture[m++] = step[k];
    return largest >=
           kFaceStepNoise * (m >= kFaceMinSteps / 2 ? robustSigma(texture, 0, m - 1) : robustSigma(step, 0, count - 1));
}

RingSearch::OriginalFaceName RingSearch::nameOriginalFace(const AlignedProfile &p) const
{
    // Noise of the aligned derivative on the inner part of the window (mostly original
    // face: the ICA's turning marks would inflate it).
    const int K = p.K;
    const double noise = robustSigma(p.deriv, 0, K / 2);
    const double innerMin = std::max(3.0 * noise, 40.0);
    OriginalFaceName name;
    // The contact edge's own hump of the derivative is not an edge inside it: a barrel
    // ramping away behind the step gives the descent two humps, the step's and the ramp's,
    // and the profile, aligned between them, would otherwise offer the step's hump as the
    // original face's. Walking in from sample K, the hump rises to its top and falls to the
    // valley before the next one, or below a quarter of its top, or to the other sign.
    const int signAtEdge = p.deriv[K] > 0 ? 1 : p.deriv[K] < 0 ? -1 : 0;
    int flank = K;
    if (signAtEdge) {
        int32_t top = signAtEdge * p.deriv[K];
        while (flank > 0 && signAtEdge * p.deriv[flank - 1] >= top) top = signAtEdge * p.deriv[--flank];
        while (flank > 0 && signAtEdge * p.deriv[flank - 1] <= signAtEdge * p.deriv[flank] &&
               4 * signAtEdge * p.deriv[flank - 1] >= top)
            --flank;
    }
    name.flank = flank - K;
    for (int k = -K + 2; k <= std::min(-2, flank - 1 - K); ++k) {
        const int idx = k + K;
        if (!isExtremum(p.deriv, idx) || std::abs(p.deriv[idx]) < innerMin || std::abs(p.deriv[idx]) <= name.strength)
            continue;
        // A real edge separates two levels; a turning mark or a scratch line is a ridge with
        // the same level on both sides. Compare the levels a few pixels either side.
        const int sign = p.deriv[idx] > 0 ? 1 : -1;
        const int g = std::max(2, int(2.5 / kFineStepPx + 0.5));
        const int fa = std::max(0, idx - g - int(8 / kFineStepPx)), fb = std::max(0, idx - g);
        const int ia = std::min(idx + g, K - 2), ib = std::min(idx + g + int(8 / kFineStepPx), K - 2);
        double lf = 0, li = 0;
        int nf = 0, ni = 0;
        for (int j = fa; j <= fb; ++j) {
            lf += p.level[j];
            ++nf;
        }
        for (int j = ia; j <= ib; ++j) {
            li += p.level[j];
            ++ni;
        }
        if (nf && ni && sign * (li / ni - lf / nf) < 0.5 * 256) continue;
        // The face's own texture (turning marks, grain) changes its level from pixel to pixel
        // too: a step no larger than three times its typical change over half the levels'
        // window is a groove's flank, not the edge of a zone (rendered photographs whose face
        // and ring differ by 2 grey levels: a groove read as the original face, μ 0.11 low).
        if (sign * (li / ni - lf / nf) < kTextureSigmas * faceTexture(p.level, idx - g)) continue;
        name.k = k;
        name.strength = std::abs(p.deriv[idx]);
        name.sign = sign;
    }
    return name;
}

bool RingSearch::originalFaceOnRays(OriginalFaceName name, const AlignedProfile &p, const double *outerR,
                                    EndFaceGeometry *m, BoundaryFit *inner, double *innerR, double *contrast)
{
    if (!name.sign) return false;
    const int K = p.K;
    // The derivative names the edge; its position is taken from a box step detector half
    // as wide as the ring (up to 12 px), which turning marks next to the edge cannot pull.
    // On a ring narrower than 12 px a box would reach across the contact edge's blur: there
    // the derivative itself locates the edge (W = 0).
    const int W = -name.k >= 12 ? std::min(-name.k / 2, 12) : 0;
    int32_t boxV = W ? 0 : name.strength;
    if (W) {
        int64_t prefix[AlignedProfile::kSpan + 1];
        prefix[0] = 0;
        for (int k = 0; k < p.count(); ++k) prefix[k + 1] = prefix[k] + p.level[k];
        const int idx0 = name.k + K;
        // The box's outer half ends where the contact edge's fall begins (its derivative's
        // hump, name.flank): a contact edge ramping away falls from several pixels inside its
        // peak, and a box reaching into that fall reads it as the original face's step.
        const int last = std::min({K - 2 - W, K + name.flank - 1 - W, idx0 + W});
        for (int j = std::max(W, idx0 - W); j <= last; ++j) {
            const int64_t diff = (prefix[j + W + 1] - prefix[j + 1]) - (prefix[j] - prefix[j - W]);
            const int32_t v = int32_t(name.sign * diff / (int64_t(W) * 8)); // 1/32 grey
            if (v > boxV) {
                boxV = v;
                name.k = j - K;
            }
        }
    }
    if (boxV <= 0) return false;
    const double uGuess = -name.k * kFineStepPx;
    const double half = std::max(3.0, std::min(0.025 * r0, 0.5 * uGuess));
    const int32_t innerStrength = std::max<int32_t>(W ? 4 : 6, int32_t(0.3 * boxV));
    const double reach = std::max(1.0, std::min(3.0, 0.5 * uGuess));
    // A window following the contact edge at the named offset. The search spans ±half about
    // the guess (pass 2: ±2.5 about the fit); the detector needs W (or 2 for the derivative)
    // more on each side.
    const int pad = std::max(W, 2) + 3;
    const int innerCount = std::min(kMaxFine, int(2 * half) + 2 * pad + 1);
    double start[kRays], lo[kRays], hi[kRays];
    for (int i = 0; i < rays_; ++i) start[i] = outerR[i] - uGuess - half - pad;
    sampleWindow(start, kFineStepPx, innerCount, W, m);
    for (int pass = 0; pass < 2; ++pass) {
        for (int i = 0; i < rays_; ++i) {
            const double ro = outerR[i];
            const double c = pass == 0 ? ro - uGuess : innerR[i];
            const double h = pass == 0 ? half : 2.5;
            lo[i] = c - h;
            hi[i] = std::min(c + h, ro - (W ? 1.0 + W : 2.0));
        }
        if (!locateOnRays(name.sign, 0, lo, hi, innerStrength, pass == 0 ? nullptr : innerPts, true, reach, inner,
                          innerR, contrast) ||
            inner->coverage < 0.25)
            return false;
    }
    return true;
}

bool RingSearch::narrowRingFromProfile(const AlignedProfile &p, int signOuter, double startWidthPx, BoundaryFit *outer,
                                       BoundaryFit *inner, double *contrastInner)
{
    const NarrowRingFit nf = fitNarrowRing(p.level, p.count(), p.K, signOuter, startWidthPx);
    if (!nf.found) return false;
    *inner = *outer;
    outer->a0 += nf.outerPx, outer->rEqPx += nf.outerPx;
    inner->a0 += nf.innerPx, inner->rEqPx += nf.innerPx;
    inner->rEqSigmaPx = nf.sigmaWidthPx;
    inner->used = 0; // no per-ray point: the edge is the profile's
    *contrastInner = nf.innerStep / 256.0;
    for (int i = 0; i < rays_; ++i) innerPts[i].valid = false;
    return true;
}

} // namespace icacam::vision
