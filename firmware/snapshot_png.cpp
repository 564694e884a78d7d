#include "firmware/snapshot_png.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <vector>

namespace icacam::fw {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kGreys = 252;
enum Colour : uint8_t { kRed = 252, kGreen = 253, kBlue = 254, kYellow = 255 };

// A marked pixel: row, column and palette index packed so that sorting orders by row.
uint64_t mark(int x, int y, uint8_t c)
{
    return (uint64_t(uint32_t(y)) << 32) | (uint64_t(uint32_t(x)) << 8) | c;
}

struct Marks {
    std::vector<uint64_t> list;
    int width, height, thick;
    void dot(double fx, double fy, uint8_t c)
    {
        const int x0 = int(std::lround(fx)), y0 = int(std::lround(fy));
        for (int dy = -thick; dy <= thick; ++dy)
            for (int dx = -thick; dx <= thick; ++dx) {
                const int x = x0 + dx, y = y0 + dy;
                if (x >= 0 && y >= 0 && x < width && y < height) list.push_back(mark(x, y, c));
            }
    }
    void curve(const vision::BoundaryFit &fit, double cx, double cy, uint8_t c)
    {
        if (fit.rEqPx <= 0) return;
        const int n = std::max(360, int(4 * kPi * fit.rEqPx));
        for (int i = 0; i < n; ++i) {
            const double a = 2 * kPi * i / n, r = fit.radiusAt(a);
            dot(cx + r * std::cos(a), cy + r * std::sin(a), c);
        }
    }
    void circle(double cx, double cy, double r, uint8_t c)
    {
        if (r <= 0) return;
        const int n = std::max(360, int(4 * kPi * r));
        for (int i = 0; i < n; ++i) dot(cx + r * std::cos(2 * kPi * i / n), cy + r * std::sin(2 * kPi * i / n), c);
    }
    void points(const vision::EdgeSample *p, int count, uint8_t c)
    {
        for (int i = 0; p && i < count; ++i)
            if (p[i].valid) dot(p[i].x.toDouble(), p[i].y.toDouble(), c);
    }
};

void appendPng(png_structp png, png_bytep data, png_size_t n)
{
    static_cast<std::string *>(png_get_io_ptr(png))->append(reinterpret_cast<const char *>(data), n);
}
void flushPng(png_structp) {}
[[noreturn]] void failPng(png_structp png, png_const_charp)
{
    png_longjmp(png, 1);
}
void quietPng(png_structp, png_const_charp) {}

} // namespace

std::string encodeSnapshotPng(const vision::LumaView &v, const reading::Reading &r, std::string *out)
{
    if (!v.valid()) return "snapshot: no frame";
    // Everything with a destructor exists before setjmp, so a longjmp skips none.
    Marks marks{{}, v.width, v.height, v.width >= 1200 ? 1 : 0};
    const vision::EndFaceGeometry &m = r.geometry;
    if (r.hasValue() || m.outer.rEqPx > 0) {
        marks.points(m.outerPoints, m.rayCount, kYellow);
        marks.points(m.innerPoints, m.rayCount, kYellow);
        marks.curve(m.outer, m.centreX, m.centreY, kGreen);
        marks.curve(m.inner, m.centreX, m.centreY, kRed);
        marks.circle(m.centreX, m.centreY, m.rMaxPx, kBlue);
    }
    std::sort(marks.list.begin(), marks.list.end());
    std::vector<png_byte> row(size_t(v.width));
    png_color palette[256];
    for (int i = 0; i < kGreys; ++i)
        palette[i].red = palette[i].green = palette[i].blue = png_byte(i * 255 / (kGreys - 1));
    palette[kRed] = {255, 40, 40};
    palette[kGreen] = {40, 255, 40};
    palette[kBlue] = {60, 120, 255};
    palette[kYellow] = {255, 230, 0};

    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, failPng, quietPng);
    if (!png) return "snapshot: libpng";
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : nullptr);
        return "snapshot: PNG encoding failed";
    }
    png_set_write_fn(png, out, appendPng, flushPng);
    png_set_compression_level(png, 1); // fast: a snapshot is looked at, not archived
    png_set_IHDR(png, info, png_uint_32(v.width), png_uint_32(v.height), 8, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_PLTE(png, info, palette, 256);
    png_write_info(png, info);
    size_t next = 0;
    for (int y = 0; y < v.height; ++y) {
        for (int x = 0; x < v.width; ++x) row[size_t(x)] = png_byte(v.at(x, y) * (kGreys - 1) / 255);
        for (; next < marks.list.size() && int(marks.list[next] >> 32) == y; ++next)
            row[size_t((marks.list[next] >> 8) & 0xFFFFFF)] = png_byte(marks.list[next] & 0xFF);
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return "";
}

} // namespace icacam::fw
