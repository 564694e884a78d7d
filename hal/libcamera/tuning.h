#pragma once
// A fixed tone curve on a Raspberry Pi camera: the project's own tuning override with
// adaptive contrast off and the gamma curve the pipeline is told (camera.tone_gamma).
//
// The Raspberry Pi IPA's contrast algorithm re-stretches the gamma curve from each frame's
// luma histogram when "ce_enable" is set (Contrast::process, src/ipa/rpi/controller/rpi/
// contrast.cpp; read() defaults it to 1), and the tuning files of the imx708, imx477,
// imx219 and ov5647 set it to 1: grey levels then move from shot to shot with what is in
// view. No control turns only that off: the IPA disables it as a side effect of HdrMode
// (ipa_base.cpp), which also changes exposure channels and denoise. What libcamera exposes
// is the tuning file itself: LIBCAMERA_RPI_TUNING_FILE names one file for every camera,
// and LIBCAMERA_IPA_CONFIG_PATH lists directories searched before the system ones for
// "<ipa module>/<sensor model>.json" (IPAProxy::configurationFile, src/libcamera/
// ipa_proxy.cpp, 0.0.3 to 0.7; Documentation/runtime_configuration.rst). The override
// copies the system's file for the sensor with "ce_enable": 0 into a directory of its own,
// for every Raspberry Pi IPA module that has one (rpi/pisp on a Pi 5, rpi/vc4 on a Pi 4,
// raspberrypi before libcamera 0.1), so libcamera picks the right platform's file itself.
//
// The same block's "gamma_curve" (a piecewise-linear map of 16-bit levels, used as is where
// adaptive contrast is off and the Contrast and Brightness controls are at 1 and 0) is the
// camera's tone curve. The sensors' files hold an S-shaped contrast curve that no single
// exponent describes, and a tone curve moves a blurred edge's steepest point towards its
// dark side (vision/tone_curve.h): the override writes the curve the pipeline is told,
// linear^(1/γ), linear luma at γ = 1.
#include <span>
#include <string>
#include <string_view>

#include "hal/error.h"

namespace icacam::hal {

// The tuning file's text with the "rpi.contrast" block's "ce_enable" set to 0 (inserted
// when the block relies on the default). Errors: BadFormat (no "rpi.contrast" block, or a
// block that is not an object).
Error withoutAdaptiveContrast(std::string_view tuning, std::string *out);

// The same with the block's "gamma_curve" (replaced, or inserted where absent) the power
// curve linear^(1/gamma) on 16-bit levels: [0, 0, 65535, 65535] at gamma 1, else 33 points
// spaced quadratically (denser in the shadows, where the curve bends most). gamma in 1–3.
Error withFixedTone(std::string_view tuning, double gamma, std::string *out);

// Where libcamera installs its IPA data (IPA_CONFIG_DIR: sysconfdir, then datadir).
inline constexpr std::string_view kIpaDataDirs[] = {"/etc/libcamera/ipa", "/usr/share/libcamera/ipa",
                                                    "/usr/local/share/libcamera/ipa"};
// The Raspberry Pi IPA modules' names, the sub-directories their tuning files live in.
inline constexpr std::string_view kRpiIpaModules[] = {"rpi/pisp", "rpi/vc4", "raspberrypi"};

struct TuningOverride {
    int files = 0;      // tuning files written (one per IPA module that has the sensor)
    std::string source; // the first system file they were made from
};

// Writes `outDir`/<module>/<model>.json with adaptive contrast off and the tone curve
// linear^(1/gamma) (withFixedTone) for each Raspberry Pi IPA module whose tuning file for
// `model` is found under `dataDirs` (first directory wins, as libcamera searches them).
// `files` = 0 when no directory has the model (not a Raspberry Pi pipeline, or an unknown
// sensor): nothing to override. Errors: Io, BadFormat, Invalid (gamma outside 1–3).
Error writeFixedToneTuning(std::span<const std::string_view> dataDirs, std::string_view model,
                           const std::string &outDir, double gamma, TuningOverride *out);

} // namespace icacam::hal
