#pragma once
// The device's recent words, for the web: the last kLines lines it said (answers, results,
// errors), kept in strings sized once, so the device's onLine copies and never allocates.
// A line longer than kMaxLine is kept cut and marked so. The web finds the answers to its
// own commands by their tag.
#include <array>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "firmware/net/device_listener.h"

namespace icacam::fw::net {

class LineExchange final : public DeviceListener {
public:
    static constexpr size_t kLines = 64;
    static constexpr size_t kMaxLine = 4096;

    LineExchange();
    void onLine(std::string_view line) override;
    void onJournaled(long id) override;

    // The lines (without '\n') whose "tag" is tag, oldest first.
    std::vector<std::string> answers(std::string_view tag) const;
    long newestJournaled() const;
    // The newest line of this "type" ("" when none is kept).
    std::string newestOfType(std::string_view type) const;

private:
    mutable std::mutex mutex_;
    std::array<std::string, kLines> lines_;
    size_t head_ = 0, used_ = 0;
    long newest_ = 0;
};

} // namespace icacam::fw::net
