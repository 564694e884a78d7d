#pragma once
// The image half of a measurement: frame → specimen centre → contact edge R_o → original
// face edge R_i → silhouette, in pixels (EndFaceGeometry). All working memory is taken once
// in configure(); measure() allocates nothing and makes no OS call.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "vision/end_face_geometry.h"
#include "vision/luma_view.h"
#include "vision/ray_capacity.h"

namespace icacam::vision {

class EndFaceAnalyzer {
public:
    EndFaceAnalyzer() = default;
    EndFaceAnalyzer(const EndFaceAnalyzer &) = delete;
    EndFaceAnalyzer &operator=(const EndFaceAnalyzer &) = delete;

    // Sizes the working memory for frames up to maxWidth × maxHeight. Returns
    // ErrorCode::None, or BadFrame for a non-positive size. May be called again.
    ErrorCode configure(int maxWidth, int maxHeight);
    size_t workingBytes() const { return workBytes_; }

    // Measures the end face in one frame: its geometry in pixels, or an error. The result's
    // point arrays stay valid until the next call.
    EndFaceGeometry measure(const LumaView &frame, const FaceSearch &search);

private:
    bool refineCentre(const LumaView &v, double r0Px, double *cx, double *cy);
    // Which edge on each ray the centre is fitted to: the strongest (the contact edge or the
    // outline), or the innermost clear one (the original face's edge or the contact edge).
    enum class RayEdge { Strongest, Innermost };
    // Rays from (cx, cy), `edge` on each, a robust first-harmonic fit and the centre moved by
    // its offset, three times at most while it still moves by settlePx or more; false where
    // the fit fails or covers under a quarter of the rays. Uses the coarse rows as scratch.
    bool centreByRays(const LumaView &v, double r0Px, RayEdge edge, double settlePx, double *cx, double *cy);
    // The coarse rays about (cx, cy) that the ring search reads its mean profile from.
    void castCoarseRays(const LumaView &v, double r0Px, double cx, double cy);
    // The contact edge confirmed by the segment frames' tilt or moved to it, or left as the
    // single frame read it where they show no tilt step.
    void contactEdgeFromTilt(const LitInTurn &lit, const LumaView &v, double r0Px, EndFaceGeometry *m);

    int maxWidth_ = 0, maxHeight_ = 0;
    size_t workBytes_ = 0;
    std::unique_ptr<uint8_t[]> arena_;
    uint8_t *locatorWork_ = nullptr;
    uint16_t *coarse_ = nullptr;     // kCoarseRays × kMaxCoarseSamples
    uint16_t *fine_ = nullptr;       // kFineRays × kMaxFineSamples
    int16_t *deriv_ = nullptr;       // kFineRays × kMaxFineSamples derivatives
    int32_t *meanProfile_ = nullptr; // kMaxCoarseSamples
    int32_t *meanDeriv_ = nullptr;   // kMaxCoarseSamples
    EdgeSample *innerPts_ = nullptr; // kFineRays
    EdgeSample *outerPts_ = nullptr; // kFineRays
};

} // namespace icacam::vision
