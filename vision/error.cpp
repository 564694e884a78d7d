// Stable names and messages for errors: they appear in CSV, JSON and on serial.
#include "vision/error.h"

namespace icacam::vision {

const char *errorName(ErrorCode c)
{
    switch (c) {
    case ErrorCode::None: return "none";
    case ErrorCode::NotConfigured: return "not_configured";
    case ErrorCode::FrameTooLarge: return "frame_too_large";
    case ErrorCode::BadFrame: return "bad_frame";
    case ErrorCode::BadSpecimen: return "bad_specimen";
    case ErrorCode::NoSpecimen: return "no_specimen";
    case ErrorCode::Saturated: return "saturated";
    case ErrorCode::TooDark: return "too_dark";
    case ErrorCode::OuterEdgeNotFound: return "outer_edge_not_found";
    case ErrorCode::InnerEdgeNotFound: return "inner_edge_not_found";
    case ErrorCode::Blurred: return "blurred";
    case ErrorCode::InconsistentRing: return "inconsistent_ring";
    case ErrorCode::CalibrationSize: return "calibration_size";
    }
    return "unknown";
}

const char *errorMessage(ErrorCode c)
{
    switch (c) {
    case ErrorCode::None: return "";
    case ErrorCode::NotConfigured: return "vision pipeline not configured";
    case ErrorCode::FrameTooLarge: return "frame larger than the configured maximum";
    case ErrorCode::BadFrame: return "frame is empty or its size and stride do not fit";
    case ErrorCode::BadSpecimen: return "scale or specimen size not usable (check mm_per_px and d0_mm)";
    case ErrorCode::NoSpecimen: return "no specimen: no end face of the expected size in the image";
    case ErrorCode::Saturated: return "image saturated: the end face is clipped at full brightness";
    case ErrorCode::TooDark: return "image too dark to find the end face";
    case ErrorCode::OuterEdgeNotFound: return "outer edge (contact edge R_o) not found";
    case ErrorCode::InnerEdgeNotFound: return "inner edge (original face R_i) not found";
    case ErrorCode::Blurred: return "image too blurred to resolve the contact ring";
    case ErrorCode::InconsistentRing: return "edges found are not in the order face < contact edge < silhouette";
    case ErrorCode::CalibrationSize: return "frame size differs from the calibration's image size";
    }
    return "unknown error";
}

} // namespace icacam::vision
