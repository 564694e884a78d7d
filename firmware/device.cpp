#include "firmware/device.h"

#include <vector>

#include "firmware/screen.h"
#include "vision/reference_disc.h"

namespace icacam::fw {

const char *Device::stateName(State s)
{
    switch (s) {
    case State::Idle: return "idle";
    case State::LedOn: return "led_on";
    case State::Capture: return "capture";
    case State::LedOff: return "led_off";
    case State::Measure: return "measure";
    case State::Report: return "report";
    }
    return "unknown";
}

Device::Device(DeviceHal hal, Config cfg, const friction::FrictionModel &model)
        : hal_(hal), cfg_(std::move(cfg)),
          cameraHealth_(hal.camera, hal.clock,
                        {cfg_.cameraFormat == "rgb24" ? hal::PixelFormat::RGB24 : hal::PixelFormat::Grey8,
                         cfg_.cameraMaxWidth, cfg_.cameraMaxHeight},
                        cfg_.cameraRetryMs, cfg_.cameraProbeMs, cfg_.captureTimeoutMs),
          journal_(hal.storage, cfg_.journalMemory), debouncer_(cfg_.debounceMs, cfg_.longPressMs), lines_(kMaxLine),
          recipes_(hal.storage)
{
    instrument_.setModel(model);
}

hal::Error Device::start()
{
    startMs_ = hal_.clock.monotonicMs();
    out_.reserve(8192);
    const auto fmt = cfg_.cameraFormat == "rgb24" ? vision::PixelFormat::RGB24 : vision::PixelFormat::Grey8;
    if (instrument_.configure(cfg_.cameraMaxWidth, cfg_.cameraMaxHeight, instrument_.model()) !=
        vision::ErrorCode::None)
        return hal::Error::make(hal::Errc::Invalid, "vision: cannot size working memory");
    lumaScratchBytes_ = vision::lumaScratchBytes(fmt, cfg_.cameraMaxWidth, cfg_.cameraMaxHeight);
    if (lumaScratchBytes_ > 0) lumaScratch_ = std::make_unique<uint8_t[]>(lumaScratchBytes_);
    sizeSegmentFrames();
    if (cfg_.journalImages == "pgm") image_.reserve(size_t(cfg_.cameraMaxWidth) * size_t(cfg_.cameraMaxHeight) + 64);
    // A camera that is not there yet is reported and looked for again; the device runs.
    cameraHealth_.open();
    // icacam-fw --check reports a bad calibration file first; a device started without
    // that check refuses it here.
    if (std::string e = loadDeviceCalibration(cfg_, &cal_); !e.empty()) return hal::Error::make(hal::Errc::Invalid, e);
    useCalibration(cal_);
    discWork_ = std::make_unique<uint8_t[]>(vision::ReferenceDiscFinder::kWorkBytes);
    // An LED ring that cannot be switched is reported, not fatal: a measurement says why it
    // has no light, and everything else goes on.
    const hal::Error ledOff = hal_.led.set(false);

    JournalRecovery rec;
    if (hal::Error e = journal_.recover(&rec); !e.ok()) return e;
    lastId_ = rec.lastId;
    const Config configured = cfg_;
    // Settings changed over serial survive a restart; a bad saved value is reported and skipped.
    std::string note = restoreSettings();
    // The recipe in effect: the newest version in the audit trail (the config file's keys
    // the first time, and whenever they are edited); what is wrong with the trail is said
    // after the greeting.
    std::vector<std::string> recipeProblems;
    if (hal::Error e = recipes_.start(configured, &cfg_, wallTime(), &recipeProblems); !e.ok())
        return hal::Error::make(e.code, "audit trail: " + e.message);
    // The recipe's controls and a camera delay saved over serial, which the camera was not
    // made with (it keeps them across reconfigures from then on).
    if (std::string e = moveCamera(configured, cfg_); !e.empty())
        recipeProblems.push_back("the recipe's controls: " + e);
    publishRecipe();
    if (cfg_.stampDelayUs != configured.stampDelayUs) applyStampDelay();
    if (!cal_.present && !(cfg_.mmPerPx > 0))
        return hal::Error::make(hal::Errc::Invalid, "no scale: calibration.mm_per_px or calibration.file is required");
    sayHello(rec);
    if (!ledOff.ok() && !hal_.parts) sendError("led_failed", ledOff.message, "");
    for (const std::string &p : recipeProblems) sendError("audit", p, "");
    if (!recipeProblems.empty()) note = "recipe/audit problem";
    // The parts missing at start-up, in the journal and the log as well (their later changes
    // come from the loop).
    if (hal_.parts)
        for (int i = 0; i < Parts::kCount; ++i)
            if (Part &p = hal_.parts->at(i); p.takeChange() && !p.ok()) reportPart(p);
    if (rec.cutBytes > 0) note = "journal tail repaired";
    showIdle(note);
    return {};
}

void Device::tick()
{
    pollParts();
    pollButton();
    pollSerial();
    pollInbox();
    pollRecipeDesk();
    pollCamera();
    if (aimUntilMs_ >= 0) aimTick();
}

bool Device::addListener(net::DeviceListener *l)
{
    if (listenerCount_ == kMaxListeners) return false;
    listeners_[listenerCount_++] = l;
    return true;
}

void Device::journaled(long id)
{
    for (int i = 0; i < listenerCount_; ++i) listeners_[i]->onJournaled(id);
}

void Device::showIdle(std::string_view note)
{
    if (!cameraHealth_.ok()) {
        const std::string words = cameraHealth_.problem() + " - looking again every " +
                                  std::to_string((cfg_.cameraRetryMs + 999) / 1000) + " s";
        drawProblem(&screen_, "icacam: no camera", words);
        showOrLog(screen_);
        return;
    }
    drawIdle(&screen_, cfg_, journal_.count(), idleNote(note));
    showOrLog(screen_);
}

void Device::showOrLog(const hal::MonoBitmap &bmp)
{
    // A part stand-in reports its own failures (device_parts.cpp).
    if (hal::Error e = hal_.display.show(bmp); !e.ok() && !hal_.parts && lastProblem_ != e.message) {
        lastProblem_ = e.message;
        sendError("display_failed", e.message, "");
    }
}

void Device::sendError(const char *code, std::string_view message, std::string_view tag)
{
    std::string line;
    reading::JsonBuilder j(&line);
    j.str("type", "error").str("code", code).str("message", message);
    if (!tag.empty()) j.str("tag", tag);
    j.end();
    send(line);
}

void Device::send(std::string_view line)
{
    (void)hal_.serial.write(line);
    for (int i = 0; i < listenerCount_; ++i) listeners_[i]->onLine(line);
}

} // namespace icacam::fw
