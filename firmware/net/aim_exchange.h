#pragma once
// Aim mode's newest picture for the web page: each picture the device takes while aiming,
// copied at every step-th pixel (the step that brings it within kMaxWidth x kMaxHeight) into
// a buffer sized once. The device's copy skips a picture while the web thread is reading
// the last one, rather than wait.
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "firmware/net/device_listener.h"

namespace icacam::fw::net {

class AimExchange final : public DeviceListener {
public:
    static constexpr int kMaxWidth = 800, kMaxHeight = 600;

    AimExchange();
    void onLine(std::string_view) override {}
    void onJournaled(long) override {}
    void onAimPicture(const vision::LumaView &v) override;

    // The newest picture as PNG and its number (0: none yet); "" or what went wrong.
    std::string png(std::string *out, long *picture, int *step) const;

private:
    mutable std::mutex mutex_;
    std::unique_ptr<uint8_t[]> pixels_;
    int width_ = 0, height_ = 0, step_ = 1;
    long picture_ = 0;
};

} // namespace icacam::fw::net
