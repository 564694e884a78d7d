#include "firmware/net/aim_exchange.h"

#include "firmware/net/pgm_png.h"

namespace icacam::fw::net {

AimExchange::AimExchange() : pixels_(std::make_unique<uint8_t[]>(size_t(kMaxWidth) * kMaxHeight)) {}

void AimExchange::onAimPicture(const vision::LumaView &v)
{
    if (!v.valid()) return;
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    int step = 1;
    while ((v.width + step - 1) / step > kMaxWidth || (v.height + step - 1) / step > kMaxHeight) ++step;
    width_ = (v.width + step - 1) / step;
    height_ = (v.height + step - 1) / step;
    step_ = step;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) pixels_[size_t(y) * size_t(width_) + size_t(x)] = v.at(x * step, y * step);
    ++picture_;
}

std::string AimExchange::png(std::string *out, long *picture, int *step) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    *picture = picture_;
    *step = step_;
    if (picture_ == 0) return "";
    return pgmToPng({width_, height_, pixels_.get()}, 1, out);
}

} // namespace icacam::fw::net
