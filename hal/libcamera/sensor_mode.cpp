#include "hal/libcamera/sensor_mode.h"

#include <cstdint>

namespace icacam::hal {

namespace {

int64_t area(const SensorMode &m)
{
    return int64_t(m.width) * m.height;
}

bool isBayerLetter(char c)
{
    return c == 'R' || c == 'G' || c == 'B';
}

int digitsAt(std::string_view s, size_t at)
{
    int v = 0;
    size_t i = at;
    for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i) v = v * 10 + (s[i] - '0');
    return i > at && v >= 8 && v <= 16 ? v : 0;
}

} // namespace

int rawBitDepth(std::string_view name)
{
    // Bayer: S + four colour letters + depth (formats.yaml: SRGGB10, SBGGR12_CSI2P, ...).
    if (name.size() > 5 && name[0] == 'S' && isBayerLetter(name[1]) && isBayerLetter(name[2]) &&
        isBayerLetter(name[3]) && isBayerLetter(name[4]))
        return digitsAt(name, 5);
    // Raw mono: R + depth (R8, R10_CSI2P); RGB888 and friends have a letter there.
    if (name.size() > 1 && name[0] == 'R') return digitsAt(name, 1);
    return 0;
}

SensorModeChoice chooseSensorMode(std::span<const SensorMode> modes, int maxWidth, int maxHeight, int width, int height)
{
    SensorModeChoice c;
    if (maxWidth <= 0 || maxHeight <= 0) return c;
    const SensorMode *best = nullptr;
    if (width > 0 && height > 0) {
        if (width > maxWidth || height > maxHeight) return c;
        // The smallest mode that covers the size: the ISP scales down, never up.
        const SensorMode *largest = nullptr;
        for (const SensorMode &m : modes) {
            if (m.width <= 0 || m.height <= 0) continue;
            if (!largest || area(m) > area(*largest) || (area(m) == area(*largest) && m.bitDepth > largest->bitDepth))
                largest = &m;
            if (m.width < width || m.height < height) continue;
            if (!best || area(m) < area(*best) || (area(m) == area(*best) && m.bitDepth > best->bitDepth)) best = &m;
        }
        if (!best) best = largest;
        if (!best) return c;
        c.found = true;
        c.mode = *best;
        c.outWidth = width;
        c.outHeight = height;
        c.scaled = best->width != width || best->height != height;
        return c;
    }
    const SensorMode *smallest = nullptr;
    for (const SensorMode &m : modes) {
        if (m.width <= 0 || m.height <= 0) continue;
        if (!smallest || area(m) < area(*smallest)) smallest = &m;
        if (m.width > maxWidth || m.height > maxHeight) continue;
        if (!best || area(m) > area(*best) || (area(m) == area(*best) && m.bitDepth > best->bitDepth)) best = &m;
    }
    if (best) {
        c.found = true;
        c.mode = *best;
        c.outWidth = best->width;
        c.outHeight = best->height;
        return c;
    }
    if (!smallest) return c;
    // Nothing fits: the ISP scales the smallest mode into the maximum, aspect ratio kept,
    // even sizes (the ISP outputs' alignment).
    c.found = true;
    c.scaled = true;
    c.mode = *smallest;
    const bool widthBound = int64_t(maxWidth) * smallest->height <= int64_t(maxHeight) * smallest->width;
    if (widthBound) {
        c.outWidth = maxWidth;
        c.outHeight = int(int64_t(maxWidth) * smallest->height / smallest->width);
    } else {
        c.outHeight = maxHeight;
        c.outWidth = int(int64_t(maxHeight) * smallest->width / smallest->height);
    }
    c.outWidth &= ~1;
    c.outHeight &= ~1;
    if (c.outWidth <= 0 || c.outHeight <= 0) c.found = false;
    return c;
}

} // namespace icacam::hal
