#pragma once
// The 128 × 64 display as PNG pictures in a folder: every new picture is written as
// screen-NNNNNN.png (up to maxPictures, then only screen-latest.png is kept current), pixel for
// pixel at 1:1 (scale 1) or enlarged; white on black like the OLED.
#include <string>

#include "hal/display.h"

namespace icacam::hal {

class PngDisplay final : public Display {
public:
    Error open(const std::string &folder, int scale = 1, int maxPictures = 10000);
    Error show(const MonoBitmap &picture) override;
    int pictureCount() const { return count_; }

private:
    std::string folder_;
    int scale_ = 1;
    int maxPictures_ = 0;
    int count_ = 0;
    bool shown_ = false;
    MonoBitmap current_;
};

} // namespace icacam::hal
