#pragma once
// A journal frame (binary PGM, as the device saves it) as a PNG for a browser, every
// step-th pixel of every step-th row (step 1-8).
#include <string>
#include <string_view>

namespace icacam::fw::net {

struct PgmView {
    int width = 0, height = 0;
    const unsigned char *pixels = nullptr; // width * height bytes, rows packed
};

// Reads a P5 header with maxval 255; "" or what is wrong with it.
std::string parsePgm(std::string_view bytes, PgmView *out);
// Appends the PNG to *png; "" or what went wrong.
std::string pgmToPng(const PgmView &pgm, int step, std::string *png);

} // namespace icacam::fw::net
