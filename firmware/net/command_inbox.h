#pragma once
// Command lines from the network for the device's loop: the same words or JSON a serial
// line carries, handled by the same parser and handler. A fixed ring of fixed-size slots,
// sized once: the network thread's push fails when the ring is full (the client is told
// to come back), and the device's pop never waits for a lock a network thread holds long.
#include <array>
#include <cstddef>
#include <mutex>
#include <string_view>

namespace icacam::fw::net {

class CommandInbox {
public:
    static constexpr size_t kSlots = 16;
    static constexpr size_t kMaxLine = 1024; // as a serial line

    // False when the line is too long or the ring is full.
    bool push(std::string_view line);
    // Copies the oldest line into out (kMaxLine bytes); its length, or 0 when empty.
    size_t pop(char *out);

private:
    struct Slot {
        std::array<char, kMaxLine> bytes;
        size_t size = 0;
    };
    std::mutex mutex_;
    std::array<Slot, kSlots> slots_{};
    size_t head_ = 0, used_ = 0;
};

} // namespace icacam::fw::net
