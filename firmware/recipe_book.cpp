#include "firmware/recipe_book.h"

#include "firmware/recipe.h"

namespace icacam::fw {

hal::Error RecipeBook::start(const Config &configured, Config *cfg, std::string_view now,
                             std::vector<std::string> *problems)
{
    const AuditCheck c = log_.load();
    for (const std::string &p : c.problems) problems->push_back("audit trail: " + p);
    const std::string seed = recipeHash(recipeText(configured));
    hal::Result<std::string> lastSeed = storage_.read(kSeedFile);
    const bool edited = lastSeed.ok() && lastSeed.value.substr(0, 64) != seed;
    const AuditEntry *newest = log_.newest();
    if (newest && !edited) {
        Config trial = *cfg;
        if (std::string e = applyRecipeText(newest->settings, &trial); e.empty()) {
            *cfg = trial;
            active_ = {newest->recipe, newest->version, newest->hash, newest->settings};
        } else {
            problems->push_back(newest->recipe + " version " + std::to_string(newest->version) +
                                " is not valid with this config (" + e + "): the config's values are used");
            active_ = {newest->recipe, newest->version, newest->hash, newest->settings};
            if (hal::Error err = record(*cfg, newest->recipe, "device", "the stored version is not valid", now);
                !err.ok())
                return err;
        }
    } else if (newest) {
        // The config file's recipe keys were edited: they are the new version.
        active_ = {newest->recipe, newest->version, newest->hash, newest->settings};
        Config trial = *cfg;
        if (std::string e = applyRecipeText(recipeText(configured), &trial); !e.empty()) {
            problems->push_back("the config file's recipe is not valid (" + e + "): " + newest->recipe + " version " +
                                std::to_string(newest->version) + " stays");
            trial = *cfg;
            if (applyRecipeText(newest->settings, &trial).empty()) *cfg = trial;
        } else {
            if (hal::Error err =
                    record(trial, newest->recipe, "config file", "the config file's recipe keys changed", now);
                !err.ok() && err.code != hal::Errc::Invalid)
                return err;
            *cfg = trial;
        }
    } else {
        active_ = {kFirstId, 0, "", ""};
        if (hal::Error err = record(*cfg, kFirstId, "config file", "the first version: the config's recipe keys", now);
            !err.ok())
            return err;
    }
    if (!lastSeed.ok() || lastSeed.value.substr(0, 64) != seed)
        if (hal::Error err = storage_.writeAtomic(kSeedFile, seed + "\n"); !err.ok()) return err;
    return {};
}

hal::Error RecipeBook::record(const Config &trial, std::string_view id, std::string_view who, std::string_view why,
                              std::string_view now)
{
    const std::string text = recipeText(trial);
    if (text == active_.text && id == active_.id)
        return hal::Error::make(hal::Errc::Invalid, "nothing changed: " + active_.id + " version " +
                                                        std::to_string(active_.version) + " has these settings");
    AuditEntry e;
    e.time = std::string(now);
    e.who = std::string(who);
    e.why = std::string(why);
    e.changes = active_.text.empty() ? "" : recipeChanges(active_.text, text); // the first: no "old"
    e.recipe = std::string(id);
    e.version = log_.lastVersion(id) + 1;
    e.hash = recipeHash(text);
    e.settings = text;
    if (hal::Error err = log_.append(e); !err.ok()) return err;
    active_ = {e.recipe, e.version, e.hash, text};
    return {};
}

AuditCheck RecipeBook::check()
{
    hal::Result<std::string> log = storage_.read(kAuditFile), head = storage_.read(kAuditHead);
    std::vector<AuditEntry> entries;
    return checkAudit(log.ok() ? std::string_view(log.value) : std::string_view(),
                      head.ok() ? std::string_view(head.value) : std::string_view(), &entries);
}

} // namespace icacam::fw
