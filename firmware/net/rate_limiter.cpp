#include "firmware/net/rate_limiter.h"

#include <algorithm>

namespace icacam::fw::net {

bool RateLimiter::allow(uint64_t address, int64_t nowMs)
{
    std::lock_guard<std::mutex> lock(mutex_);
    Bucket *b = nullptr, *idlest = &buckets_[0];
    for (Bucket &c : buckets_) {
        if (c.used && c.address == address) {
            b = &c;
            break;
        }
        if (!c.used || (idlest->used && c.lastMs < idlest->lastMs)) idlest = &c;
    }
    if (!b) {
        b = idlest;
        *b = {address, burst_, nowMs, true};
    }
    b->tokens = std::min(burst_, b->tokens + double(nowMs - b->lastMs) * rate_ / 1000.0);
    b->lastMs = nowMs;
    if (b->tokens < 1) return false;
    b->tokens -= 1;
    return true;
}

} // namespace icacam::fw::net
