// Settings over serial: `set KEY VALUE` checked on a copy, kept and saved to settings.conf,
// restored from it at start; a recipe key becomes a new recipe version (device_recipe.cpp).
#include "firmware/device.h"

#include "firmware/recipe.h"

namespace icacam::fw {

namespace {

constexpr const char *kSettingsFile = "settings.conf";

} // namespace

std::string Device::restoreSettings()
{
    std::string note;
    if (auto saved = hal_.storage.read(kSettingsFile); saved.ok()) {
        Config trial = cfg_;
        std::string_view t = saved.value;
        while (!t.empty()) {
            const size_t nl = t.find('\n');
            std::string_view line = t.substr(0, nl);
            t.remove_prefix(nl == std::string_view::npos ? t.size() : nl + 1);
            const size_t eq = line.find(" = ");
            if (eq == std::string_view::npos) continue;
            if (!setConfigKey(&trial, line.substr(0, eq), line.substr(eq + 3), true).empty())
                note = "saved setting bad";
        }
        // A saved calibration that can no longer be read leaves the configured one in place.
        if (trial.calibrationFile != cfg_.calibrationFile && !setCalibrationFile(&trial).empty()) {
            trial.calibrationFile = cfg_.calibrationFile;
            note = "saved setting bad";
        }
        cfg_ = trial;
    }
    return note;
}

bool Device::applySetting(const Command &c, reading::JsonBuilder &j)
{
    Config trial = cfg_;
    std::string err = setConfigKey(&trial, c.key, c.value, true);
    if (err.empty()) err = specimenIssue(trial);
    // A recipe key: a new version of the recipe, its audit entry naming where it came from.
    if (const std::string key = recipeKeyOf(c.key); err.empty() && !key.empty()) {
        err = applyRecipe(trial, recipes_.active().id, lineOrigin_,
                          "set " + key + " " + c.value + " (" + lineOrigin_ + " command)");
        if (!err.empty()) {
            sendError("bad_argument", err, c.tag);
            return false;
        }
        std::string v;
        bool num = false;
        getConfigKey(cfg_, c.key, &v, &num);
        j.str("type", "settings");
        num ? j.raw(c.key, v) : j.str(c.key, v);
        appendRecipe(j);
        showIdle("");
        return true;
    }
    if (err.empty() && liveKeyName(c.key) == "calibration_file") err = setCalibrationFile(&trial);
    if (err.empty() && liveKeyName(c.key) == "stamp_delay_us" && trial.stampDelayUs >= 0)
        if (hal::Error e = hal_.camera.setStampDelayUs(trial.stampDelayUs); !e.ok()) err = e.message;
    if (!err.empty()) {
        sendError("bad_argument", err, c.tag);
        return false;
    }
    cfg_ = trial;
    persistSettings();
    std::string v;
    bool num = false;
    getConfigKey(cfg_, c.key, &v, &num);
    j.str("type", "settings");
    num ? j.raw(c.key, v) : j.str(c.key, v);
    showIdle("");
    return true;
}

void Device::persistSettings()
{
    std::string text;
    for (const std::string &k : configKeys(true)) {
        if (k == "mm_per_px" && cfg_.mmPerPx == 0) continue; // not given: a calibration file scales
        std::string v;
        bool num = false;
        getConfigKey(cfg_, k, &v, &num);
        text += k + " = " + v + "\n";
    }
    if (hal::Error e = hal_.storage.writeAtomic(kSettingsFile, text); !e.ok())
        sendError("storage", "setting not saved: " + e.message, "");
}

void Device::useCalibration(const DeviceCalibration &cal)
{
    instrument_.setCalibration(cal.present ? &cal.file.plane : nullptr, cal.file.imageWidth, cal.file.imageHeight);
}

std::string Device::setCalibrationFile(Config *trial)
{
    if (trial->calibrationFile == "none") trial->calibrationFile.clear();
    if (trial->calibrationFile.empty() && !(trial->mmPerPx > 0))
        return "no scale would be left: set mm_per_px before removing calibration_file";
    DeviceCalibration d;
    if (std::string e = loadDeviceCalibration(*trial, &d); !e.empty()) return e;
    cal_ = d;
    useCalibration(cal_);
    return "";
}

} // namespace icacam::fw
