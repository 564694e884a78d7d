#include "vision/end_face_analyzer.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>

#include "vision/boundary_fit.h"
#include "vision/contact_tilt.h"
#include "vision/edge_profile.h"
#include "vision/radial_profile.h"
#include "vision/ring_search.h"
#include "vision/segment_bearing.h"
#include "vision/specimen_locator.h"

namespace icacam::vision {

namespace {
template <typename T> T *carve(uint8_t *&p, size_t count)
{
    T *out = reinterpret_cast<T *>(p);
    p += (count * sizeof(T) + 15) & ~size_t(15);
    return out;
}

// Walking out from inside the end face, the first clear step of either sign is the original
// face's edge or the contact edge, both on the end face's plane; the outline, often the
// strongest (a dark barrel against a lit fixture), lies beyond them. A quarter of the
// strongest: the original face's edge steps 30–50 grey levels where the outline steps 80
// (rendered photographs).
constexpr int kInnermostDivisor = 4;
// The tilt profile's search about the single frame's contact edge (pixels, and of R0).
constexpr double kTiltReachMinPx = 10, kTiltReachOfR0 = 0.1, kTiltBeyondPx = 10;
// The tilt's knee model's own error (pixels), and within how many of the knee's σ it confirms
// the single frame's contact edge, beyond how many it moves it.
constexpr double kTiltKneeModelPx = 1.0, kTiltConfirmSigmas = 1.5, kTiltMoveSigmas = 3.0;
constexpr double kTiltCleanMisfit = 0.02;
// A segment 0 seen this far from where it is said to be: the tilt weighs every segment by
// cos of the error, so 30° costs it an eighth of its step; further is a ring mounted turned
// (the photographic bench's segment sets: segment 0 seen within 13° of where it was rendered
// on 108 of 114 records, the other 6 too evenly lit to tell).
constexpr double kSegmentBearingToleranceDeg = 30;
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

// Two passes of rays at the coarse Hough centre: the strongest edge on each ray (usually
// the contact edge or the silhouette, both circles about the specimen's axis), a robust
// first-harmonic fit, and the centre moved by the fitted offset.
bool EndFaceAnalyzer::refineCentre(const LumaView &v, double r0Px, double *cx, double *cy)
{
    // Pass 1: the strongest edge on each of 32 rays at 2 px steps. The Hough centre can be a
    // cell or two off (a distractor circle in the fixture pulls the votes): while the fit
    // still moves the centre by more than 6 % of the radius, the rays are cast again from the
    // moved centre (rarely more than once).
    if (!centreByRays(v, r0Px, RayEdge::Strongest, std::max(3.0, 0.06 * r0Px), cx, cy)) return false;
    // Pass 2: 64 rays about the refined centre, kept for the mean profile and the
    // silhouette (the fine stage's contact-edge fit absorbs what offset remains).
    castCoarseRays(v, r0Px, *cx, *cy);
    return true;
}

bool EndFaceAnalyzer::centreByRays(const LumaView &v, double r0Px, RayEdge edge, double settlePx, double *cx,
                                   double *cy)
{
    int32_t d[kMaxCoarseSamples];
    double radius[kCoarseRays];
    bool valid[kCoarseRays];
    const double rA = kCoarseStart * r0Px, rB = kCoarseEnd * r0Px;
    for (int iteration = 0; iteration < 3; ++iteration) {
        const int rays = kCoarseRays / 2;
        // Coarser than the kept pass: a centre, not a profile, is wanted (2–4 px, about
        // 1.5 % of the radius, far below the edges' spacing).
        const double step = std::max({2.0, std::min(4.0, 0.015 * r0Px), (rB - rA) / kMaxCoarseSamples});
        const int count = std::min(kMaxCoarseSamples, int((rB - rA) / step));
        const RaySpec along{Q16_16::fromDouble(*cx), Q16_16::fromDouble(*cy), {}, {},
                            Q16_16::fromDouble(rA),  Q16_16::fromDouble(step)};
        for (int i = 0; i < rays; ++i) {
            RaySpec ray = along;
            rayDirection(i, rays, &ray.cosT, &ray.sinT);
            uint16_t *row = coarse_ + size_t(i) * kMaxCoarseSamples;
            sampleRay(v, ray, count, row);
            profileDerivative(row, count, d);
            const EdgePeak e = edge == RayEdge::Strongest
                                   ? strongestEdgeEitherSign(d, count, 2, count - 3)
                                   : innermostClearEdge(d, count, 2, count - 3, 0, kInnermostDivisor);
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
        if (moved < settlePx) break;
    }
    return true;
}

void EndFaceAnalyzer::castCoarseRays(const LumaView &v, double r0Px, double cx, double cy)
{
    const double rA = kCoarseStart * r0Px;
    const double step = coarseStep(r0Px);
    const int count = coarseCount(r0Px);
    const RaySpec along{Q16_16::fromDouble(cx), Q16_16::fromDouble(cy),  {}, {},
                        Q16_16::fromDouble(rA), Q16_16::fromDouble(step)};
    for (int i = 0; i < kCoarseRays; ++i) {
        RaySpec ray = along;
        rayDirection(i, kCoarseRays, &ray.cosT, &ray.sinT);
        sampleRay(v, ray, count, coarse_ + size_t(i) * kMaxCoarseSamples);
    }
}

EndFaceGeometry EndFaceAnalyzer::measure(const LumaView &v, const FaceSearch &face)
{
    EndFaceGeometry m;
    m.frameWidth = v.width;
    m.frameHeight = v.height;
    auto fail = [&m](ErrorCode c) {
        m.error = c;
        return m;
    };
    if (!arena_) return fail(ErrorCode::NotConfigured);
    if (!v.valid()) return fail(ErrorCode::BadFrame);
    if (v.width > maxWidth_ || v.height > maxHeight_) return fail(ErrorCode::FrameTooLarge);
    const double mmPerPx = face.mmPerPx;
    if (!(mmPerPx > 1e-5 && mmPerPx < 10) || !(face.d0Mm > 0.5 && face.d0Mm < 500)) return fail(ErrorCode::BadSpecimen);
    const double r0 = 0.5 * face.d0Mm / mmPerPx; // initial radius in pixels
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

    RingSearch search{&v, r0, cx, cy, coarse_, fine_, deriv_, meanProfile_, meanDeriv_, innerPts_, outerPts_};
    search.toneGamma = face.toneGamma;
    ErrorCode e = search.run(&m);
    // A tilted camera sees the barrel wide on the side facing it and not at all on the far
    // side, where the contact edge bounds the specimen: the strongest edge on each ray is the
    // outline on one side and the contact edge on the other, and their fit's centre lies off
    // the end face's by up to the barrel band's width (rendered photographs tilted 6–14°: up
    // to 21 px). About it the mean profile smears the end face's edges, and the search may
    // find no original face's edge. The end face's own centre is that of the innermost clear
    // edge on each ray; where it lies more than max(3 px, 3 % R0) away, the end face is
    // searched again about it, as a view that sees the barrel on one side (the first search's
    // answer stands where that one finds nothing either).
    // Another search about (sx, sy) with the coarse rays cast from there; its answer is
    // taken where it finds the ring.
    auto searchAgain = [&](double sx, double sy, bool oblique, bool beyondDrop) {
        castCoarseRays(v, r0, sx, sy);
        EndFaceGeometry about;
        about.frameWidth = v.width;
        about.frameHeight = v.height;
        about.centreX = sx;
        about.centreY = sy;
        search =
            RingSearch{&v, r0, sx, sy, coarse_, fine_, deriv_, meanProfile_, meanDeriv_, innerPts_, outerPts_, oblique};
        search.toneGamma = face.toneGamma;
        if ((beyondDrop ? search.runBeyondDrop(&about) : search.run(&about)) != ErrorCode::None) return;
        m = about;
        e = ErrorCode::None;
    };
    if (e == ErrorCode::InnerEdgeNotFound) {
        double fx = cx, fy = cy;
        if (centreByRays(v, r0, RayEdge::Innermost, 1.0, &fx, &fy) &&
            std::hypot(fx - cx, fy - cy) > std::max(3.0, 0.03 * r0))
            searchAgain(fx, fy, true, false);
    }
    // Last, a ring a few pixels wide darker (or lighter) than both the face and the barrel's
    // lit shoulder beyond it: the coarse step sees one drop, the face's edge, with no
    // original face's edge inside it, and the profile steps straight back beyond it.
    if (e == ErrorCode::InnerEdgeNotFound) searchAgain(cx, cy, false, true);
    if (e != ErrorCode::None) return fail(e);
    m.error = ErrorCode::None;
    if (face.litInTurn) contactEdgeFromTilt(*face.litInTurn, v, r0, &m);
    return m;
}

void EndFaceAnalyzer::contactEdgeFromTilt(const LitInTurn &lit, const LumaView &v, double r0Px, EndFaceGeometry *m)
{
    for (int k = 0; k < lit.count; ++k)
        if (lit.segment[k].width != v.width || lit.segment[k].height != v.height || !lit.segment[k].valid()) return;
    // The segments light from where they are said to (a ring mounted turned, or its lines
    // listed the other way round, weighs the wrong frames: no tilt is read from them). Read
    // over the barrel and the fixture beyond it, to 1.3 R_max (R_max about 1.1 R_o at 50 %).
    const double reachPx = 1.3 * (m->rMaxPx > 0 ? m->rMaxPx : 1.1 * m->outer.rEqPx);
    const SegmentBearings b = segmentBearings(lit, m->centreX, m->centreY, m->outer.rEqPx, reachPx);
    if (b.found) {
        m->segment0SeenDeg = b.segment0Deg;
        m->segmentWay = b.way;
        if (b.way < 0 || bearingOffsetDeg(b, lit.azimuth0Deg) > kSegmentBearingToleranceDeg) {
            m->imageFlags |= kImageSegmentsMisplaced;
            return;
        }
    }
    // The optics' blur: the original face's edge, a step in the finish alone, where measured.
    const double blurPx = m->innerEdgeWidthPx > 0 ? m->innerEdgeWidthPx : m->edgeWidthPx > 0 ? m->edgeWidthPx : 1.0;
    // From as far inside as the single frame's steepest fall lies beyond the flat face's end
    // on a long lit shoulder (rendered flat-sided barrels: up to 0.1 R0), never across the
    // original face's edge; to a few pixels beyond it, where a step read too soon ends.
    const double ringPx = m->outer.rEqPx - m->inner.rEqPx;
    const double innerPx = std::min(std::max(kTiltReachMinPx, kTiltReachOfR0 * r0Px), ringPx - 2.5 * blurPx);
    const TiltEdge t = contactEdgeByTilt(lit, m->outer, m->centreX, m->centreY, innerPx, kTiltBeyondPx, blurPx);
    if (!t.found) return;
    // The knee's error: its fit's and the knee model's own on a barrel curving away, whose
    // tilt grows gently from the edge (640 × 480 photographs: knees −2.5 … +1.8 px about the
    // contact edge, σ about 1 px). Within 1.5 σ of the single frame's contact edge the tilt
    // confirms it: the flat face ends there, and the edge stands. Beyond 3 σ the single frame
    // read a fall on the barrel (or short of the flat face's end) and the edge moves to the
    // knee. Between, neither is sure: the edge stands, and the reading says so.
    const double sigma = std::hypot(t.sigmaPx, kTiltKneeModelPx);
    m->tiltKneePx = t.shiftPx;
    // Only a clean knee moves the edge: turning marks whose ripple the smoothing left (the
    // knee model's residual beyond 2 % of the step; clean knees 0.3–1.4 %) move the knee by a
    // fraction of their period (a 1456 × 1088 ring of 15 px with 8 px marks: 4 px).
    if (std::fabs(t.shiftPx) > kTiltMoveSigmas * sigma && t.misfit <= kTiltCleanMisfit) {
        m->outer.a0 += t.shiftPx;
        m->outer.rEqPx += t.shiftPx;
        m->tiltSigmaPx = sigma;
        m->imageFlags |= kImageContactEdgeByTilt;
    } else if (std::fabs(t.shiftPx) <= kTiltConfirmSigmas * sigma) {
        m->tiltSigmaPx = sigma;
        m->imageFlags |= kImageTiltConfirms;
    } else {
        m->imageFlags |= kImageTiltDisagrees;
    }
}

} // namespace icacam::vision
