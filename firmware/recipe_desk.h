#pragma once
// Recipe changes from the web for the device's loop, and the device's recipe for the web:
// one waiting request at a time (a second is refused: the client tries again), taken by the
// device between measurements without waiting for a lock a web thread holds; and the
// version in effect, published by the device after each change for the web to read.
#include <mutex>
#include <string>
#include <string_view>

#include "firmware/recipe_book.h"

namespace icacam::fw {

class RecipeDesk {
public:
    struct Request {
        // Save: text (`key = value` lines of recipe keys) over the version in effect, as the
        // next version of id. Live: aim mode's camera controls (camera.* recipe keys in
        // text), not saved; they end with aim mode.
        enum class Kind { Save, Live } kind = Kind::Save;
        std::string tag, who, why, id, text;
    };

    // From a web thread; false when a request is waiting.
    bool post(Request r);
    // From the device; false when none is waiting (or a web thread holds the lock).
    bool take(Request *out);

    // From the device: the version in effect and aim mode's live controls ("" when none).
    void publish(const RecipeVersion &v, std::string_view live);
    RecipeVersion inEffect(std::string *live) const;

private:
    mutable std::mutex mutex_;
    Request waiting_;
    bool hasWaiting_ = false;
    RecipeVersion published_;
    std::string live_;
};

} // namespace icacam::fw
