#include "end_face_analyzer.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>

#include "boundary_fit.h"
#include "radial_profile.h"
#include "model/radii_consistency.h"
#include "ring_search.h"

namespace icacam::vision {

namespace {
template <typename T> T *carve(uint8_t *&p, size_t count)
{
    T *out = reinterpret_cast<T *>(p);
    p += (count * sizeof(T) + 15) & ~size_t(15);
    return out;
}
} // namespace

ErrorCode EndFaceAnalyzer::configure(int maxWidth, int maxHeight)
{
    if (maxWidth <= 0 || maxHeight <= 0) return ErrorCode::BadFrame;
    maxWidth_ = maxWidth;
    maxHeight_ = maxHeight;
    const size_t bytes = SpecimenLocator::kWorkBytes + 16 +
                         (size_t(kCoarseRays) * kMaxCoarseSamples * 2 + 16) +
                         2 * (size_t(kFineRays) * kMaxFineSamples * 2 + 16) +
                         2 * (size_t(kMaxCoarseSamples) * 4 + 16) +
                         2 * (size_t(kFineRays) * sizeof(EdgeSample) + 16);
    arena_.reset(new (std::nothrow) uint8_t[bytes]);
    if (!arena_) return ErrorCode::FrameTooLarge;
    workBytes_ = bytes;
    uint8_t *p = arena_.get();
    locatorWork_ = carve<uint8_t>(p, SpecimenLocator::kWorkBytes);
    coarse_ = carve<uint16_t>(p, size_t(kCoarseRays) * kMaxCoarseSamples);
    fine_ = carve<uint16_t>(p, size_t(kFineRays) * kMaxFineSamples);
    deriv_ = carve<int16_t>(p, size_t(kFineRays) * kMaxFineSamples);
    meanProfile_ = carve<int32_t>(p, kMaxCoarseSamples);
    meanDeriv_ = carve<int32_t>(p, kMaxCoarseSamples);
    innerPts_ = carve<EdgeSample>(p, kFineRays);
    outerPts_ = carve<EdgeSample>(p, kFineRays);
    return ErrorCode::None;
}

// Two passes of rays at the coarse Hough centre: the strongest edge on each ray (usually
// the contact edge or the silhouette, both circles about the specimen's axis), a robust
// first-harmonic fit, and the centre moved by the fitted offset.
bool EndFaceAnalyzer::refineCentre(const LumaView &v, double r0Px, double *cx, double *cy)
{
    // Pass 1: the strongest edge on each of 32 rays at 2 px steps (usually the contact edge
    // or the silhouette, both circles about the specimen's axis), a robust first-harmonic
    // fit, and the centre moved by the fitted offset.
    int32_t d[kMaxCoarseSamples];
    double radius[kCoarseRays];
    bool valid[kCoarseRays];
    const double rA = kCoarseStart * r0Px, rB = kCoarseEnd * r0Px;
    // The Hough centre can be a cell or two off (a distractor circle in the fixture pulls
    // the votes): while the fit still moves the centre by more than 6 % of the radius, the
    // rays are cast again from the moved centre (rarely more than once).
    for (int iteration = 0; iteration < 3; ++iteration) {
        const int rays = kCoarseRays / 2;
        // Coarser than the kept pass: a centre, not a profile, is wanted (2–4 px, about
        // 1.5 % of the radius, far below the edges' spacing).
        const double step = std::max({2.0, std::min(4.0, 0.015 * r0Px), (rB - rA) / kMaxCoarseSamples});
        const int count = std::min(kMaxCoarseSamples, int((rB - rA) / step));
        for (int i = 0; i < rays; ++i) {
            RaySpec ray{Q16_16::fromDouble(*cx), Q16_16::fromDouble(*cy), {}, {},
                        Q16_16::fromDouble(rA), Q16_16::fromDouble(step)};
            rayDirection(i, rays, &ray.cosT, &ray.sinT);
            uint16_t *row = coarse_ + size_t(i) * kMaxCoarseSamples;
            sampleRay(v, ray, count, row);
            profileDerivative(row, count, d);
            const EdgePeak up = strongestEdge(d, count, 2, count - 3, +1);
            const EdgePeak down = strongestEdge(d, count, 2, count - 3, -1);
            const EdgePeak &e = up.value > down.value ? up : down;
            valid[i] = e.found;
            radius[i] = rA + e.position.toDouble() * step;
        }
        BoundaryFit fit;
        FitOptions opt;
        opt.maxHarmonics = 1;
        opt.minRejectPx = 2.0;
        if (!fitBoundary(radius, valid, rays, *cx, *cy, opt, &fit)) return false;
        if (fit.coverage < 0.25) return false;
        const double moved = std::hypot(fit.centreX - *cx, fit.centreY - *cy);
        *cx = fit.centreX;
        *cy = fit.centreY;
        if (moved < std::max(3.0, 0.06 * r0Px)) break;
    }
    // Pass 2: 64 rays about the refined centre, kept for the mean profile and the
    // silhouette (the fine stage's contact-edge fit absorbs what offset remains).
    const double step = coarseStep(r0Px);
    const int count = std::min(kMaxCoarseSamples, int((rB - rA) / step));
    for (int i = 0; i < kCoarseRays; ++i) {
        RaySpec ray{Q16_16::fromDouble(*cx), Q16_16::fromDouble(*cy), {}, {},
                    Q16_16::fromDouble(rA), Q16_16::fromDouble(step)};
        rayDirection(i, kCoarseRays, &ray.cosT, &ray.sinT);
        sampleRay(v, ray, count, coarse_ + size_t(i) * kMaxCoarseSamples);
    }
    return true;
}

Measurement EndFaceAnalyzer::measure(const LumaView &v, const SpecimenSpec &spec,
                                     const FrictionModel &model)
{
    Measurement m;
    auto fail = [&m](ErrorCode c) {
        m.status = Status::Error;
        m.error = c;
        return m;
    };
    if (!arena_) return fail(ErrorCode::NotConfigured);
    if (!v.valid()) return fail(ErrorCode::BadFrame);
    if (v.width > maxWidth_ || v.height > maxHeight_) return fail(ErrorCode::FrameTooLarge);
    if (!(spec.mmPerPx > 1e-5 && spec.mmPerPx < 10) || !(spec.d0Mm > 0.5 && spec.d0Mm < 500) ||
        !std::isfinite(spec.n))
        return fail(ErrorCode::BadSpecimen);
    const double r0 = 0.5 * spec.d0Mm / spec.mmPerPx; // initial radius in pixels
    if (r0 < 15 || r0 > 4 * std::max(v.width, v.height)) return fail(ErrorCode::BadSpecimen);

    SpecimenLocator locator(locatorWork_);
    const CentreEstimate coarse = locator.locate(v, 0.8 * r0, 1.8 * r0);
    // A specimen's concentric edges stack hundreds of votes on one cell; a textured
    // background spreads them evenly. (Each voter votes at every other radius: 20 votes
    // here are 40 of a vote at every radius.)
    if (!coarse.found || coarse.votes * 100 < 12 * coarse.background || coarse.votes < 20)
        return fail(ErrorCode::NoSpecimen);
    double cx = coarse.x, cy = coarse.y;
    if (!refineCentre(v, r0, &cx, &cy)) return fail(ErrorCode::NoSpecimen);
    m.centreX = cx;
    m.centreY = cy;

    RingSearch search{&v, r0, cx, cy, coarse_, fine_, deriv_, meanProfile_, meanDeriv_,
                      innerPts_, outerPts_};
    const ErrorCode e = search.run(&m);
    if (e != ErrorCode::None) return fail(e);
    finishResult(spec, model, &m);
    return m;
}

void EndFaceAnalyzer::finishResult(const SpecimenSpec &spec, const FrictionModel &model,
                                   Measurement *m) const
{
    double s = spec.mmPerPx;
    m->rInnerMm = m->inner.rEqPx * s;
    m->rOuterMm = m->outer.rEqPx * s;
    m->rMaxMm = m->rMaxPx * s;
    m->uPx = m->outer.rEqPx - m->inner.rEqPx;
    m->uMm = m->uPx * s;
    double planeOffsetPx = -1;    // centre offset measured in the end-face plane
    bool scaleCalibrated = false;  // the calibration, not R_max, vouches for the scale
    if (spec.calibration) {
        // Each boundary mapped point by point into the end-face plane (undistorted, tilt
        // removed, at the specimen's height); s becomes the contact edge's effective scale
        // for the uncertainties and thresholds below.
        const PlaneOutline pi = planeOutline(m->inner, m->centreX, m->centreY, *spec.calibration);
        const PlaneOutline po = planeOutline(m->outer, m->centreX, m->centreY, *spec.calibration);
        if (!(pi.valid && po.valid && m->outer.rEqPx > 0)) {
            m->status = Status::Error;
            m->error = ErrorCode::BadSpecimen;
            return;
        }
        const double ri = pi.rEqMm, ro = po.rEqMm;
        m->rInnerMm = ri, m->rOuterMm = ro, m->uMm = ro - ri;
        s = ro / m->outer.rEqPx;
        // Tilt and the lens make round boundaries elliptical and shift their centres in the
        // image; the calibration takes both out, so the shape checks below judge the end face
        // itself (ellipticity and axis in the plane, fixture axes), not the camera.
        m->inner.ellipticity = pi.ellipticity, m->inner.axisDeg = pi.axisDeg;
        m->outer.ellipticity = po.ellipticity, m->outer.axisDeg = po.axisDeg;
        planeOffsetPx = std::hypot(pi.centroidX - po.centroidX, pi.centroidY - po.centroidY) / s;
        // The barrel is widest about half-way down: its silhouette maps at half the height.
        BoundaryFit silhouette;
        silhouette.a0 = m->rMaxPx;
        PlaneCalibration mid = *spec.calibration;
        mid.heightMm *= 0.5;
        m->rMaxMm = m->rMaxPx > 0 ? equivalentRadiusMm(silhouette, m->centreX, m->centreY, mid) : 0;
        // R_max is reported but not held against the model: the scale is the calibration's
        // (checked on the device with a reference disc), and a camera close enough to need
        // one sees the barrel obliquely, its widest section partly hidden behind the end
        // face's rim (parallax of the axis between the two heights), so the outline it
        // finds is not R_max (docs/calibration.md: 3-5 % high on the tilted test camera).
        scaleCalibrated = true;
    }
    // Edge location has a floor of about 0.1 px of bias per boundary besides its scatter.
    const double sigPx = std::sqrt(m->inner.rEqSigmaPx * m->inner.rEqSigmaPx +
                                   m->outer.rEqSigmaPx * m->outer.rEqSigmaPx + 2 * 0.1 * 0.1);
    m->uSigmaMm = sigPx * s;

    const ModelEstimate est = model.estimate({m->uMm, spec.n, spec.kMpa, spec.d0Mm, spec.h0Mm, spec.hFinalMm});
    m->mu = est.mu;
    m->muSigma = std::sqrt(est.dMuDu * est.dMuDu * m->uSigmaMm * m->uSigmaMm +
                           est.modelSigma * est.modelSigma);
    uint32_t f = m->flags;
    if (est.range & (kModelNBelow | kModelNAbove)) f |= kFlagNOutOfRange;
    if (est.range & kModelKOutside) f |= kFlagKOutOfRange;
    if (est.range & kModelMuBelow) f |= kFlagMuBelowRange;
    if (est.range & kModelMuAbove) f |= kFlagMuAboveRange;
    if (est.range & kModelUOutside) f |= kFlagUOutsideModel;
    if (est.range & kModelAspectOutside) f |= kFlagAspectOutside;

    const double r0 = 0.5 * spec.d0Mm / s;
    if (std::min(m->inner.coverage, m->outer.coverage) < 0.6) f |= kFlagLowCoverage;
    if (std::max(m->inner.scatterPx, m->outer.scatterPx) > std::max(1.5, 0.006 * r0))
        f |= kFlagHighScatter;
    if (std::fabs(m->inner.contrast) < 5.0) f |= kFlagLowContrast;
    m->centreOffsetPx = planeOffsetPx >= 0 ? planeOffsetPx
                                           : std::hypot(m->inner.centreX - m->outer.centreX,
                                                        m->inner.centreY - m->outer.centreY);
    if (m->centreOffsetPx > std::max(3.0, 0.012 * r0)) f |= kFlagCentreOffset;
    const double axisDiff = std::fabs(std::remainder(m->inner.axisDeg - m->outer.axisDeg, 180.0));
    if (m->inner.ellipticity > 0.012 && m->outer.ellipticity > 0.012 && axisDiff < 20)
        f |= kFlagElliptical;
    if (m->uPx < 3.0) f |= kFlagNarrowRing;
    if (m->edgeWidthPx > 2.6) f |= kFlagBlurred;
    if (m->saturatedFraction > 0.02) f |= kFlagSaturated;
    // Scale and reduction check: the silhouette against the FE's R_max at the measured μ and
    // the declared n, at the declared final height, or at the model's 50 % when none is given
    // (radii_consistency.h). Without a final height a mismatch means the scale or the 50 %
    // is wrong (scale_suspect, with the reduction R_max implies as a diagnostic); with one,
    // the declared scale, n and height cannot all be right (radii_inconsistent).
    if (scaleCalibrated) {
        // Neither scale_suspect nor no_silhouette: see the calibration branch above.
    } else if (m->rMaxPx > 0) {
        const bool declared = spec.hFinalMm > 0 && spec.hFinalMm < spec.h0Mm;
        const double r = declared ? 1.0 - spec.hFinalMm / spec.h0Mm : 0.5;
        const RadiiCheck rc = checkRadii(m->rMaxMm, spec.n, est.mu, spec.d0Mm, r, spec.h0Mm);
        m->rMaxZ = rc.z;
        m->reductionEst = rc.reductionEst;
        if (rc.inconsistent()) f |= declared ? kFlagRadiiInconsistent : kFlagScaleSuspect;
    } else {
        f |= kFlagNoSilhouette;
    }
    // u grows by 0.03–0.08 mm per percent of height reduction near 50 % (FE issue facts):
    // one percent off the model's 50 % already moves μ by more than its uncertainty. A model
    // that carries u to 50 % itself says where its FE data stop.
    if (model.correctsReduction()) {
        if (est.range & kModelReductionOutside) f |= kFlagReductionOutside;
    } else if (spec.hFinalMm > 0 && spec.h0Mm > 0 && std::fabs(1.0 - spec.hFinalMm / spec.h0Mm - 0.5) > 0.01) {
        f |= kFlagReductionOutside;
    }
    m->flags = f;
    m->status = f ? Status::Warn : Status::Ok;
    m->error = ErrorCode::None;
}

} // namespace icacam::vision
