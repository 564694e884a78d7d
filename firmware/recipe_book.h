#pragma once
// The device's recipes: the version in effect, and every change made as a new version with
// an audit entry (firmware/audit_log.h) before it takes effect. Across restarts the newest
// version in the trail is in effect; the config file's recipe keys make the first version,
// and a new one whenever they are edited (the hash of what the config file said at the last
// start is kept in recipe.seed, so an edit is told from the config the device started with).
#include <string>
#include <string_view>
#include <vector>

#include "firmware/audit_log.h"
#include "firmware/config.h"
#include "hal/storage.h"

namespace icacam::fw {

struct RecipeVersion {
    std::string id;
    long version = 0;
    std::string hash, text; // text: canonical (firmware/recipe.h)
};

class RecipeBook {
public:
    static constexpr const char *kSeedFile = "recipe.seed";
    static constexpr const char *kFirstId = "default";

    explicit RecipeBook(hal::Storage &storage) : storage_(storage), log_(storage) {}
    // configured: the config file's values; *cfg: the settings in effect, to which the
    // version in effect is applied. What is wrong with the trail, or with a stored version,
    // goes to *problems (the device says it); the error: the trail cannot be written.
    hal::Error start(const Config &configured, Config *cfg, std::string_view now, std::vector<std::string> *problems);
    // trial (a whole config, validated and applied by the caller) as the next version of id:
    // the audit entry fsynced, then it is the version in effect. Invalid when nothing
    // changed; Full, Io from storage.
    hal::Error record(const Config &trial, std::string_view id, std::string_view who, std::string_view why,
                      std::string_view now);
    const RecipeVersion &active() const { return active_; }
    // The trail read again and checked.
    AuditCheck check();

private:
    hal::Storage &storage_;
    AuditLog log_;
    RecipeVersion active_;
};

} // namespace icacam::fw
