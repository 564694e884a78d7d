#include "firmware/net/command_inbox.h"

#include <cstring>

namespace icacam::fw::net {

bool CommandInbox::push(std::string_view line)
{
    if (line.empty() || line.size() > kMaxLine) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    if (used_ == kSlots) return false;
    Slot &s = slots_[(head_ + used_) % kSlots];
    std::memcpy(s.bytes.data(), line.data(), line.size());
    s.size = line.size();
    ++used_;
    return true;
}

size_t CommandInbox::pop(char *out)
{
    // The device's loop does not wait: a network thread in push holds the lock for one copy.
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || used_ == 0) return 0;
    const Slot &s = slots_[head_];
    std::memcpy(out, s.bytes.data(), s.size);
    const size_t n = s.size;
    head_ = (head_ + 1) % kSlots;
    --used_;
    return n;
}

} // namespace icacam::fw::net
