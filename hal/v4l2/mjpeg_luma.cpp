#include "hal/v4l2/mjpeg_luma.h"

#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

namespace icacam::hal {

namespace {

struct JpegError {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
};

// libjpeg's default handler exits the program; this one returns to decodeMjpegLuma.
[[noreturn]] void jpegFail(j_common_ptr c)
{
    std::longjmp(reinterpret_cast<JpegError *>(c->err)->jump, 1);
}
void jpegQuiet(j_common_ptr) {} // corrupt-data warnings: the frame is refused or used as decoded

} // namespace

Error decodeMjpegLuma(const uint8_t *jpeg, size_t bytes, uint8_t *dst, size_t capacity, int width, int height,
                      int dstStride)
{
    if (!jpeg || bytes < 4) return Error::make(Errc::BadFormat, "MJPEG frame empty");
    if (size_t(dstStride) * size_t(height) > capacity)
        return Error::make(Errc::TooLarge, "MJPEG frame larger than its buffer");
    // Nothing with a destructor lives between setjmp and the longjmp that may come back to it.
    jpeg_decompress_struct cinfo;
    JpegError err;
    cinfo.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = jpegFail;
    err.mgr.output_message = jpegQuiet;
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&cinfo);
        return Error::make(Errc::BadFormat, "MJPEG frame corrupt");
    }
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, jpeg, static_cast<unsigned long>(bytes));
    jpeg_read_header(&cinfo, TRUE);
    cinfo.out_color_space = JCS_GRAYSCALE;
    jpeg_start_decompress(&cinfo);
    if (int(cinfo.output_width) != width || int(cinfo.output_height) != height || cinfo.output_components != 1) {
        char msg[96];
        std::snprintf(msg, sizeof msg, "MJPEG frame is %ux%u, the stream %dx%d", cinfo.output_width,
                      cinfo.output_height, width, height);
        jpeg_destroy_decompress(&cinfo);
        return Error::make(Errc::BadFormat, msg);
    }
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = dst + size_t(cinfo.output_scanline) * size_t(dstStride);
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    return {};
}

} // namespace icacam::hal
