#include "hal/ssd1306/ssd1306_display.h"

#include <fcntl.h>
#include <linux/i2c-dev.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

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

Error Ssd1306Display::init()
{
    // Datasheet §10 and application note "charge pump": 128 × 64, internal VCC.
    static const uint8_t kInit[] = {
        0xAE,       // display off
        0xD5, 0x80, // clock divide / oscillator
        0xA8, 0x3F, // multiplex ratio 64
        0xD3, 0x00, // display offset 0
        0x40,       // start line 0
        0x8D, 0x14, // charge pump on
        0x20, 0x00, // horizontal addressing: 1024 bytes fill the screen page by page
        0xA1,       // segment remap (column 127 = SEG0): picture not mirrored
        0xC8,       // COM scan descending: picture not upside down
        0xDA, 0x12, // COM pins: alternative, for 64 rows
        0x81, 0x7F, // contrast
        0xD9, 0xF1, // pre-charge
        0xDB, 0x40, // VCOMH deselect
        0xA4,       // show RAM
        0xA6,       // normal (not inverted)
        0xAF,       // display on
    };
    ready_ = false;
    if (Error e = commands(kInit, sizeof kInit); !e.ok()) return e;
    ready_ = true;
    return {};
}

Error Ssd1306Display::show(const MonoBitmap &picture)
{
    if (!ready_)
        if (Error e = init(); !e.ok()) return e;
    static const uint8_t kWindow[] = {0x21, 0, 127, 0x22, 0, 7}; // whole column and page range
    Error e = commands(kWindow, sizeof kWindow);
    uint8_t buf[1 + kChunk];
    buf[0] = kDataStream;
    const auto &bytes = picture.bytes();
    for (size_t off = 0; e.ok() && off < bytes.size(); off += kChunk) {
        std::memcpy(buf + 1, bytes.data() + off, kChunk);
        e = bus_.write(buf, sizeof buf);
    }
    if (!e.ok()) ready_ = false;
    return e;
}

} // namespace icacam::hal
