// The ring's two edges in linear light: a camera's tone curve draws a blurred edge's
// derivative peak towards its dark side (vision/tone_curve.h), by up to 0.4 px at the blurs
// and contrasts of rendered photographs, in opposite directions on the two edges where the
// ring is the darker or the lighter zone: u reads up to 0.7 px wide or narrow by polarity.
#include "vision/ring_search.h"

#include <algorithm>
#include <cmath>

#include "vision/ring_search_detail.h"
#include "vision/tone_curve.h"

namespace icacam::vision {

using namespace ring_search_detail;

namespace {

// The mean level of the aligned profile's samples from..to (offsets from its edge sample, in
// samples), those off the frame left out; 0 where none is on it.
double meanLevel(const RingSearch::AlignedProfile &p, int from, int to)
{
    double sum = 0;
    int n = 0;
    for (int k = p.K + from; k <= p.K + to; ++k)
        if (k >= 0 && k < p.count() && p.level[k] > 0) sum += p.level[k], ++n;
    return n ? sum / n : 0;
}

// How far the edge the profile is aligned on lies inside (negative) or outside the edge the
// optics drew: its levels read from 2.5 blurs to reachPx either side of it.
double toneOffset(const RingSearch::AlignedProfile &p, double blurPx, double reachPx, double gamma)
{
    const int near = int(std::ceil(2.5 * blurPx / kFineStepPx));
    const int far = std::max(near + 1, int(reachPx / kFineStepPx));
    const double in = meanLevel(p, -far, -near), out = meanLevel(p, near, far);
    const double shift = toneEdgeShiftPx(std::min(in, out), std::max(in, out), blurPx, gamma, kLocatorBlurSq);
    // The peak lies on the dark side: outside where the profile falls outwards.
    return out < in ? shift : -shift;
}

} // namespace

void RingSearch::shiftBoundary(double offsetPx, BoundaryFit *fit, EdgeSample *pts) const
{
    fit->a0 += offsetPx;
    fit->rEqPx += offsetPx;
    for (int i = 0; i < rays_; ++i) {
        const double r = pts[i].radius.toDouble() + offsetPx;
        pts[i].radius = Q16_16::fromDouble(r);
        pts[i].x = Q16_16::fromDouble(cx + r * rayCos_[i]);
        pts[i].y = Q16_16::fromDouble(cy + r * raySin_[i]);
    }
}

void RingSearch::undoToneCurve(const AlignedProfile &atInner, const AlignedProfile &atOuter, double blurPx,
                               double reachPx, bool outerAtKnee, BoundaryFit *inner, BoundaryFit *outer)
{
    shiftBoundary(-toneOffset(atInner, blurPx, reachPx, toneGamma), inner, innerPts);
    // A knee is where the ring's level ends, not a step's steepest point: left as fitted.
    if (!outerAtKnee) shiftBoundary(-toneOffset(atOuter, blurPx, reachPx, toneGamma), outer, outerPts);
}

} // namespace icacam::vision
