// The parts besides the camera (firmware/parts.h): a missing display, serial line, trigger
// button or LED ring is said wherever the device can still say something, and looked for again.
#include "firmware/device.h"

namespace icacam::fw {

void Device::pollParts()
{
    if (!hal_.parts) return;
    hal_.parts->poll();
    bool changed = false;
    for (int i = 0; i < Parts::kCount; ++i) {
        const Part &p = hal_.parts->at(i);
        if (!hal_.parts->at(i).takeChange()) continue;
        reportPart(p);
        changed = true;
    }
    if (changed && state_ == State::Idle && aimUntilMs_ < 0) showIdle("");
}

void Device::reportPart(const Part &p)
{
    // Journaled between the results (id 0: an event, not a measurement), so the journal shows
    // when the device ran without its display or serial line.
    std::string line;
    reading::JsonBuilder j(&line);
    j.str("type", "part").integer("id", 0).str("part", p.name()).str("state", Part::stateName(p.state()));
    if (!p.ok()) j.str("problem", p.problem());
    if (!p.ok()) j.integer("retry_s", (hal_.parts->retryMs() + 999) / 1000);
    j.integer("wall_ms", hal_.clock.wallMs());
    j.end();
    (void)journal_.append(line);
    send(line);
    // The log (stderr: journalctl -u icacam-fw) in words.
    std::string words = std::string(p.name()) + " " + Part::stateName(p.state());
    if (!p.ok())
        words +=
            ": " + p.problem() + " - trying again every " + std::to_string((hal_.parts->retryMs() + 999) / 1000) + " s";
    hal_.parts->log(words);
}

void Device::appendPartsStatus(reading::JsonBuilder &j) const
{
    if (!hal_.parts) return;
    j.str("parts_missing", hal_.parts->missingNames());
    for (int i = 0; i < Parts::kCount; ++i) {
        const Part &p = hal_.parts->at(i);
        if (p.ok()) continue;
        j.str(std::string(p.name()) + "_problem", p.problem());
    }
}

std::string Device::idleNote(std::string_view note) const
{
    if (hal_.parts) {
        const std::string missing = hal_.parts->missingNames();
        if (!missing.empty()) return "no " + missing;
    }
    return std::string(note);
}

} // namespace icacam::fw
