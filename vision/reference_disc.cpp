#include "vision/reference_disc.h"

#include <algorithm>
#include <cmath>

#include "vision/boundary_fit.h"
#include "vision/edge_profile.h"
#include "vision/radial_profile.h"

namespace icacam::vision {

namespace {

// One pass of rays about (cx, cy) from rA outwards; each ray's strongest edge of the given
// polarity (+1: brighter outwards, a dark disc). Returns the polarity's summed strength.
int64_t edgeRadii(const LumaView &v, double cx, double cy, double rA, double step, int count, int sign, double *radius,
                  bool *valid)
{
    uint16_t samples[ReferenceDiscFinder::kMaxSamples];
    int32_t d[ReferenceDiscFinder::kMaxSamples];
    int64_t total = 0;
    for (int i = 0; i < ReferenceDiscFinder::kRays; ++i) {
        RaySpec ray{Q16_16::fromDouble(cx), Q16_16::fromDouble(cy),  {}, {},
                    Q16_16::fromDouble(rA), Q16_16::fromDouble(step)};
        rayDirection(i, ReferenceDiscFinder::kRays, &ray.cosT, &ray.sinT);
        sampleRay(v, ray, count, samples);
        profileDerivative(samples, count, d);
        const EdgePeak e = strongestEdge(d, count, 2, count - 3, sign, true);
        valid[i] = e.found;
        radius[i] = rA + e.position.toDouble() * step;
        if (e.found) total += e.value;
    }
    return total;
}

} // namespace

DiscFit ReferenceDiscFinder::find(const LumaView &v, double radiusPx) const
{
    DiscFit out;
    if (!v.valid()) return out.error = ErrorCode::BadFrame, out;
    if (!(radiusPx >= 15 && radiusPx <= 0.75 * std::max(v.width, v.height)))
        return out.error = ErrorCode::BadSpecimen, out;
    SpecimenLocator locator(work_);
    const CentreEstimate c = locator.locate(v, (1 - kRadiusSpan) * radiusPx, (1 + kRadiusSpan) * radiusPx);
    // The same evidence the analyzer asks of a specimen: a peak well above the background.
    if (!c.found || c.votes * 100 < 12 * c.background || c.votes < 40) return out.error = ErrorCode::NoSpecimen, out;

    const double rA = (1 - kRadiusSpan) * radiusPx, span = 2 * kRadiusSpan * radiusPx;
    const double step = std::max(0.5, span / kMaxSamples);
    const int count = std::min(kMaxSamples, int(span / step));
    double cx = c.x, cy = c.y;
    double radius[kRays];
    bool valid[kRays];
    BoundaryFit fit;
    // Three passes: the polarity and a first centre, then the edge about the refined centre
    // (rays across an off-centre circle meet it obliquely), then once more to settle.
    int sign = +1;
    for (int pass = 0; pass < 3; ++pass) {
        if (pass == 0) {
            double rd[kRays];
            bool vd[kRays];
            const int64_t dark = edgeRadii(v, cx, cy, rA, step, count, +1, rd, vd);
            const int64_t bright = edgeRadii(v, cx, cy, rA, step, count, -1, radius, valid);
            if (dark >= bright) {
                std::copy(rd, rd + kRays, radius);
                std::copy(vd, vd + kRays, valid);
            } else {
                sign = -1;
            }
        } else {
            edgeRadii(v, cx, cy, rA, step, count, sign, radius, valid);
        }
        FitOptions opt;
        opt.maxHarmonics = 4;
        if (!fitBoundary(radius, valid, kRays, cx, cy, opt, &fit) || fit.coverage < 0.6)
            return out.error = ErrorCode::OuterEdgeNotFound, out;
        if (pass < 2) cx = fit.centreX, cy = fit.centreY;
    }
    out.edge = fit;
    out.centreX = cx, out.centreY = cy;
    out.error = ErrorCode::None;
    return out;
}

} // namespace icacam::vision
