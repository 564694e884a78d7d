#include <gtest/gtest.h>

#include <vector>

#include "vision/luma_view.h"

using namespace icacam::vision;

namespace {
FrameView frame(PixelFormat f, const std::vector<uint8_t> &b, int w, int h, int stride)
{
    FrameView v;
    v.format = f;
    v.data = b.data();
    v.width = w;
    v.height = h;
    v.stride = stride;
    v.bytes = b.size();
    return v;
}
} // namespace

TEST(LumaView, GreyAndPlanarAreViewedInPlace)
{
    std::vector<uint8_t> nv12(4 * 2 + 4 * 1, 7);
    LumaView lv;
    ASSERT_EQ(lumaOf(frame(PixelFormat::NV12, nv12, 4, 2, 4), nullptr, 0, &lv), ErrorCode::None);
    EXPECT_EQ(lv.data, nv12.data());
    std::vector<uint8_t> yuv420(4 * 2 + 2 * 2 * 1);
    ASSERT_EQ(lumaOf(frame(PixelFormat::YUV420, yuv420, 4, 2, 4), nullptr, 0, &lv), ErrorCode::None);
    EXPECT_EQ(lv.data, yuv420.data());
}

TEST(LumaView, YuyvUsesAPixelStep)
{
    // Y0 U Y1 V per pair: luma 10, 20, 30, 40.
    std::vector<uint8_t> b = {10, 128, 20, 128, 30, 128, 40, 128};
    LumaView lv;
    ASSERT_EQ(lumaOf(frame(PixelFormat::YUYV, b, 4, 1, 8), nullptr, 0, &lv), ErrorCode::None);
    EXPECT_EQ(lv.data, b.data());
    EXPECT_EQ(lv.at(0, 0), 10);
    EXPECT_EQ(lv.at(3, 0), 40);
}

TEST(LumaView, RgbFormatsConvertWithBt601Weights)
{
    // Pure red, green, blue, white pixels in RGB, BGR and BGRX orders.
    std::vector<uint8_t> rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    std::vector<uint8_t> bgr = {0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255};
    std::vector<uint8_t> bgrx = {0, 0, 255, 9, 0, 255, 0, 9, 255, 0, 0, 9, 255, 255, 255, 9};
    const uint8_t want[4] = {77, 149, 29, 255}; // (w·255 + 128) >> 8
    for (auto [fmt, buf, stride] : {std::tuple{PixelFormat::RGB24, &rgb, 12}, std::tuple{PixelFormat::BGR24, &bgr, 12},
                                    std::tuple{PixelFormat::XRGB32, &bgrx, 16}}) {
        std::vector<uint8_t> scratch(lumaScratchBytes(fmt, 4, 1));
        LumaView lv;
        ASSERT_EQ(lumaOf(frame(fmt, *buf, 4, 1, stride), scratch.data(), scratch.size(), &lv), ErrorCode::None);
        for (int x = 0; x < 4; ++x) EXPECT_EQ(lv.at(x, 0), want[x]) << int(fmt) << " x=" << x;
    }
}

TEST(LumaView, RefusesGeometryThatDoesNotFit)
{
    std::vector<uint8_t> b(10);
    LumaView lv;
    EXPECT_EQ(lumaOf(frame(PixelFormat::Grey8, b, 4, 4, 4), nullptr, 0, &lv), ErrorCode::BadFrame);
    EXPECT_EQ(lumaOf(frame(PixelFormat::Grey8, b, 4, 2, 3), nullptr, 0, &lv), ErrorCode::BadFrame);
    EXPECT_EQ(lumaOf(frame(PixelFormat::Grey8, b, 0, 2, 4), nullptr, 0, &lv), ErrorCode::BadFrame);
    std::vector<uint8_t> rgb(12);
    EXPECT_EQ(lumaOf(frame(PixelFormat::RGB24, rgb, 4, 1, 12), nullptr, 0, &lv), ErrorCode::FrameTooLarge);
}
