#include "firmware/frame_luma.h"

namespace icacam::fw {

namespace {

// The two enumerations name the same formats with the same values, so a frame crosses the
// seam as it is.
template <hal::PixelFormat H, vision::PixelFormat V> constexpr bool kSame = uint8_t(H) == uint8_t(V);
static_assert(kSame<hal::PixelFormat::Grey8, vision::PixelFormat::Grey8>);
static_assert(kSame<hal::PixelFormat::RGB24, vision::PixelFormat::RGB24>);
static_assert(kSame<hal::PixelFormat::BGR24, vision::PixelFormat::BGR24>);
static_assert(kSame<hal::PixelFormat::XRGB32, vision::PixelFormat::XRGB32>);
static_assert(kSame<hal::PixelFormat::YUYV, vision::PixelFormat::YUYV>);
static_assert(kSame<hal::PixelFormat::NV12, vision::PixelFormat::NV12>);
static_assert(kSame<hal::PixelFormat::YUV420, vision::PixelFormat::YUV420>);

vision::FrameView visionFrame(const hal::FrameView &f)
{
    return {static_cast<vision::PixelFormat>(f.format), f.data, f.width, f.height, f.stride, f.bytes};
}

} // namespace

vision::ErrorCode frameLuma(const hal::FrameView &frame, uint8_t *scratch, size_t scratchBytes, vision::LumaView *out)
{
    return vision::lumaOf(visionFrame(frame), scratch, scratchBytes, out);
}

} // namespace icacam::fw
