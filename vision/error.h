#pragma once
// Errors as values (no exceptions in vision/): a named code and a fixed human message.
#include <cstdint>

namespace icacam::vision {

enum class ErrorCode : uint8_t {
    None = 0,
    NotConfigured,     // measure() before configure()
    FrameTooLarge,     // frame exceeds the configured maximum
    BadFrame,          // null data, zero size, stride smaller than width
    BadSpecimen,       // scale or specimen size missing or not physical
    NoSpecimen,        // nothing circular of the expected size in the frame
    Saturated,         // the end face is clipped at full scale
    TooDark,           // the end face has no usable signal
    OuterEdgeNotFound, // the contact edge (ICA / barrel) was not found around the ring
    InnerEdgeNotFound, // the original face edge (face / ICA) was not found
    Blurred,           // edges too wide to locate the ring
    InconsistentRing,  // found edges are not ordered R_i < R_o < R_max
    CalibrationSize,   // the frame's size differs from the calibration's images
};

const char *errorName(ErrorCode c);
const char *errorMessage(ErrorCode c);

} // namespace icacam::vision
