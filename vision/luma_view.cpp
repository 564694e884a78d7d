#include "vision/luma_view.h"

namespace icacam::vision {

namespace {

int bytesPerPixel(PixelFormat f)
{
    switch (f) {
    case PixelFormat::RGB24:
    case PixelFormat::BGR24: return 3;
    case PixelFormat::XRGB32: return 4;
    case PixelFormat::YUYV: return 2;
    default: return 1;
    }
}

// Total bytes the format needs from the first byte, given the luma stride.
size_t bytesNeeded(const FrameView &f)
{
    const size_t rows = size_t(f.height);
    const size_t stride = size_t(f.stride);
    const size_t lastRow = size_t(f.width) * size_t(bytesPerPixel(f.format));
    const size_t luma = (rows - 1) * stride + lastRow;
    switch (f.format) {
    case PixelFormat::NV12: return rows * stride + ((rows + 1) / 2 - 1) * stride + size_t(f.width);
    case PixelFormat::YUV420: return rows * stride + 2 * ((rows + 1) / 2) * ((stride + 1) / 2);
    default: return luma;
    }
}

} // namespace

size_t lumaScratchBytes(PixelFormat f, int width, int height)
{
    switch (f) {
    case PixelFormat::RGB24:
    case PixelFormat::BGR24:
    case PixelFormat::XRGB32: return size_t(width) * size_t(height);
    default: return 0;
    }
}

ErrorCode lumaOf(const FrameView &frame, uint8_t *scratch, size_t scratchBytes, LumaView *out)
{
    if (!out || !frame.data || frame.width <= 0 || frame.height <= 0) return ErrorCode::BadFrame;
    const int bpp = bytesPerPixel(frame.format);
    if (frame.stride < frame.width * bpp) return ErrorCode::BadFrame;
    if (frame.bytes < bytesNeeded(frame)) return ErrorCode::BadFrame;

    switch (frame.format) {
    case PixelFormat::Grey8:
    case PixelFormat::NV12:
    case PixelFormat::YUV420: *out = {frame.data, frame.width, frame.height, frame.stride, 1}; return ErrorCode::None;
    case PixelFormat::YUYV: // Y0 U Y1 V: luma at every second byte
        *out = {frame.data, frame.width, frame.height, frame.stride, 2};
        return ErrorCode::None;
    default: break;
    }

    const size_t need = lumaScratchBytes(frame.format, frame.width, frame.height);
    if (!scratch || scratchBytes < need) return ErrorCode::FrameTooLarge;
    // Channel offsets of R, G, B within a pixel.
    int r = 0, g = 1, b = 2;
    if (frame.format == PixelFormat::BGR24) {
        r = 2;
        b = 0;
    }
    if (frame.format == PixelFormat::XRGB32) {
        r = 2;
        g = 1;
        b = 0;
    } // little-endian B G R X
    for (int y = 0; y < frame.height; ++y) {
        const uint8_t *src = frame.data + size_t(y) * size_t(frame.stride);
        uint8_t *dst = scratch + size_t(y) * size_t(frame.width);
        for (int x = 0; x < frame.width; ++x, src += bpp)
            dst[x] = uint8_t((77u * src[r] + 150u * src[g] + 29u * src[b] + 128u) >> 8);
    }
    *out = {scratch, frame.width, frame.height, frame.width, 1};
    return ErrorCode::None;
}

} // namespace icacam::vision
