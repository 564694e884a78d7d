#pragma once
// A 5 × 7 bitmap font in 6 × 8 cells (the classic glcd font, public domain), ASCII 0x20–0x7E
// plus μ, σ and ±. The display's 128 × 64 holds 21 × 8 cells.
#include <cstdint>
#include <string>
#include <string_view>

#include "hal/display.h"

namespace icacam::fw {

constexpr int kCellWidth = 6;
constexpr int kCellHeight = 8;
constexpr int kColumns = hal::MonoBitmap::kWidth / kCellWidth; // 21
constexpr int kRows = hal::MonoBitmap::kHeight / kCellHeight;  // 8

// Glyph index for a code point; '?' for anything the font does not have.
int glyphIndex(uint32_t codePoint);
const uint8_t *glyphColumns(int index); // 5 column bytes, least significant bit on top
int glyphCount();

// Draws UTF-8 text at cell (col, row); returns the number of cells used. Clipped at the edge.
int drawText(hal::MonoBitmap *bmp, int col, int row, std::string_view utf8);
// Reads the text of one cell row back (exact glyph match; '\x01' for an unknown cell). For
// tests that check what the screen shows; μ/σ/± come back as UTF-8.
std::string readRow(const hal::MonoBitmap &bmp, int row);

} // namespace icacam::fw
