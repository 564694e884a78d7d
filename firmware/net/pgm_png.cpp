#include "firmware/net/pgm_png.h"

#include <png.h>

#include <cctype>
#include <cstdint>
#include <vector>

namespace icacam::fw::net {

namespace {

// The header's tokens: magic, width, height, maxval; '#' comments between them.
bool nextNumber(std::string_view b, size_t *pos, long *value)
{
    for (;;) {
        while (*pos < b.size() && std::isspace(static_cast<unsigned char>(b[*pos]))) ++*pos;
        if (*pos < b.size() && b[*pos] == '#') {
            while (*pos < b.size() && b[*pos] != '\n') ++*pos;
            continue;
        }
        break;
    }
    long v = 0;
    const size_t start = *pos;
    while (*pos < b.size() && std::isdigit(static_cast<unsigned char>(b[*pos])) && *pos - start < 6)
        v = v * 10 + (b[(*pos)++] - '0');
    *value = v;
    return *pos > start;
}

} // namespace

std::string parsePgm(std::string_view b, PgmView *out)
{
    if (b.size() < 2 || b[0] != 'P' || b[1] != '5') return "not a binary PGM";
    size_t pos = 2;
    long w = 0, h = 0, maxval = 0;
    if (!nextNumber(b, &pos, &w) || !nextNumber(b, &pos, &h) || !nextNumber(b, &pos, &maxval))
        return "PGM header incomplete";
    if (w < 1 || h < 1 || w > 16384 || h > 16384) return "PGM size out of range";
    if (maxval != 255) return "PGM is not 8-bit";
    if (pos >= b.size() || !std::isspace(static_cast<unsigned char>(b[pos]))) return "PGM header not ended";
    ++pos;
    if (b.size() - pos < size_t(w) * size_t(h)) return "PGM pixels cut short";
    *out = {int(w), int(h), reinterpret_cast<const unsigned char *>(b.data() + pos)};
    return "";
}

std::string pgmToPng(const PgmView &pgm, int step, std::string *png)
{
    if (step < 1 || step > 8) return "step must be 1-8";
    const int w = (pgm.width + step - 1) / step, h = (pgm.height + step - 1) / step;
    std::vector<unsigned char> small(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            small[size_t(y) * size_t(w) + size_t(x)] =
                pgm.pixels[size_t(y * step) * size_t(pgm.width) + size_t(x * step)];
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(w);
    image.height = png_uint_32(h);
    image.format = PNG_FORMAT_GRAY;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, small.data(), w, nullptr))
        return std::string("png: ") + image.message;
    const size_t at = png->size();
    png->resize(at + size);
    if (!png_image_write_to_memory(&image, png->data() + at, &size, 0, small.data(), w, nullptr)) {
        png->resize(at);
        return std::string("png: ") + image.message;
    }
    png->resize(at + size);
    return "";
}

} // namespace icacam::fw::net
