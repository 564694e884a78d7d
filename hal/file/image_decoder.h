#pragma once
// Decodes PNG (libpng), JPEG (libjpeg-turbo) and binary PGM into a caller-owned buffer of
// fixed capacity. Not OpenCV: the file-backed HAL must build where OpenCV is absent.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hal/error.h"

namespace icacam::hal {

struct DecodedImage {
    int width = 0;
    int height = 0;
    int channels = 0; // 1 grey, 3 RGB
    int stride = 0;   // bytes per row in the destination buffer
};

// Decodes path into dst (capacity bytes). Rows are placed stride bytes apart, where stride is
// minStride if it is at least width × channels, otherwise width × channels. RGBA and 16-bit
// inputs are reduced to RGB / 8 bit; palette PNGs are expanded. Errors: NotFound, BadFormat,
// TooLarge (more than maxWidth × maxHeight or more than capacity), BadStride never.
Error decodeImage(const std::string &path, uint8_t *dst, size_t capacity, int maxWidth, int maxHeight, int minStride,
                  DecodedImage *out);

// Writes an 8-bit grey or RGB image as PNG (compression level 1: fast, for test pictures).
Error writePng(const std::string &path, const uint8_t *data, int width, int height, int channels, int stride);

} // namespace icacam::hal
