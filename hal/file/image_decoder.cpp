#include "hal/file/image_decoder.h"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

#include <jpeglib.h>
#include <png.h>

namespace icacam::hal {

namespace {

struct FileCloser {
    void operator()(FILE *f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<FILE, FileCloser>;

Error checkGeometry(int w, int h, int ch, int maxW, int maxH, int minStride, size_t cap, int *stride)
{
    if (w <= 0 || h <= 0) return Error::make(Errc::BadFormat, "image has no pixels");
    if (w > maxW || h > maxH)
        return Error::make(Errc::TooLarge, "image " + std::to_string(w) + "x" + std::to_string(h) +
                                               " exceeds the configured maximum " + std::to_string(maxW) + "x" +
                                               std::to_string(maxH));
    *stride = minStride >= w * ch ? minStride : w * ch;
    if (size_t(*stride) * size_t(h) > cap) return Error::make(Errc::TooLarge, "image exceeds the frame buffer");
    return {};
}

// libpng's default handlers print to stderr; ours stay quiet and return by longjmp.
void pngQuietError(png_structp png, png_const_charp)
{
    png_longjmp(png, 1);
}
void pngQuietWarning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp; nothing with a destructor lives between setjmp and it.
Error decodePng(FILE *f, uint8_t *dst, size_t cap, int maxW, int maxH, int minStride, DecodedImage *out)
{
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, pngQuietError, pngQuietWarning);
    if (!png) return Error::make(Errc::Io, "libpng: out of memory");
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return Error::make(Errc::Io, "libpng: out of memory");
    }
    static thread_local Error err;
    err = {};
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return err.ok() ? Error::make(Errc::BadFormat, "corrupt or truncated PNG") : err;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    const png_byte colour = png_get_color_type(png, info);
    if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_bit_depth(png, info) == 16) png_set_strip_16(png);
    if (colour & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    png_read_update_info(png, info);
    const int w = int(png_get_image_width(png, info));
    const int h = int(png_get_image_height(png, info));
    const int ch = int(png_get_channels(png, info));
    int stride = 0;
    if (ch != 1 && ch != 3)
        err = Error::make(Errc::BadFormat, "PNG with unsupported channel layout");
    else
        err = checkGeometry(w, h, ch, maxW, maxH, minStride, cap, &stride);
    if (!err.ok()) png_error(png, "geometry");
    for (int pass = png_set_interlace_handling(png); pass > 0; --pass)
        for (int y = 0; y < h; ++y) png_read_row(png, dst + size_t(y) * size_t(stride), nullptr);
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    *out = {w, h, ch, stride};
    return {};
}

struct JpegErr {
    jpeg_error_mgr mgr;
    jmp_buf jump;
};

void jpegFail(j_common_ptr c)
{
    longjmp(reinterpret_cast<JpegErr *>(c->err)->jump, 1);
}

Error decodeJpeg(FILE *f, uint8_t *dst, size_t cap, int maxW, int maxH, int minStride, DecodedImage *out)
{
    jpeg_decompress_struct cinfo;
    JpegErr jerr;
    cinfo.err = jpeg_std_error(&jerr.mgr);
    jerr.mgr.error_exit = jpegFail;
    static thread_local Error err;
    err = {};
    if (setjmp(jerr.jump)) {
        jpeg_destroy_decompress(&cinfo);
        return err.ok() ? Error::make(Errc::BadFormat, "corrupt or truncated JPEG") : err;
    }
    jpeg_create_decompress(&cinfo);
    jpeg_stdio_src(&cinfo, f);
    jpeg_read_header(&cinfo, TRUE);
    cinfo.out_color_space = cinfo.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&cinfo);
    const int w = int(cinfo.output_width), h = int(cinfo.output_height), ch = cinfo.output_components;
    int stride = 0;
    err = checkGeometry(w, h, ch, maxW, maxH, minStride, cap, &stride);
    if (!err.ok()) longjmp(jerr.jump, 1);
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = dst + size_t(cinfo.output_scanline) * size_t(stride);
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    *out = {w, h, ch, stride};
    return {};
}

// Binary PGM (P5), maxval ≤ 255, comments allowed in the header.
Error decodePgm(FILE *f, uint8_t *dst, size_t cap, int maxW, int maxH, int minStride, DecodedImage *out)
{
    int vals[3];
    for (int &v : vals) {
        int c = std::fgetc(f);
        for (;;) {
            while (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = std::fgetc(f);
            if (c != '#') break;
            while (c != '\n' && c != EOF) c = std::fgetc(f);
        }
        if (c < '0' || c > '9') return Error::make(Errc::BadFormat, "bad PGM header");
        long acc = 0;
        while (c >= '0' && c <= '9' && acc < 1000000) {
            acc = acc * 10 + (c - '0');
            c = std::fgetc(f);
        }
        v = int(acc);
    }
    if (vals[2] <= 0 || vals[2] > 255) return Error::make(Errc::BadFormat, "PGM maxval must be 1..255");
    int stride = 0;
    if (Error e = checkGeometry(vals[0], vals[1], 1, maxW, maxH, minStride, cap, &stride); !e.ok()) return e;
    for (int y = 0; y < vals[1]; ++y)
        if (std::fread(dst + size_t(y) * size_t(stride), 1, size_t(vals[0]), f) != size_t(vals[0]))
            return Error::make(Errc::BadFormat, "PGM file is truncated");
    *out = {vals[0], vals[1], 1, stride};
    return {};
}

} // namespace

Error decodeImage(const std::string &path, uint8_t *dst, size_t capacity, int maxWidth, int maxHeight, int minStride,
                  DecodedImage *out)
{
    FilePtr f(std::fopen(path.c_str(), "rb"));
    if (!f) return Error::make(Errc::NotFound, "cannot open image '" + path + "': " + std::strerror(errno));
    unsigned char magic[8] = {};
    const size_t n = std::fread(magic, 1, sizeof magic, f.get());
    std::rewind(f.get());
    if (n >= 8 && png_sig_cmp(magic, 0, 8) == 0)
        return decodePng(f.get(), dst, capacity, maxWidth, maxHeight, minStride, out);
    if (n >= 3 && magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF)
        return decodeJpeg(f.get(), dst, capacity, maxWidth, maxHeight, minStride, out);
    if (n >= 2 && magic[0] == 'P' && magic[1] == '5') {
        std::fseek(f.get(), 2, SEEK_SET);
        return decodePgm(f.get(), dst, capacity, maxWidth, maxHeight, minStride, out);
    }
    return Error::make(Errc::BadFormat, "'" + path + "' is not a PNG, JPEG or binary PGM file");
}

Error writePng(const std::string &path, const uint8_t *data, int width, int height, int channels, int stride)
{
    FilePtr f(std::fopen(path.c_str(), "wb"));
    if (!f) return Error::make(Errc::Io, "cannot write '" + path + "': " + std::strerror(errno));
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, pngQuietError, pngQuietWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return Error::make(Errc::Io, "libpng: out of memory");
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return Error::make(Errc::Io, "libpng failed writing '" + path + "'");
    }
    png_init_io(png, f.get());
    png_set_compression_level(png, 1);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8,
                 channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) png_write_row(png, data + size_t(y) * size_t(stride));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return {};
}

} // namespace icacam::hal
