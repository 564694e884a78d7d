// The seam between the camera's frame (hal::FrameView) and vision's luma view: a frame from
// the HAL gives the same luma as the same bytes handed to vision::lumaOf directly.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "firmware/frame_luma.h"

using namespace icacam;

namespace {

constexpr int kW = 6, kH = 4;

std::vector<uint8_t> pattern(size_t n)
{
    std::vector<uint8_t> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = uint8_t(i * 37 + 11);
    return v;
}

TEST(FrameLuma, ViewsInPlaceFormatsWithoutCopying)
{
    const std::vector<uint8_t> px = pattern(size_t(2 * kW + 4) * kH * 2);
    const struct {
        hal::PixelFormat format;
        int stride, step;
    } cases[] = {{hal::PixelFormat::Grey8, kW + 2, 1},
                 {hal::PixelFormat::NV12, kW, 1},
                 {hal::PixelFormat::YUV420, kW, 1},
                 {hal::PixelFormat::YUYV, 2 * kW + 4, 2}};
    for (const auto &c : cases) {
        const hal::FrameView f{c.format, px.data(), kW, kH, c.stride, px.size()};
        vision::LumaView luma;
        ASSERT_EQ(fw::frameLuma(f, nullptr, 0, &luma), vision::ErrorCode::None) << int(c.format);
        EXPECT_EQ(luma.data, px.data());
        EXPECT_EQ(luma.width, kW);
        EXPECT_EQ(luma.height, kH);
        EXPECT_EQ(luma.stride, c.stride);
        EXPECT_EQ(luma.pixelStep, c.step);
    }
}

TEST(FrameLuma, ConvertsPackedRgbAsVisionDoes)
{
    const struct {
        hal::PixelFormat hal;
        vision::PixelFormat vision;
        int bytesPerPixel;
    } cases[] = {{hal::PixelFormat::RGB24, vision::PixelFormat::RGB24, 3},
                 {hal::PixelFormat::BGR24, vision::PixelFormat::BGR24, 3},
                 {hal::PixelFormat::XRGB32, vision::PixelFormat::XRGB32, 4}};
    for (const auto &c : cases) {
        const int stride = kW * c.bytesPerPixel + 2;
        const std::vector<uint8_t> px = pattern(size_t(stride) * kH);
        std::vector<uint8_t> got(kW * kH), want(kW * kH);
        vision::LumaView a, b;
        ASSERT_EQ(fw::frameLuma({c.hal, px.data(), kW, kH, stride, px.size()}, got.data(), got.size(), &a),
                  vision::ErrorCode::None);
        ASSERT_EQ(vision::lumaOf({c.vision, px.data(), kW, kH, stride, px.size()}, want.data(), want.size(), &b),
                  vision::ErrorCode::None);
        EXPECT_EQ(a.data, got.data());
        EXPECT_EQ(got, want) << int(c.hal);
    }
}

TEST(FrameLuma, RefusesWhatVisionRefuses)
{
    const std::vector<uint8_t> px = pattern(size_t(3 * kW) * kH);
    vision::LumaView luma;
    // Fewer bytes than the geometry needs.
    EXPECT_EQ(fw::frameLuma({hal::PixelFormat::Grey8, px.data(), kW, kH, kW, size_t(kW * kH - 1)}, nullptr, 0, &luma),
              vision::ErrorCode::BadFrame);
    // A converted format without room for its luma.
    std::vector<uint8_t> scratch(kW * kH - 1);
    EXPECT_EQ(fw::frameLuma({hal::PixelFormat::RGB24, px.data(), kW, kH, 3 * kW, px.size()}, scratch.data(),
                            scratch.size(), &luma),
              vision::ErrorCode::FrameTooLarge);
}

} // namespace
