#include "hal/file/png_display.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "hal/file/image_decoder.h"

namespace icacam::hal {

Error PngDisplay::open(const std::string &folder, int scale, int maxPictures)
{
    if (scale < 1 || scale > 8) return Error::make(Errc::Invalid, "display scale must be 1..8");
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) return Error::make(Errc::Io, "display folder '" + folder + "': " + ec.message());
    folder_ = folder;
    scale_ = scale;
    maxPictures_ = maxPictures;
    return {};
}

Error PngDisplay::show(const MonoBitmap &picture)
{
    if (folder_.empty()) return Error::make(Errc::Invalid, "display not opened");
    if (shown_ && picture == current_) return {}; // the panel keeps what it shows
    current_ = picture;
    shown_ = true;
    const int w = MonoBitmap::kWidth * scale_, h = MonoBitmap::kHeight * scale_;
    std::vector<uint8_t> px(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            px[size_t(y) * size_t(w) + size_t(x)] = picture.get(x / scale_, y / scale_) ? 255 : 0;
    const std::string latest = folder_ + "/screen-latest.png";
    if (Error e = writePng(latest + ".tmp", px.data(), w, h, 1, w); !e.ok()) return e;
    std::error_code ec;
    std::filesystem::rename(latest + ".tmp", latest, ec);
    if (count_ < maxPictures_) {
        char name[32];
        std::snprintf(name, sizeof name, "/screen-%06d.png", count_ + 1);
        std::filesystem::copy_file(latest, folder_ + name, std::filesystem::copy_options::overwrite_existing, ec);
        if (ec) return Error::make(Errc::Io, "display picture: " + ec.message());
    }
    ++count_;
    return {};
}

} // namespace icacam::hal
