// The libcamera backend's mode choice against the mode lists of the sensors the product
// names, as their Raspberry Pi kernel drivers enumerate them (VIDIOC_SUBDEV_ENUM_FRAME_SIZE
// per media-bus code, which libcamera's raw stream formats list one for one):
//  * imx708 (Camera Module 3), raspberrypi/linux drivers/media/i2c/imx708.c,
//    supported_modes_10bit_no_hdr: 4608x2592, 2304x1296, 1536x864; 10-bit codes only.
//  * imx477 (HQ camera), drivers/media/i2c/imx477.c: supported_modes_12bit 4056x3040,
//    2028x1520, 2028x1080; supported_modes_10bit 1332x990.
//  * imx219 (Camera Module 2), drivers/media/i2c/imx219.c: supported_modes 3280x2464,
//    1920x1080, 1640x1232, 640x480, each under the 10-bit and the 8-bit codes.
//  * ov5647 (Camera Module 1), drivers/media/i2c/ov5647.c: ov5647_modes 2592x1944,
//    1920x1080, 1296x972, 640x480; SBGGR10 only.
// Without this choice the processed stream took the largest entry of libcamera's table of
// common resolutions: 3840x2400 for imx708 and imx477, 3200x2400 for imx219.
#include <gtest/gtest.h>

#include <vector>

#include "hal/libcamera/sensor_mode.h"

namespace {

using icacam::hal::chooseSensorMode;
using icacam::hal::rawBitDepth;
using icacam::hal::SensorMode;

const std::vector<SensorMode> kImx708{{4608, 2592, 10}, {2304, 1296, 10}, {1536, 864, 10}};
const std::vector<SensorMode> kImx477{{4056, 3040, 12}, {2028, 1520, 12}, {2028, 1080, 12}, {1332, 990, 10}};
const std::vector<SensorMode> kImx219{{3280, 2464, 10}, {1920, 1080, 10}, {1640, 1232, 10}, {640, 480, 10},
                                      {3280, 2464, 8},  {1920, 1080, 8},  {1640, 1232, 8},  {640, 480, 8}};
const std::vector<SensorMode> kOv5647{{2592, 1944, 10}, {1920, 1080, 10}, {1296, 972, 10}, {640, 480, 10}};

// The shipped maximum (deploy/device.conf): large enough for every one of them.
constexpr int kMaxW = 4608, kMaxH = 3040;

void expectFullMode(const std::vector<SensorMode> &modes, int w, int h, int bits)
{
    const auto c = chooseSensorMode(modes, kMaxW, kMaxH);
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.mode.width, w);
    EXPECT_EQ(c.mode.height, h);
    EXPECT_EQ(c.mode.bitDepth, bits);
    EXPECT_EQ(c.outWidth, w); // the luma is the mode, pixel for pixel
    EXPECT_EQ(c.outHeight, h);
    EXPECT_FALSE(c.scaled);
}

TEST(SensorMode, EachSensorRunsItsFullResolutionModeAndTheLumaIsThatSize)
{
    expectFullMode(kImx708, 4608, 2592, 10);
    expectFullMode(kImx477, 4056, 3040, 12);
    expectFullMode(kImx219, 3280, 2464, 10); // the 10-bit one of the two equal sizes
    expectFullMode(kOv5647, 2592, 1944, 10);
}

TEST(SensorMode, TheModeListOrderDoesNotMatter)
{
    std::vector<SensorMode> reversed(kImx219.rbegin(), kImx219.rend());
    const auto c = chooseSensorMode(reversed, kMaxW, kMaxH);
    EXPECT_EQ(c.mode.width, 3280);
    EXPECT_EQ(c.mode.bitDepth, 10);
}

TEST(SensorMode, AMaximumBelowTheFullModeTakesTheLargestModeThatFits)
{
    // 4608 x 2592 (the Camera Module 3's size) cuts the HQ camera's 3040 rows: its binned mode.
    auto c = chooseSensorMode(kImx477, 4608, 2592);
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.mode.width, 2028);
    EXPECT_EQ(c.mode.height, 1520);
    EXPECT_FALSE(c.scaled);
    // The firmware's default maximum, 4096 x 3072, fits the HQ camera but not the imx708.
    c = chooseSensorMode(kImx477, 4096, 3072);
    EXPECT_EQ(c.mode.width, 4056);
    c = chooseSensorMode(kImx708, 4096, 3072);
    EXPECT_EQ(c.mode.width, 2304);
    EXPECT_EQ(c.outHeight, 1296);
}

TEST(SensorMode, NoModeFitsThenTheSmallestIsScaledDownWithItsAspectRatio)
{
    auto c = chooseSensorMode(kImx708, 1280, 1024);
    ASSERT_TRUE(c.found);
    EXPECT_TRUE(c.scaled);
    EXPECT_EQ(c.mode.width, 1536);
    EXPECT_EQ(c.mode.height, 864);
    EXPECT_EQ(c.outWidth, 1280);
    EXPECT_EQ(c.outHeight, 720);
    c = chooseSensorMode(kOv5647, 320, 320);
    EXPECT_EQ(c.mode.width, 640);
    EXPECT_EQ(c.outWidth, 320);
    EXPECT_EQ(c.outHeight, 240);
}

TEST(SensorMode, AConfiguredSizeComesFromTheSmallestModeThatCoversIt)
{
    // 1080p: the imx219 has it; the HQ camera crops 2028x1080; the CM3 bins to 2304x1296.
    auto c = chooseSensorMode(kImx219, kMaxW, kMaxH, 1920, 1080);
    EXPECT_EQ(c.mode.width, 1920);
    EXPECT_EQ(c.mode.bitDepth, 10);
    EXPECT_FALSE(c.scaled);
    c = chooseSensorMode(kImx477, kMaxW, kMaxH, 1920, 1080);
    EXPECT_EQ(c.mode.width, 2028);
    EXPECT_EQ(c.mode.height, 1080);
    EXPECT_TRUE(c.scaled);
    EXPECT_EQ(c.outWidth, 1920);
    c = chooseSensorMode(kImx708, kMaxW, kMaxH, 1920, 1080);
    EXPECT_EQ(c.mode.width, 2304);
    // Larger than every mode: the largest, upscaled (the configuration asked for it).
    c = chooseSensorMode(kOv5647, kMaxW, kMaxH, 3000, 2000);
    EXPECT_EQ(c.mode.width, 2592);
    EXPECT_TRUE(c.scaled);
    // Above the maximum: refused.
    EXPECT_FALSE(chooseSensorMode(kImx708, 1920, 1080, 2304, 1296).found);
}

TEST(SensorMode, NothingListedIsNothingFound)
{
    EXPECT_FALSE(chooseSensorMode({}, kMaxW, kMaxH).found);
    EXPECT_FALSE(chooseSensorMode(kImx708, 0, 0).found);
}

TEST(SensorMode, BitDepthFromTheRawFormatName)
{
    EXPECT_EQ(rawBitDepth("SRGGB10_CSI2P"), 10);
    EXPECT_EQ(rawBitDepth("SBGGR12"), 12);
    EXPECT_EQ(rawBitDepth("SGRBG8"), 8);
    EXPECT_EQ(rawBitDepth("SGBRG16"), 16);
    EXPECT_EQ(rawBitDepth("R10_CSI2P"), 10); // mono sensors
    EXPECT_EQ(rawBitDepth("R8"), 8);
    EXPECT_EQ(rawBitDepth("NV12"), 0);
    EXPECT_EQ(rawBitDepth("RGB888"), 0);
    EXPECT_EQ(rawBitDepth("YUYV"), 0);
    EXPECT_EQ(rawBitDepth("BGGR_PISP_COMP1"), 0);
    EXPECT_EQ(rawBitDepth("S"), 0);
}

} // namespace
