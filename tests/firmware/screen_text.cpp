// fw_screen_text PICTURE.png: prints the 8 text rows a display picture shows.
#include <cstdio>
#include <vector>

#include "firmware/font5x7.h"
#include "hal/file/image_decoder.h"

int main(int argc, char **argv)
{
    using namespace icacam;
    if (argc != 2) {
        std::fprintf(stderr, "usage: fw_screen_text PICTURE.png\n");
        return 64;
    }
    constexpr int kMaxScale = 8;
    std::vector<uint8_t> px(size_t(hal::MonoBitmap::kWidth) * hal::MonoBitmap::kHeight * kMaxScale * kMaxScale);
    hal::DecodedImage img;
    hal::Error e = hal::decodeImage(argv[1], px.data(), px.size(), hal::MonoBitmap::kWidth * kMaxScale,
                                    hal::MonoBitmap::kHeight * kMaxScale, 0, &img);
    if (!e.ok() || img.channels != 1) {
        std::fprintf(stderr, "fw_screen_text: %s\n", e.message.c_str());
        return 1;
    }
    const int scale = img.width / hal::MonoBitmap::kWidth;
    if (scale < 1 || img.width != scale * hal::MonoBitmap::kWidth || img.height != scale * hal::MonoBitmap::kHeight) {
        std::fprintf(stderr, "fw_screen_text: not a picture of the 128x64 display\n");
        return 1;
    }
    hal::MonoBitmap bmp;
    for (int y = 0; y < hal::MonoBitmap::kHeight; ++y)
        for (int x = 0; x < hal::MonoBitmap::kWidth; ++x)
            bmp.set(x, y, px[size_t(y * scale * img.stride + x * scale)] > 127);
    for (int r = 0; r < fw::kRows; ++r) std::printf("%s\n", fw::readRow(bmp, r).c_str());
    return 0;
}
