#pragma once
// What the 128 × 64 display shows: pages composed from short words, 21 × 8 characters.
#include <string>
#include <string_view>

#include "firmware/config.h"
#include "hal/display.h"
#include "reading/reading.h"

namespace icacam::fw {

// Short words for the display (the serial line carries the long message).
const char *shortError(vision::ErrorCode c);
const char *shortFlag(int bit);

void drawIdle(hal::MonoBitmap *bmp, const Config &cfg, long records, std::string_view note);
void drawBusy(hal::MonoBitmap *bmp, long id);
void drawResult(hal::MonoBitmap *bmp, long id, const reading::Reading &m, std::string_view note);
// A device-level problem (camera timeout, storage full …): title and words, wrapped.
void drawProblem(hal::MonoBitmap *bmp, std::string_view title, std::string_view words);
void drawSettings(hal::MonoBitmap *bmp, const Config &cfg);

} // namespace icacam::fw
