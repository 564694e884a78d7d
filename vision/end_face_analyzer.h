#pragma once
// The measurement pipeline: frame → specimen centre → contact edge R_o → original face
// edge R_i → silhouette (measureFace), then the interpretation → radii in mm, u, μ ± σ with
// its budget and flags (reading_interpreter.h). All working memory is taken once in
// configure(); measure() allocates nothing and makes no OS call.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "friction/friction_model.h"
#include "vision/edge_profile.h"
#include "vision/luma_view.h"
#include "vision/measurement.h"
#include "vision/plane_calibration.h"
#include "vision/specimen_locator.h"
#include "vision/specimen_spec.h"

namespace icacam::vision {

class EndFaceAnalyzer {
public:
    static constexpr int kCoarseRays = 64;
    static constexpr int kFineRays = 256;
    static constexpr int kMaxCoarseSamples = 1024;
    static constexpr int kMaxFineSamples = 640;
    // Radial span of the coarse rays, in initial radii: from inside the widest ICA's outer
    // edge to beyond the silhouette at 60 % reduction (R0·1.58·1.04 ≈ 1.65 R0).
    static constexpr double kCoarseStart = 0.88, kCoarseEnd = 1.72;
    // Radial step of the coarse rays: 2 px is fine enough to name the edges (the fine stage
    // locates them) and to find the silhouette to a quarter of a percent.
    static double coarseStep(double r0Px)
    {
        const double span = (kCoarseEnd - kCoarseStart) * r0Px;
        return span / 2 > kMaxCoarseSamples ? span / kMaxCoarseSamples : 2.0;
    }

    EndFaceAnalyzer() = default;
    EndFaceAnalyzer(const EndFaceAnalyzer &) = delete;
    EndFaceAnalyzer &operator=(const EndFaceAnalyzer &) = delete;

    // Sizes the working memory for frames up to maxWidth × maxHeight. Returns
    // ErrorCode::None, or BadFrame for a non-positive size. May be called again.
    ErrorCode configure(int maxWidth, int maxHeight);
    size_t workingBytes() const { return workBytes_; }

    // Measures one frame and interprets it (measureFace, then interpretEndFace of
    // reading_interpreter.h). The result's point arrays stay valid until the next call.
    Measurement measure(const LumaView &frame, const SpecimenSpec &spec, const friction::FrictionModel &model);
    // The image half alone: boundaries, silhouette and image-quality flags in pixels, sized
    // by spec's scale (or, with a calibration and no scale, the calibration's at the image
    // centre). Status stays Error with error None when the face was found: interpretEndFace
    // turns it into a reading.
    Measurement measureFace(const LumaView &frame, const SpecimenSpec &spec);

private:
    struct Ring; // transient per-measurement state (on the stack, fixed size)

    bool refineCentre(const LumaView &v, double r0Px, double *cx, double *cy);

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
