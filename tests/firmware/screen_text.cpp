// fw_screen_text PICTURE.png: prints the 8 text rows a display picture shows.
#include <cstdio>
#include <vector>

#include "firmware/font5x7.h"
#include "hal/file/image_decoder.h"

int main(int argc, char **argv)
{
    using namespace icacam;
    if (argc != 2) { std::fprintf(stderr, "usage: fw_screen_text PICTURE.png\n"); return 64; }
    std::vector<uint8_t> px(size_t(hal::MonoBitmap::kWidth) * hal::MonoBitmap::kHeight);
    hal::DecodedImage img;
    hal::Error e = hal::decodeImage(argv[1], px.data(), px.size(), hal::MonoBitmap::kWidth, hal::MonoBitmap::kHeight, 0, &img);
    if (!e.ok() || img.channels != 1) { std::fprintf(stderr, "fw_screen_text: %s\n", e.message.c_str()); return 1; }
    hal::MonoBitmap bmp;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) bmp.set(x, y, px[size_t(y * img.stride + x)] > 127);
    for (int r = 0; r < fw::kRows; ++r) std::printf("%s\n", fw::readRow(bmp, r).c_str());
    return 0;
}
