#include "firmware/recipe_desk.h"

namespace icacam::fw {

bool RecipeDesk::post(Request r)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (hasWaiting_) return false;
    waiting_ = std::move(r);
    hasWaiting_ = true;
    return true;
}

bool RecipeDesk::take(Request *out)
{
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || !hasWaiting_) return false;
    *out = std::move(waiting_);
    hasWaiting_ = false;
    return true;
}

void RecipeDesk::publish(const RecipeVersion &v, std::string_view live)
{
    std::lock_guard<std::mutex> lock(mutex_);
    published_ = v;
    live_.assign(live);
}

RecipeVersion RecipeDesk::inEffect(std::string *live) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (live) *live = live_;
    return published_;
}

} // namespace icacam::fw
