// Recipes on the device: every change of a recipe key (a web save, `set` over serial, `lens`,
// `focus`) is a new version with its audit entry, written before the change takes effect;
// every record names the version in effect. Aim mode's live controls move the camera
// without a version, and go back to the recipe's when aim mode ends. The camera follows
// either on the run (firmware/recipe_camera.h), between measurements.
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
    if (std::string e = moveCamera(running, trial); !e.empty()) return e;
    if (hal::Error saved = recipes_.record(trial, id, who, why, wallTime()); !saved.ok()) {
        (void)moveCamera(trial, running); // the camera back as it was
        return saved.message;
    }
    cfg_ = trial;
    liveOn_ = false;
    persistSettings();
    publishRecipe();
    return "";
}

std::string Device::moveCamera(const Config &from, const Config &to)
{
    if (hal_.recipeCamera) return hal_.recipeCamera->follow(from, to).message;
    if (RecipeCamera::needsRemake(from, to))
        return "this camera takes its white balance and automatic controls only when it starts";
    const hal::CameraControls change = changedControls(cameraControlsOf(from), cameraControlsOf(to));
    if (!hal::anyControlSet(change)) return "";
    return hal_.camera.setControls(change).error.message;
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
    if (err.empty()) err = moveCamera(liveOn_ ? live_ : cfg_, trial);
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
    if (std::string e = moveCamera(live_, cfg_); !e.empty())
        sendError("camera", "back to the recipe's controls: " + e, "");
    publishRecipe();
}

} // namespace icacam::fw
