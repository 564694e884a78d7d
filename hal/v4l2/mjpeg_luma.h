#pragma once
// Decodes one MJPEG frame from a UVC camera into its luma plane (libjpeg-turbo reads the Y
// component straight out: no colour conversion). Most UVC cameras deliver 720p and above
// only as MJPEG, and many leave the Huffman tables out of each frame (the standard ones
// are meant); libjpeg-turbo supplies them.
#include <cstddef>
#include <cstdint>

#include "hal/error.h"

namespace icacam::hal {

// Writes width × height grey pixels, rows dstStride apart, into dst (capacity bytes). The
// frame must be exactly width × height. Errors: BadFormat (corrupt or another size), TooLarge.
Error decodeMjpegLuma(const uint8_t *jpeg, size_t bytes, uint8_t *dst, size_t capacity, int width, int height,
                      int dstStride);

} // namespace icacam::hal
