#include "reading/instrument.h"

#include <cmath>

#include "reading/interpretation.h"

namespace icacam::reading {

ErrorCode Instrument::configure(int maxWidth, int maxHeight, const friction::FrictionModel &model)
{
    model_ = &model;
    return analyzer_.configure(maxWidth, maxHeight);
}

void Instrument::setCalibration(const vision::PlaneCalibration *plane, int imageWidth, int imageHeight)
{
    calibrated_ = plane != nullptr;
    if (plane) plane_ = *plane;
    calibrationWidth_ = imageWidth;
    calibrationHeight_ = imageHeight;
}

std::string Instrument::frameSizeIssue(int width, int height) const
{
    if (!calibrated_ || (width == calibrationWidth_ && height == calibrationHeight_)) return "";
    return "frame is " + std::to_string(width) + "x" + std::to_string(height) + " but the calibration is for " +
           std::to_string(calibrationWidth_) + "x" + std::to_string(calibrationHeight_) + " images";
}

vision::FaceSearch Instrument::searchFor(const SpecimenSpec &spec, int width, int height) const
{
    vision::FaceSearch search{spec.d0Mm, spec.mmPerPx, spec.toneGamma};
    if (!(search.mmPerPx > 0) && calibrated_) {
        // Only a calibration: the search is sized from its scale at the image centre, on a
        // plane at half the initial height.
        vision::PlaneCalibration plane = plane_;
        plane.heightMm = 0.5 * spec.h0Mm;
        search.mmPerPx = planeScaleAt(plane, 0.5 * (width - 1), 0.5 * (height - 1));
    }
    return search;
}

Reading Instrument::read(const vision::LumaView &frame, const SpecimenSpec &spec, const vision::LitInTurn *lit)
{
    Reading out;
    if (!model_) return out;
    if (!std::isfinite(spec.n)) {
        out.error = ErrorCode::BadSpecimen;
        return out;
    }
    if (calibrated_ && (frame.width != calibrationWidth_ || frame.height != calibrationHeight_)) {
        out.error = ErrorCode::CalibrationSize;
        return out;
    }
    vision::FaceSearch search = searchFor(spec, frame.width, frame.height);
    search.litInTurn = lit && lit->count > 0 ? lit : nullptr;
    return interpret(analyzer_.measure(frame, search), spec);
}

Reading Instrument::interpret(const vision::EndFaceGeometry &geometry, const SpecimenSpec &spec) const
{
    return reading::interpret(geometry, spec, calibrated_ ? &plane_ : nullptr, *model_);
}

Reading Instrument::interpret(const FaceInMm &face, const SpecimenSpec &spec) const
{
    return reading::interpret(face, spec, *model_);
}

} // namespace icacam::reading
