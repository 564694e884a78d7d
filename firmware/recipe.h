#pragma once
// The recipe: the settings a measurement is made with, as opposed to the device's own (its
// backends, paths, network, display). Recipe keys: the specimen (n, K, D0, H0, final height,
// material), the tolerances, the scale (calibration.mm_per_px) and the camera's imaging
// controls (exposure, gains, white balance, lens position, sharpening, noise reduction).
// The device keys stay in the config: the camera calibration file and the camera's stamp
// delay belong to the mounted camera, reading.model to the installed instrument.
//
// A recipe's content is its canonical text: one `key = value` line per recipe key, in
// kRecipeKeys' order, each value as the config prints it; its hash is the SHA-256 of that
// text, so the same settings always have the same hash. A recipe is applied to a config with
// the config's own rules (setConfigKey for each key, then crossKeyIssues): no second set of
// rules.
#include <string>
#include <string_view>

#include "firmware/config.h"

namespace icacam::fw {

inline constexpr const char *kRecipeKeys[] = {
    "specimen.n",
    "specimen.k_mpa",
    "specimen.d0_mm",
    "specimen.h0_mm",
    "specimen.h_final_mm",
    "specimen.material",
    "tolerance.mu",
    "tolerance.rel",
    "tolerance.n",
    "tolerance.h_final_mm",
    "tolerance.mm_per_px",
    "calibration.mm_per_px",
    "calibration.working_distance_mm",
    "camera.exposure_us",
    "camera.analogue_gain",
    "camera.red_gain",
    "camera.blue_gain",
    "camera.white_balance_k",
    "camera.lens_position",
    "camera.sharpness",
    "camera.noise_reduction",
};

bool isRecipeKey(std::string_view key);
// The full name of a recipe key given by its full or serial name ("" when not a recipe key).
std::string recipeKeyOf(std::string_view key);
// A recipe's name: 1-32 letters, digits, '-', '_' or '.'.
bool validRecipeId(std::string_view id);
// The recipe keys of cfg as canonical text.
std::string recipeText(const Config &cfg);
// SHA-256 of text, 64 lower-case hex digits.
std::string recipeHash(std::string_view text);
// Sets the `key = value` lines of text (recipe keys only; keys not given keep cfg's value)
// on cfg, validated as the config is (each key by setConfigKey; of the rules between keys,
// crossKeyIssues, the ones the recipe breaks). "" or every problem, "; " separated (cfg is then
// partly changed: apply to a copy).
std::string applyRecipeText(std::string_view text, Config *cfg);
// What differs between two canonical texts: "key: old -> new; ..." ("" when the same).
std::string recipeChanges(std::string_view from, std::string_view to);

} // namespace icacam::fw
