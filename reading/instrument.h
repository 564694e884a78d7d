#pragma once
// The instrument: one object that turns a frame and what the lab declared into a reading.
// The device, `icacam measure` and `icacam loop` each hold one. It owns the pipeline's
// working memory (sized once in configure()), the friction model, and the camera's
// calibration with the frame size it is valid for; read() allocates nothing.
#include <cstddef>
#include <string>

#include "friction/friction_model.h"
#include "reading/reading.h"
#include "reading/specimen_spec.h"
#include "vision/contact_tilt.h"
#include "vision/end_face_analyzer.h"
#include "vision/luma_view.h"
#include "vision/plane_calibration.h"

namespace icacam::reading {

class Instrument {
public:
    Instrument() = default;
    Instrument(const Instrument &) = delete;
    Instrument &operator=(const Instrument &) = delete;

    // Working memory for frames up to maxWidth × maxHeight, and the model every reading uses.
    // ErrorCode::None, or why not (BadFrame for a non-positive size, FrameTooLarge when the
    // memory cannot be had).
    ErrorCode configure(int maxWidth, int maxHeight, const friction::FrictionModel &model);
    void setModel(const friction::FrictionModel &model) { model_ = &model; }
    const friction::FrictionModel &model() const { return *model_; }
    size_t workingBytes() const { return analyzer_.workingBytes(); }

    // The camera's calibration (docs/calibration.md), valid for frames of imageWidth ×
    // imageHeight: each boundary is then mapped into the end-face plane at the specimen's
    // final height, and the spec's scale only sizes the search. nullptr: none.
    void setCalibration(const vision::PlaneCalibration *plane, int imageWidth, int imageHeight);
    bool calibrated() const { return calibrated_; }
    // "" when a frame of this size can be read, else why not in words.
    std::string frameSizeIssue(int width, int height) const;

    // Measures the frame and interprets it; with segment frames of the same view (the ring
    // light lit in turn, vision/contact_tilt.h) the contact edge is where the surface's tilt
    // says the flat face ends. The reading's point arrays stay valid until the next read().
    Reading read(const vision::LumaView &frame, const SpecimenSpec &spec, const vision::LitInTurn *lit = nullptr);
    // The interpretation alone, of geometry measured earlier or of radii measured elsewhere.
    Reading interpret(const vision::EndFaceGeometry &geometry, const SpecimenSpec &spec) const;
    Reading interpret(const FaceInMm &face, const SpecimenSpec &spec) const;

    // Where the pipeline looks for the end face in a frame of this size: the spec's scale, or
    // with a calibration and no scale the calibration's at the image centre.
    vision::FaceSearch searchFor(const SpecimenSpec &spec, int width, int height) const;

private:
    vision::EndFaceAnalyzer analyzer_;
    const friction::FrictionModel *model_ = nullptr;
    vision::PlaneCalibration plane_;
    bool calibrated_ = false;
    int calibrationWidth_ = 0, calibrationHeight_ = 0;
};

} // namespace icacam::reading
