// The SSD1306 driver against recorded I2C transactions: the power-up sequence, the picture
// sent page by page in the controller's layout, and a NACK (no display on the bus) as a
// clear error after which the next picture re-initialises the display.
#include <gtest/gtest.h>

#include <vector>

#include "hal/ssd1306/ssd1306_display.h"

namespace {

using namespace icacam;

struct RecordedBus final : hal::I2cBus {
    std::vector<std::vector<uint8_t>> writes;
    int nackAfter = -1; // fail every write once this many have succeeded (-1: never)
    hal::Error write(const uint8_t *data, size_t len) override
    {
        if (nackAfter >= 0 && int(writes.size()) >= nackAfter)
            return hal::Error::make(hal::Errc::Io, "/dev/i2c-1 @0x3c: no acknowledge (display not connected?)");
        writes.emplace_back(data, data + len);
        return {};
    }
};

TEST(Ssd1306, InitThenWholePictureInEightPageWrites)
{
    RecordedBus bus;
    hal::Ssd1306Display display(bus);
    hal::MonoBitmap pic;
    pic.set(0, 0, true);    // page 0, column 0, bit 0
    pic.set(127, 63, true); // page 7, column 127, bit 7
    pic.set(5, 9, true);    // page 1, column 5, bit 1
    ASSERT_TRUE(display.show(pic).ok());
    ASSERT_EQ(bus.writes.size(), 1u + 1u + 8u); // init, window, 8 × 128 data bytes
    const auto &init = bus.writes[0];
    EXPECT_EQ(init.front(), 0x00);          // command stream
    EXPECT_EQ(init[1], 0xAE);               // display off first
    EXPECT_EQ(init.back(), 0xAF);           // display on last
    const std::vector<uint8_t> window{0x00, 0x21, 0, 127, 0x22, 0, 7};
    EXPECT_EQ(bus.writes[1], window);
    for (int page = 0; page < 8; ++page) {
        const auto &w = bus.writes[size_t(2 + page)];
        ASSERT_EQ(w.size(), 129u);
        EXPECT_EQ(w[0], 0x40); // data stream
    }
    EXPECT_EQ(bus.writes[2][1 + 0], 0x01);
    EXPECT_EQ(bus.writes[3][1 + 5], 0x02);
    EXPECT_EQ(bus.writes[9][1 + 127], 0x80);
    // The next picture skips the init.
    ASSERT_TRUE(display.show(pic).ok());
    EXPECT_EQ(bus.writes.size(), 10u + 9u);
}

TEST(Ssd1306, NackIsAClearErrorAndTheNextPictureReinitialises)
{
    RecordedBus bus;
    bus.nackAfter = 3; // init and window pass, then the display drops off the bus
    hal::Ssd1306Display display(bus);
    hal::MonoBitmap pic;
    hal::Error e = display.show(pic);
    EXPECT_EQ(e.code, hal::Errc::Io);
    EXPECT_NE(e.message.find("no acknowledge"), std::string::npos) << e.message;
    bus.nackAfter = -1;
    bus.writes.clear();
    ASSERT_TRUE(display.show(pic).ok());
    ASSERT_FALSE(bus.writes.empty());
    EXPECT_EQ(bus.writes[0][1], 0xAE); // power-up sequence again
}

TEST(Ssd1306, MissingBusIsNotFound)
{
    hal::I2cDevBus bus;
    hal::Error e = bus.open(77, 0x3C);
    EXPECT_EQ(e.code, hal::Errc::NotFound) << e.message;
    uint8_t b = 0;
    EXPECT_EQ(bus.write(&b, 1).code, hal::Errc::Invalid);
}

} // namespace
