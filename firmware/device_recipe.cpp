// Recipes on the device: every change of a recipe key (a web save, `set` over serial, `lens`,
// `focus`) is a new version with its audit entry, written before the change takes effect;
// every record names the version in effect. Aim mode's live controls move the camera
// without a version, and go back to the recipe's when aim mode ends.
#include <cstdio>
#include <ctime>

#include "firmware/device.h"
#include "firmware/recipe.h"

namespace icacam::fw {

std::string Device::wallTime() const
{
    const int64_t ms = hal_.clock.wallMs();
    const time_t s = time_t(ms / 1000);
    tm t{};
    gmtime_r(&s, &t);
    char b[40];
    std::snprintf(b, sizeof b, "%04d-%02d-%02dT%02d:%02d:%02dZ", t.tm_year + 1900, t.tm_mon + 1, t.tm_mday, t.tm_hour,
                  t.tm_min, t.tm_sec);
    return b;
}

void Device::appendRecipe(reading::JsonBuilder &j) const
{
    const RecipeVersion &r = recipes_.active();
    j.str("recipe", r.id).integer("recipe_version", r.version).str("recipe_hash", r.hash);
}

void Device::publishRecipe()
{
    if (desk_) desk_->publish(recipes_.active(), liveOn_ ? recipeChanges(recipeText(cfg_), recipeText(live_)) : "");
}

std::string Device::applyRecipe(const Config &trial, std::string_view id, std::string_view who, std::string_view why)
{
    if (!validRecipeId(id)) return "a recipe id is 1-32 letters, digits, '-', '_' or '.'";
    if (id == recipes_.active().id && recipeText(trial) == recipes_.active().text && !liveOn_) {
        cfg_ = trial; // nothing of the recipe changes: no version
        return "";
    }
    // The camera as the version in effect, while aim's live controls are not.
    const Config &running = liveOn_ ? live_ : cfg_;
    const bool remake = cameraStartControlsDiffer(trial, running);
    if (remake && !hal_.recipeCamera) return "this camera takes exposure, gains and white balance only when it starts";
    if (remake)
        if (hal::Error e = hal_.recipeCamera->setStartControls(trial); !e.ok()) return "camera: " + e.message;
    const bool moveLens = trial.lensPosition >= 0 && trial.lensPosition != running.lensPosition;
    hal::Error lens = moveLens ? hal_.camera.setLensPosition(trial.lensPosition) : hal::Error{};
    hal::Error saved = lens.ok() ? recipes_.record(trial, id, who, why, wallTime()) : hal::Error{};
    if (!lens.ok() || !saved.ok()) { // the camera back as it was
        if (remake) (void)hal_.recipeCamera->setStartControls(running);
        if (moveLens && running.lensPosition >= 0) (void)hal_.camera.setLensPosition(running.lensPosition);
        return !lens.ok() ? lens.message : saved.message;
    }
    cfg_ = trial;
    liveOn_ = false;
    persistSettings();
    publishRecipe();
    return "";
}

void Device::pollRecipeDesk()
{
    if (!desk_ || !desk_->take(&deskRequest_)) return;
    if (deskRequest_.kind == RecipeDesk::Request::Kind::Save)
        saveRecipe(deskRequest_);
    else
        liveControls(deskRequest_);
}

void Device::saveRecipe(const RecipeDesk::Request &r)
{
    // The form's keys over the version in effect, by the config's own rules.
    Config trial = cfg_;
    std::string err = applyRecipeText(r.text, &trial);
    if (err.empty() && r.why.empty()) err = "a reason is required";
    if (err.empty()) err = applyRecipe(trial, r.id.empty() ? recipes_.active().id : r.id, r.who, r.why);
    if (!err.empty()) {
        sendError("recipe_refused", err, r.tag);
        return;
    }
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "recipe");
    appendRecipe(j);
    j.str("who", r.who).str("why", r.why);
    if (!r.tag.empty()) j.str("tag", r.tag);
    j.end();
    send(out_);
    showIdle("recipe saved");
}

void Device::liveControls(const RecipeDesk::Request &r)
{
    if (aimUntilMs_ < 0) {
        sendError("recipe_refused", "live controls only while aiming", r.tag);
        return;
    }
    Config trial = liveOn_ ? live_ : cfg_;
    std::string err;
    for (std::string_view t = r.text; !t.empty() && err.empty();) {
        const size_t nl = t.find('\n');
        const std::string_view line = t.substr(0, nl);
        t.remove_prefix(nl == std::string_view::npos ? t.size() : nl + 1);
        if (!line.empty() && line.substr(0, 7) != "camera.") err = "live controls are the camera's keys only";
    }
    if (err.empty()) err = applyRecipeText(r.text, &trial);
    const Config &running = liveOn_ ? live_ : cfg_;
    if (err.empty() && cameraStartControlsDiffer(trial, running)) {
        if (!hal_.recipeCamera)
            err = "this camera takes exposure, gains and white balance only when it starts";
        else if (hal::Error e = hal_.recipeCamera->setStartControls(trial); !e.ok())
            err = "camera: " + e.message;
    }
    if (err.empty() && trial.lensPosition >= 0 && trial.lensPosition != running.lensPosition)
        if (hal::Error e = hal_.camera.setLensPosition(trial.lensPosition); !e.ok()) err = "lens: " + e.message;
    if (!err.empty()) {
        sendError("recipe_refused", err, r.tag);
        return;
    }
    live_ = trial;
    liveOn_ = true;
    publishRecipe();
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "live").str("changes", recipeChanges(recipeText(cfg_), recipeText(live_)));
    if (!r.tag.empty()) j.str("tag", r.tag);
    j.end();
    send(out_);
}

void Device::endLiveControls()
{
    if (!liveOn_) return;
    liveOn_ = false;
    if (hal_.recipeCamera)
        if (hal::Error e = hal_.recipeCamera->setStartControls(cfg_); !e.ok())
            sendError("camera", "back to the recipe's controls: " + e.message, "");
    if (cfg_.lensPosition >= 0 && cfg_.lensPosition != live_.lensPosition)
        if (hal::Error e = hal_.camera.setLensPosition(cfg_.lensPosition); !e.ok())
            sendError("lens_failed", "back to the recipe's lens position: " + e.message, "");
    publishRecipe();
}

} // namespace icacam::fw
