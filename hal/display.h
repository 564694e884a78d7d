#pragma once
// A 128 × 64 monochrome display (SSD1306 class). The firmware draws into a MonoBitmap and
// hands the whole picture over; the backend decides how to transfer it.
#include <array>
#include <cstdint>

#include "hal/error.h"

namespace icacam::hal {

// 1 bit per pixel in the SSD1306's page layout: byte (page * 128 + x) holds the 8 pixels
// x, page*8 … page*8+7, least significant bit on top. A real backend sends it as is.
class MonoBitmap {
public:
    static constexpr int kWidth = 128;
    static constexpr int kHeight = 64;
    static constexpr int kBytes = kWidth * kHeight / 8;

    void clear() { bytes_.fill(0); }
    void set(int x, int y, bool on)
    {
        if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return; // clipped, by design
        uint8_t &b = bytes_[size_t((y / 8) * kWidth + x)];
        const auto bit = uint8_t(1u << (y % 8));
        b = on ? uint8_t(b | bit) : uint8_t(b & ~bit);
    }
    bool get(int x, int y) const
    {
        if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return false;
        return (bytes_[size_t((y / 8) * kWidth + x)] >> (y % 8)) & 1u;
    }
    const std::array<uint8_t, kBytes> &bytes() const { return bytes_; }
    bool operator==(const MonoBitmap &o) const { return bytes_ == o.bytes_; }

private:
    std::array<uint8_t, kBytes> bytes_{};
};

class Display {
public:
    virtual ~Display() = default;
    virtual Error show(const MonoBitmap &picture) = 0;
};

} // namespace icacam::hal
