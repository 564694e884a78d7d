#include "hal/ssd1306/ssd1306_display.h"

#include <fcntl.h>
#include <linux/i2c-dev.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace icacam::hal {

namespace {
// Control bytes (datasheet §8.1.5.2): Co = 0, D/C# = 0 for commands, 1 for display data.
constexpr uint8_t kCommandStream = 0x00;
constexpr uint8_t kDataStream = 0x40;
} // namespace

Error I2cDevBus::open(int bus, int address)
{
    name_ = "/dev/i2c-" + std::to_string(bus);
    fd_.reset(::open(name_.c_str(), O_RDWR | O_CLOEXEC));
    if (!fd_.valid())
        return Error::make(errno == ENOENT ? Errc::NotFound : Errc::Io, name_ + ": " + std::strerror(errno));
    if (::ioctl(fd_.get(), I2C_SLAVE, long(address)) < 0) {
        const Error e = Error::make(Errc::Io, name_ + ": I2C_SLAVE: " + std::strerror(errno));
        fd_.reset();
        return e;
    }
    name_ += " @0x" + [address] {
        char b[8];
        std::snprintf(b, sizeof b, "%02x", address & 0x7f);
        return std::string(b);
    }();
    return {};
}

Error I2cDevBus::write(const uint8_t *data, size_t len)
{
    if (!fd_.valid()) return Error::make(Errc::Invalid, "I2C bus not open");
    const ssize_t n = ::write(fd_.get(), data, len);
    if (n == ssize_t(len)) return {};
    if (n < 0 && (errno == ENXIO || errno == EREMOTEIO))
        return Error::make(Errc::Io, name_ + ": no acknowledge (display not connected?)");
    return Error::make(Errc::Io, name_ + ": " + (n < 0 ? std::strerror(errno) : "short write"));
}

Error Ssd1306Display::commands(const uint8_t *cmds, size_t n)
{
    uint8_t buf[32];
    buf[0] = kCommandStream;
    std::memcpy(buf + 1, cmds, n);
    return bus_.write(buf, n + 1);
}

Error Ssd1306Display::writePage(int page, const uint8_t *bytes, size_t n, int firstColumn)
{
    const uint8_t at[] = {uint8_t(0xB0 | page), uint8_t(firstColumn & 0x0F), uint8_t(0x10 | (firstColumn >> 4))};
    if (Error e = commands(at, sizeof at); !e.ok()) return e;
    uint8_t buf[1 + 132];
    buf[0] = kDataStream;
    std::memcpy(buf + 1, bytes, n);
    return bus_.write(buf, n + 1);
}

Error Ssd1306Display::init()
{
    // Datasheet §10: 128 × 64, internal VCC, page addressing. The SH1106 has no addressing
    // modes (always pages) and its own DC-DC command instead of the charge pump.
    const bool flip = options_.rotate180;
    uint8_t init[32];
    size_t n = 0;
    auto add = [&](std::initializer_list<uint8_t> bytes) {
        for (uint8_t b : bytes) init[n++] = b;
    };
    add({0xAE, 0xD5, 0x80, 0xA8, 0x3F, 0xD3, 0x00, 0x40}); // off, clock, 64 rows, offset 0, line 0
    if (options_.sh1106)
        add({0xAD, 0x8B}); // DC-DC converter on
    else
        add({0x8D, 0x14, 0x20, 0x02});            // charge pump on, page addressing
    add({uint8_t(flip ? 0xA0 : 0xA1),             // segment remap: not mirrored (or turned 180°)
         uint8_t(flip ? 0xC0 : 0xC8),             // COM scan: not upside down (or turned)
         0xDA, 0x12,                              // COM pins: alternative, for 64 rows
         0x81, uint8_t(options_.contrast & 0xFF), // contrast
         0xD9, 0xF1, 0xDB, 0x40,                  // pre-charge, VCOMH deselect
         0xA4, 0xA6});                            // show RAM, not inverted
    ready_ = false;
    if (Error e = commands(init, n); !e.ok()) return e;
    // Clear the whole RAM (the SH1106's 132 columns too) before the panel is switched on.
    static const uint8_t kBlank[132] = {};
    const size_t columns = options_.sh1106 ? 132 : 128;
    for (int page = 0; page < 8; ++page)
        if (Error e = writePage(page, kBlank, columns, 0); !e.ok()) return e;
    static const uint8_t kOn[] = {0xAF};
    if (Error e = commands(kOn, sizeof kOn); !e.ok()) return e;
    ready_ = true;
    return {};
}

Error Ssd1306Display::show(const MonoBitmap &picture)
{
    if (!ready_)
        if (Error e = init(); !e.ok()) return e;
    const int firstColumn = options_.sh1106 ? 2 : 0; // the SH1106 panel sits on RAM columns 2…129
    const auto &bytes = picture.bytes();
    Error e;
    for (int page = 0; e.ok() && page < 8; ++page)
        e = writePage(page, bytes.data() + size_t(page) * kChunk, kChunk, firstColumn);
    if (!e.ok()) ready_ = false;
    return e;
}

} // namespace icacam::hal
