#include "vision/end_face_analyzer.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>

#include "vision/boundary_fit.h"
#include "vision/edge_profile.h"
#include "vision/radial_profile.h"
#include "vision/ring_search.h"
#include "vision/specimen_locator.h"

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
    const size_t bytes = SpecimenLocator::kWorkBytes + 16 + (size_t(kCoarseRays) * kMaxCoarseSamples * 2 + 16) +
                         2 * (size_t(kFineRays) * kMaxFineSamples * 2 + 16) + 2 * (size_t(kMaxCoarseSamples) * 4 + 16) +
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

// Rays from the coarse Hough centre: the strongest edge on each ray (usually the contact edge
// or the silhouette, both circles about the specimen's axis), a robust first-harmonic fit,
// and the centre moved by the fitted offset, until it settles; then the kept pass.
bool EndFaceAnalyzer::refineCentre(const LumaView &v, double r0Px, double *cx, double *cy)
{
    int32_t d[kMaxCoarseSamples];
    double radius[kCoarseRays];
    bool valid[kCoarseRays];
    const double rA = kCoarseStart * r0Px, rB = kCoarseEnd * r0Px;
    // Every later stage samples its rays from this centre, so it must not depend on where the
    // search began: the rays are cast again from the moved centre until the fit moves it by
    // less than kCentreTolPx, a fixed point of the fit whatever the start within the
    // locator's cell (a start a cell or two off, where a distractor circle in the fixture
    // pulled the votes, takes a few more casts).
    constexpr double kCentreTolPx = 0.005;
    constexpr int kMaxCasts = 12;
    const int rays = kCoarseRays / 2;
    // Coarser than the kept pass: a centre, not a profile, is wanted (2–4 px, about 1.5 % of
    // the radius, far below the edges' spacing).
    const double step = std::max({2.0, std::min(4.0, 0.015 * r0Px), (rB - rA) / kMaxCoarseSamples});
    const int count = std::min(kMaxCoarseSamples, int((rB - rA) / step));
    // Once the centre is within a few pixels (the fit moved it by less than 6 % of the
    // radius), the rays search only a window about the edge the fit follows: the strongest
    // edge of a whole ray may be another boundary on a few rays, and which rays those are
    // changes with the centre, so the fit would have more than one fixed point.
    double around = 0;         // the followed edge's mean radius (0: whole rays)
    constexpr int kWindow = 4; // samples either side of it
    for (int cast = 0; cast < kMaxCasts; ++cast) {
        // The window's samples lie on the whole rays' grid (from rA): the parabola's bias
        // between samples then depends on the centre alone, not on where the window began.
        const int first = around > 0 ? std::max(0, int((around - rA) / step) - kWindow - 3) : 0;
        const double from = rA + first * step;
        const int n = around > 0 ? 2 * kWindow + 7 : count;
        for (int i = 0; i < rays; ++i) {
            RaySpec ray{Q16_16::fromDouble(*cx),  Q16_16::fromDouble(*cy), {}, {},
                        Q16_16::fromDouble(from), Q16_16::fromDouble(step)};
            rayDirection(i, rays, &ray.cosT, &ray.sinT);
            uint16_t *row = coarse_ + size_t(i) * kMaxCoarseSamples;
            sampleRay(v, ray, n, row);
            profileDerivative(row, n, d);
            const EdgePeak e = strongestEdgeEitherSign(d, n, 2, n - 3);
            valid[i] = e.found;
            radius[i] = from + e.position.toDouble() * step;
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
        if (around == 0 && moved < std::max(3.0, 0.06 * r0Px)) around = fit.a0;
        if (moved < kCentreTolPx) break;
    }
    // Pass 2: 64 rays about the refined centre, kept for the mean profile and the
    // silhouette (the fine stage's contact-edge fit absorbs what offset remains).
    const double keptStep = coarseStep(r0Px);
    const int keptCount = std::min(kMaxCoarseSamples, int((rB - rA) / keptStep));
    for (int i = 0; i < kCoarseRays; ++i) {
        RaySpec ray{Q16_16::fromDouble(*cx), Q16_16::fromDouble(*cy),     {}, {},
                    Q16_16::fromDouble(rA),  Q16_16::fromDouble(keptStep)};
        rayDirection(i, kCoarseRays, &ray.cosT, &ray.sinT);
        sampleRay(v, ray, keptCount, coarse_ + size_t(i) * kMaxCoarseSamples);
    }
    return true;
}

ErrorCode EndFaceAnalyzer::checkInputs(const LumaView &v, const FaceSearch &face, double *r0Px) const
{
    if (!arena_) return ErrorCode::NotConfigured;
    if (!v.valid()) return ErrorCode::BadFrame;
    if (v.width > maxWidth_ || v.height > maxHeight_) return ErrorCode::FrameTooLarge;
    const double mmPerPx = face.mmPerPx;
    if (!(mmPerPx > 1e-5 && mmPerPx < 10) || !(face.d0Mm > 0.5 && face.d0Mm < 500)) return ErrorCode::BadSpecimen;
    *r0Px = 0.5 * face.d0Mm / mmPerPx; // initial radius in pixels
    if (*r0Px < 15 || *r0Px > 4 * std::max(v.width, v.height)) return ErrorCode::BadSpecimen;
    return ErrorCode::None;
}

EndFaceGeometry EndFaceAnalyzer::measure(const LumaView &v, const FaceSearch &face)
{
    EndFaceGeometry m;
    double r0 = 0;
    if ((m.error = checkInputs(v, face, &r0)) != ErrorCode::None) return m;
    SpecimenLocator locator(locatorWork_);
    const CentreEstimate coarse = locator.locate(v, 0.8 * r0, 1.8 * r0);
    // A specimen's concentric edges stack hundreds of votes on one cell; a textured
    // background spreads them evenly. (Each voter votes at every other radius: 20 votes
    // here are 40 of a vote at every radius.)
    if (!coarse.found || coarse.votes * 100 < 12 * coarse.background || coarse.votes < 20) {
        m.error = ErrorCode::NoSpecimen;
        return m;
    }
    return measureAbout(v, r0, coarse.x, coarse.y);
}

EndFaceGeometry EndFaceAnalyzer::measureFrom(const LumaView &v, const FaceSearch &face, double startX, double startY)
{
    EndFaceGeometry m;
    double r0 = 0;
    if ((m.error = checkInputs(v, face, &r0)) != ErrorCode::None) return m;
    return measureAbout(v, r0, startX, startY);
}

EndFaceGeometry EndFaceAnalyzer::measureAbout(const LumaView &v, double r0, double startX, double startY)
{
    EndFaceGeometry m;
    double cx = startX, cy = startY;
    if (!refineCentre(v, r0, &cx, &cy)) {
        m.error = ErrorCode::NoSpecimen;
        return m;
    }
    m.centreX = cx;
    m.centreY = cy;

    RingSearch search{&v, r0, cx, cy, coarse_, fine_, deriv_, meanProfile_, meanDeriv_, innerPts_, outerPts_};
    const ErrorCode e = search.run(&m);
    m.error = e;
    return m;
}

} // namespace icacam::vision
