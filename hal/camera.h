#pragma once
// The camera seam. configure() once with the largest frame the program will accept; then
// capture() hands out one frame at a time. The frame's memory belongs to the camera and stays
// valid until the next capture() (the way libcamera recycles its request buffers).
#include <cstdint>
#include <string>

#include "hal/error.h"
#include "vision/luma_view.h"

namespace icacam::hal {

struct CameraFormat {
    vision::PixelFormat format = vision::PixelFormat::Grey8;
    int maxWidth = 0;
    int maxHeight = 0;
};

struct CapturedFrame {
    vision::FrameView view;
    int64_t timestampMs = 0; // monotonic time of the exposure (Clock::monotonicMs)
    std::string source;      // where it came from (file name, sensor model), for the journal
};

class Camera {
public:
    virtual ~Camera() = default;
    // Allocates buffers for frames up to the given size. Errors: Invalid, BadFormat, Io.
    virtual Error configure(const CameraFormat &fmt) = 0;
    // Captures one frame, waiting at most timeoutMs. Errors: Timeout, BadFormat (a frame
    // of another format), BadStride, TooLarge, Io. Never blocks longer than timeoutMs.
    virtual Error capture(int timeoutMs, CapturedFrame *out) = 0;
};

} // namespace icacam::hal
