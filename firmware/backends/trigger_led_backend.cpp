#include "firmware/backends/trigger_led_backend.h"

#include <vector>

#include "firmware/backends/backend_config.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#ifdef ICACAM_HAVE_GPIOD
#include "hal/gpiod/gpiod_lines.h"
#endif

namespace icacam::fw {

namespace {

using TriggerResult = hal::Result<std::unique_ptr<hal::TriggerButton>>;
using LedResult = hal::Result<std::unique_ptr<hal::LedRing>>;

#ifdef ICACAM_HAVE_GPIOD
constexpr bool kGpiod = true;

// Button to ground with the SoC's pull-up (pressed = low); LED ring through a driver
// transistor (on = high). docs/hardware.md has the wiring.
TriggerResult openGpiodTrigger(const Config &cfg, hal::Clock &clock)
{
    hal::GpioLineSpec button;
    button.chipPath = cfg.gpioChip;
    hal::parseGpioLine(cfg.triggerLine, &button);
    button.activeLow = cfg.triggerActive == "low";
    button.pullUp = cfg.triggerBias == "pull-up";
    button.pullDown = cfg.triggerBias == "pull-down";
    button.biasOff = cfg.triggerBias == "disabled";
    button.debounceUs = cfg.debounceMs * 1000 / 2; // the kernel takes the bounce, the firmware the rest
    auto trigger = std::make_unique<hal::GpiodTrigger>(clock);
    if (hal::Error e = trigger->open(button); !e.ok()) return {nullptr, e};
    return {std::move(trigger), {}};
}

// One line, or a segmented ring's lines (segment 0 first), all at the same active level.
LedResult openGpiodLed(const Config &cfg)
{
    std::vector<hal::GpioLineSpec> ring;
    for (const std::string &line : ledLines(cfg)) {
        hal::GpioLineSpec spec;
        spec.chipPath = cfg.ledChip.empty() ? cfg.gpioChip : cfg.ledChip;
        hal::parseGpioLine(line, &spec);
        spec.activeLow = cfg.ledActive == "low";
        ring.push_back(spec);
    }
    auto led = std::make_unique<hal::GpiodLed>();
    if (hal::Error e = led->open(ring); !e.ok()) return {nullptr, e};
    return {std::move(led), {}};
}
#else
constexpr bool kGpiod = false;
TriggerResult openGpiodTrigger(const Config &, hal::Clock &)
{
    return TriggerResult::fail(hal::Errc::Invalid, "gpiod not built");
}
LedResult openGpiodLed(const Config &)
{
    return LedResult::fail(hal::Errc::Invalid, "gpiod not built");
}
#endif

} // namespace

std::string triggerBackendIssue(const Config &cfg)
{
    if (cfg.triggerBackend == "file" || (kGpiod && cfg.triggerBackend == "gpiod")) return "";
    return notBuiltIssue("trigger.backend", cfg.triggerBackend, "file");
}

std::string ledBackendIssue(const Config &cfg)
{
    if (cfg.ledBackend == "file" || (kGpiod && cfg.ledBackend == "gpiod")) return "";
    return notBuiltIssue("led.backend", cfg.ledBackend, "file");
}

hal::Result<std::unique_ptr<hal::TriggerButton>> makeTrigger(const Config &cfg, hal::Clock &clock)
{
    if (cfg.triggerBackend == "file") {
        auto trigger = std::make_unique<hal::FileTrigger>(clock);
        if (!cfg.triggerScript.empty())
            if (hal::Error e = trigger->open(pathFromConfig(cfg, cfg.triggerScript)); !e.ok()) return {nullptr, e};
        return {std::move(trigger), {}};
    }
    if (kGpiod && cfg.triggerBackend == "gpiod") return openGpiodTrigger(cfg, clock);
    return TriggerResult::fail(hal::Errc::Invalid, triggerBackendIssue(cfg));
}

hal::Result<std::unique_ptr<hal::LedRing>> makeLed(const Config &cfg, hal::Clock &clock, hal::ScriptedLight *light)
{
    if (cfg.ledBackend == "file") {
        auto led = std::make_unique<hal::FileLed>(clock, light, cfg.ledSegments);
        if (hal::Error e = led->open(pathFromConfig(cfg, cfg.ledLog)); !e.ok()) return {nullptr, e};
        return {std::move(led), {}};
    }
    if (kGpiod && cfg.ledBackend == "gpiod") return openGpiodLed(cfg);
    return LedResult::fail(hal::Errc::Invalid, ledBackendIssue(cfg));
}

} // namespace icacam::fw
