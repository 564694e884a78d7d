// The SSD1306 driver against recorded I2C transactions: the power-up sequence, the picture
// sent page by page in the controller's layout, and a NACK (no display on the bus) as a
// clear error after which the next picture re-initialises the display.
#include <gtest/gtest.h>

#include <algorithm>
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

TEST(Ssd1306, InitClearsTheRamBeforeTheDisplayComesOnThenSendsThePictureByPage)
{
    RecordedBus bus;
    hal::Ssd1306Display display(bus);
    hal::MonoBitmap pic;
    pic.set(0, 0, true);    // page 0, column 0, bit 0
    pic.set(127, 63, true); // page 7, column 127, bit 7
    pic.set(5, 9, true);    // page 1, column 5, bit 1
    ASSERT_TRUE(display.show(pic).ok());
    // init, 8 × (page address, 128 zero bytes), display on, 8 × (page address, picture row)
    ASSERT_EQ(bus.writes.size(), 1u + 16u + 1u + 16u);
    const auto &init = bus.writes[0];
    EXPECT_EQ(init.front(), 0x00); // command stream
    EXPECT_EQ(init[1], 0xAE);      // display off first
    for (int page = 0; page < 8; ++page) {
        const std::vector<uint8_t> at{0x00, uint8_t(0xB0 + page), 0x00, 0x10};
        EXPECT_EQ(bus.writes[size_t(1 + 2 * page)], at);
        const auto &blank = bus.writes[size_t(2 + 2 * page)];
        ASSERT_EQ(blank.size(), 129u);
        for (size_t i = 1; i < blank.size(); ++i) ASSERT_EQ(blank[i], 0) << page;
    }
    EXPECT_EQ(bus.writes[17], (std::vector<uint8_t>{0x00, 0xAF})); // on only after the clear
    for (int page = 0; page < 8; ++page) {
        const auto &w = bus.writes[size_t(19 + 2 * page)];
        ASSERT_EQ(w.size(), 129u);
        EXPECT_EQ(w[0], 0x40); // data stream
    }
    EXPECT_EQ(bus.writes[19][1 + 0], 0x01);
    EXPECT_EQ(bus.writes[21][1 + 5], 0x02);
    EXPECT_EQ(bus.writes[33][1 + 127], 0x80);
    // The next picture skips the init.
    ASSERT_TRUE(display.show(pic).ok());
    EXPECT_EQ(bus.writes.size(), 34u + 16u);
}

TEST(Ssd1306, Sh1106PanelIsClearedOver132ColumnsAndDrawnFromColumnTwo)
{
    RecordedBus bus;
    hal::Ssd1306Display display(bus, {true, false, 0x7F});
    hal::MonoBitmap pic;
    pic.set(0, 0, true);
    ASSERT_TRUE(display.show(pic).ok());
    EXPECT_EQ(bus.writes[2].size(), 133u);                 // 132 columns of RAM cleared
    const std::vector<uint8_t> at{0x00, 0xB0, 0x02, 0x10}; // column 2: the panel's first
    EXPECT_EQ(bus.writes[18], at);
    EXPECT_EQ(bus.writes[19][1], 0x01);
}

TEST(Ssd1306, RotationAndContrastAreSentAtInit)
{
    RecordedBus upright, turned;
    hal::Ssd1306Display a(upright), b(turned, {false, true, 0x20});
    ASSERT_TRUE(a.init().ok());
    ASSERT_TRUE(b.init().ok());
    auto has = [](const std::vector<uint8_t> &w, uint8_t c) { return std::find(w.begin() + 1, w.end(), c) != w.end(); };
    EXPECT_TRUE(has(upright.writes[0], 0xA1) && has(upright.writes[0], 0xC8));
    EXPECT_TRUE(has(turned.writes[0], 0xA0) && has(turned.writes[0], 0xC0));
    const auto &t = turned.writes[0];
    const auto contrast = std::find(t.begin() + 1, t.end(), uint8_t(0x81));
    ASSERT_NE(contrast, t.end());
    EXPECT_EQ(*(contrast + 1), 0x20);
}

TEST(Ssd1306, NackIsAClearErrorAndTheNextPictureReinitialises)
{
    RecordedBus bus;
    bus.nackAfter = 3; // init and the first cleared page pass, then the display drops off the bus
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
