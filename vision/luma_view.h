#pragma once
// A non-owning view of an 8-bit luma plane, and the converters from the formats cameras
// deliver. Grey, NV12, YUV420 and YUYV are viewed in place (YUYV through a pixel step of
// 2); only packed RGB needs a conversion, into a buffer the caller sized at start-up.
#include <cstddef>
#include <cstdint>

#include "vision/error.h"

namespace icacam::vision {

struct LumaView {
    const uint8_t *data = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;    // bytes between rows
    int pixelStep = 1; // bytes between neighbouring pixels in a row (2 for YUYV)

    uint8_t at(int x, int y) const { return data[size_t(y) * size_t(stride) + size_t(x) * size_t(pixelStep)]; }
    bool valid() const { return data && width > 0 && height > 0 && pixelStep >= 1 && stride >= width * pixelStep; }
};

enum class PixelFormat : uint8_t { Grey8, RGB24, BGR24, XRGB32, YUYV, NV12, YUV420 };

// One frame as the camera delivers it. Planar formats give the luma plane first.
struct FrameView {
    PixelFormat format = PixelFormat::Grey8;
    const uint8_t *data = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;   // bytes per row of the first plane
    size_t bytes = 0; // bytes available from data (checked against the format's needs)
};

// Bytes a converted luma plane needs for a frame of this size (0 for in-place formats).
size_t lumaScratchBytes(PixelFormat f, int width, int height);

// Returns a view of the frame's luma. In-place formats ignore `scratch`; RGB formats
// write BT.601 luma into it (fixed-point weights 77/150/29, sum 256). Errors: BadFrame
// when the geometry does not fit the bytes given, FrameTooLarge when scratch is short.
ErrorCode lumaOf(const FrameView &frame, uint8_t *scratch, size_t scratchBytes, LumaView *out);

} // namespace icacam::vision
