#include "firmware/device.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

#include "firmware/capture_fields.h"
#include "firmware/frame_luma.h"
#include "firmware/recipe.h"
#include "firmware/scale_check.h"
#include "firmware/screen.h"
#include "reading/reading_record.h"
#include "vision/reference_disc.h"

namespace icacam::fw {

namespace {

// Writes into a caller buffer: the report path allocates nothing once out_ has grown.
void isoTime(int64_t wallMs, char (&b)[96])
{
    const time_t s = time_t(wallMs / 1000);
    tm t{};
    gmtime_r(&s, &t);
    std::snprintf(b, sizeof b, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", t.tm_year + 1900, t.tm_mon + 1, t.tm_mday,
                  t.tm_hour, t.tm_min, t.tm_sec, int(wallMs % 1000));
}

constexpr const char *kSettingsFile = "settings.conf";

// The keys settable over serial, for help and refusals.
std::string liveKeyList()
{
    std::string out;
    for (const std::string &k : configKeys(true)) out += (out.empty() ? "" : " ") + k;
    return out;
}

} // namespace

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
    out_.clear();
    reading::JsonBuilder j0(&out_);
    j0.str("type", "hello")
        .str("version", "0.1.0")
        .str("model", instrument_.model().name())
        .integer("records", rec.records)
        .integer("last_id", rec.lastId)
        .integer("recovered_cut_bytes", static_cast<long long>(rec.cutBytes))
        .integer("temp_files_removed", rec.tempFilesRemoved);
    appendRecipe(j0);
    appendCameraStatus(j0);
    appendPartsStatus(j0);
    j0.end();
    send(out_);
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

void Device::pollCamera()
{
    // No probe while aiming: aim mode captures all the time, and says when it cannot.
    if (!cameraHealth_.poll(aimUntilMs_ < 0)) return;
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "camera");
    appendCameraStatus(j);
    j.end();
    send(out_);
    if (state_ == State::Idle && aimUntilMs_ < 0) showIdle(cameraHealth_.ok() ? "camera found" : "");
}

void Device::appendCameraStatus(reading::JsonBuilder &j) const
{
    j.str("camera", CameraHealth::stateName(cameraHealth_.state()));
    if (!cameraHealth_.ok()) j.str("camera_problem", cameraHealth_.problem());
    j.str("camera_info", cameraHealth_.describe());
    j.integer("camera_latency_us", cameraHealth_.lastLatencyUs());
    // What the camera reported for its last frame (-1: not reported, or no frame yet).
    const hal::CameraControls &c = cameraHealth_.lastControls();
    char controls[160];
    std::snprintf(controls, sizeof controls, "exposure_us %d gain %.3f red_gain %.3f blue_gain %.3f lens_position %.3f",
                  c.exposureUs, c.analogueGain, c.redGain, c.blueGain, c.lensPosition);
    j.str("camera_controls", controls);
}

void Device::pollButton()
{
    // Held here since an earlier batch: the level is read before the queue is drained, so a
    // release that happened is either in the queue or was lost (libgpiod 1.6 drops the newest
    // event when the queue is full, e.g. while a measurement ran).
    hal::Result<bool> level = hal::Result<bool>::fail(hal::Errc::Invalid, "");
    if (debouncer_.isDown()) level = hal_.trigger.pressed();
    hal::ButtonEdge edges[16];
    hal::Result<size_t> r = hal_.trigger.readEdges(edges, 16);
    if (!r.ok()) {
        // A part stand-in reports its own failures (device_parts.cpp).
        if (!hal_.parts && lastProblem_ != r.error.message) {
            lastProblem_ = r.error.message;
            sendError("trigger_failed", r.error.message, "");
        }
        return;
    }
    for (size_t i = 0; i < r.value; ++i) {
        const Press p = debouncer_.onEdge(edges[i]);
        if (p != Press::Short) continue;
        if (aimUntilMs_ >= 0) { // a press ends aiming; it does not measure
            stopAim("button");
            continue;
        }
        measure("button", "");
    }
    if (level.ok() && !level.value && r.value == 0) debouncer_.resync(false);
    if (debouncer_.poll(hal_.clock.monotonicMs()) == Press::Long) {
        // Long press: aim mode; held again while aiming: the settings page.
        if (aimUntilMs_ < 0) {
            startAim(60, "");
        } else {
            stopAim("button");
            drawSettings(&screen_, cfg_);
            showOrLog(screen_);
        }
    }
}

void Device::pollSerial()
{
    char buf[4096];
    for (int chunk = 0; chunk < 64; ++chunk) { // at most 256 KiB a tick, so buttons stay responsive
        hal::Result<size_t> r = hal_.serial.read(buf, sizeof buf);
        if (!r.ok() || r.value == 0) return;
        std::string_view data(buf, r.value);
        for (;;) {
            const LineAssembler::Event ev = lines_.push(&data);
            if (ev == LineAssembler::Event::None) break;
            if (ev == LineAssembler::Event::Overflow)
                sendError("line_too_long", "line longer than 1024 bytes: ignored up to its end", "");
            else
                handleLine(lines_.line());
        }
    }
}

bool Device::addListener(net::DeviceListener *l)
{
    if (listenerCount_ == kMaxListeners) return false;
    listeners_[listenerCount_++] = l;
    return true;
}

void Device::pollInbox()
{
    if (!inbox_) return;
    if (!inboxLine_) inboxLine_ = std::make_unique<char[]>(net::CommandInbox::kMaxLine);
    for (int i = 0; i < 4; ++i) { // a few a tick, so buttons stay responsive
        const size_t n = inbox_->pop(inboxLine_.get());
        if (n == 0) return;
        lineOrigin_ = "web";
        handleLine(std::string_view(inboxLine_.get(), n));
        lineOrigin_ = "serial";
    }
}

void Device::journaled(long id)
{
    for (int i = 0; i < listenerCount_; ++i) listeners_[i]->onJournaled(id);
}

void Device::handleLine(std::string_view line)
{
    if (line.empty() || line == "\r") return;
    const CommandParse p = parseCommand(line);
    if (!p.ok) {
        sendError(p.code, p.message, "");
        return;
    }
    handleCommand(p.cmd);
}

void Device::handleCommand(const Command &c)
{
    out_.clear();
    reading::JsonBuilder j(&out_);
    switch (c.kind) {
    case CommandKind::Help:
        j.str("type", "help")
            .str("commands", "status | trigger | get [KEY] | set KEY VALUE | results [N] | "
                             "scalecheck DIAMETER_MM [TOLERANCE_PCT [THICKNESS_MM]] | aim [SECONDS | off] | snapshot | "
                             "fetch NAME | lens POSITION | focus | measure-latency | help; "
                             "as words or JSON {\"cmd\":\"set\",\"key\":\"n\",\"value\":0.2,\"id\":\"x\"}")
            .str("keys", liveKeyList());
        break;
    case CommandKind::Status: {
        auto free = hal_.storage.freeBytes();
        j.str("type", "status")
            .str("state", stateName(state_))
            .integer("records", journal_.count())
            .integer("last_id", lastId_)
            .integer("uptime_ms", hal_.clock.monotonicMs() - startMs_)
            .integer("free_bytes", free.ok() ? (long long)free.value : -1)
            .boolean("led", hal_.led.isOn())
            .str("model", instrument_.model().name());
        appendRecipe(j);
        appendCameraStatus(j);
        appendPartsStatus(j);
        break;
    }
    case CommandKind::Trigger:
        if (aimUntilMs_ >= 0) stopAim("measurement");
        measure(lineOrigin_, c.tag);
        return;
    case CommandKind::Aim:
        if (c.aimSeconds == 0)
            stopAim("serial");
        else
            startAim(c.aimSeconds, c.tag);
        return;
    case CommandKind::Snapshot:
        if (aimUntilMs_ >= 0) stopAim("snapshot");
        snapshot(c);
        return;
    case CommandKind::Lens: setLens(c); return;
    case CommandKind::Focus:
        if (aimUntilMs_ >= 0) stopAim("focus");
        focus(c);
        return;
    case CommandKind::Fetch: fetch(c); return;
    case CommandKind::MeasureLatency:
        if (aimUntilMs_ >= 0) stopAim("measure-latency");
        measureLatency(c);
        return;
    case CommandKind::Get: {
        j.str("type", "settings");
        int matched = 0;
        for (const std::string &k : configKeys(true)) {
            if (!c.key.empty() && liveKeyName(c.key) != k) continue;
            std::string v;
            bool num = false;
            getConfigKey(cfg_, k, &v, &num);
            num ? j.raw(k, v) : j.str(k, v);
            ++matched;
        }
        if (matched == 0) {
            sendError("bad_argument", "unknown key (keys: " + liveKeyList() + ")", c.tag);
            return;
        }
        break;
    }
    case CommandKind::Set:
        if (!applySetting(c, j)) return;
        break;
    case CommandKind::Results: sendResults(c, j); return;
    case CommandKind::ScaleCheck:
        if (aimUntilMs_ >= 0) stopAim("scalecheck");
        scaleCheck(c);
        return;
    }
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    send(out_);
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

void Device::sendResults(const Command &c, reading::JsonBuilder &j)
{
    const size_t have = journal_.recentCount();
    const size_t n = std::min(have, size_t(c.count));
    j.str("type", "results").integer("count", static_cast<long long>(n));
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    send(out_);
    for (size_t i = have - n; i < have; ++i) {
        // Measurements come back as records; scale checks as they were sent.
        const std::string_view line = journal_.recent(i), result = "{\"type\":\"result\"";
        if (line.substr(0, result.size()) == result) {
            out_.assign("{\"type\":\"record\"");
            out_.append(line.substr(result.size()));
        } else {
            out_.assign(line);
        }
        out_.push_back('\n');
        send(out_);
    }
}

void Device::measure(const char *origin, const std::string &tag)
{
    const int64_t t0 = hal_.clock.monotonicMs();
    const long id = lastId_ + 1;
    drawBusy(&screen_, id);
    showOrLog(screen_);
    reading::Reading m;
    std::string problem;
    hal::CapturedFrame frame;
    vision::LumaView luma;
    const bool captured = captureFrame(&frame, &luma, &problem);
    if (captured && problem.empty()) {
        if (std::string issue = instrument_.frameSizeIssue(luma.width, luma.height); !issue.empty())
            problem = "calibration '" + cal_.name + "': " + issue;
        else
            m = instrument_.read(luma, specimenSpec(cfg_));
    }

    state_ = State::Report;
    lastId_ = id;
    std::string imageName;
    std::string storageProblem;
    if (captured && problem.empty() && cfg_.journalImages == "pgm") {
        char name[32];
        std::snprintf(name, sizeof name, "img-%06ld.pgm", id);
        if (hal::Error e = saveImage(name, luma); e.ok())
            imageName = name;
        else
            storageProblem =
                e.code == hal::Errc::Full ? "storage full: image not saved" : "image not saved: " + e.message;
    }
    buildRecord(id, origin, tag, m, problem, captured ? &frame : nullptr, imageName,
                long(hal_.clock.monotonicMs() - t0));
    // The record is durable before anyone hears of it: what was reported survives a crash.
    if (hal::Error e = journal_.append(out_); !e.ok())
        storageProblem = e.code == hal::Errc::Full ? "storage full: result not journaled" : "journal: " + e.message;
    else
        journaled(id);
    send(out_);
    if (!problem.empty()) sendError("measurement_failed", problem, tag);
    if (!storageProblem.empty()) sendError("storage", storageProblem, tag);

    char title[32];
    std::snprintf(title, sizeof title, "#%ld error", id);
    if (!problem.empty())
        drawProblem(&screen_, title, problem);
    else
        drawResult(&screen_, id, m, storageProblem.empty() ? "" : "STORAGE FULL");
    showOrLog(screen_);
    state_ = State::Idle;
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

void Device::scaleCheck(const Command &c)
{
    const int64_t t0 = hal_.clock.monotonicMs();
    const long id = lastId_ + 1;
    drawBusy(&screen_, id);
    showOrLog(screen_);
    std::string problem;
    hal::CapturedFrame frame;
    vision::LumaView luma;
    const bool captured = captureFrame(&frame, &luma, &problem);
    ScaleCheckResult r;
    if (captured && problem.empty())
        r = checkScale(luma, {c.diameterMm, c.tolerancePct, c.thicknessMm}, cal_, cfg_.mmPerPx, discWork_.get());

    state_ = State::Report;
    lastId_ = id;
    std::string imageName, storageProblem;
    if (captured && problem.empty() && cfg_.journalImages == "pgm") {
        char name[32];
        std::snprintf(name, sizeof name, "img-%06ld.pgm", id);
        if (hal::Error e = saveImage(name, luma); e.ok())
            imageName = name;
        else
            storageProblem =
                e.code == hal::Errc::Full ? "storage full: image not saved" : "image not saved: " + e.message;
    }
    out_.clear();
    reading::JsonBuilder j(&out_);
    char when[96];
    isoTime(hal_.clock.wallMs(), when);
    const char *status = !problem.empty() || !r.measured ? "error" : r.pass ? "pass" : "fail";
    j.str("type", "scalecheck").integer("id", id).str("time", when).str("status", status);
    j.num("diameter_mm", c.diameterMm, 4);
    if (r.measured) j.num("measured_mm", r.measuredMm, 7).num("ratio", r.ratio, 7);
    j.num("tolerance_pct", c.tolerancePct, 3).num("thickness_mm", c.thicknessMm, 3);
    j.str("message", !problem.empty() ? problem : r.message);
    j.str("calibration", cal_.present ? cal_.name : "").num("mm_per_px", cfg_.mmPerPx, 8);
    j.str("image", imageName).str("source", captured ? std::string_view(frame.source) : std::string_view());
    j.str("trigger", "serial").integer("ms", long(hal_.clock.monotonicMs() - t0));
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    if (hal::Error e = journal_.append(out_); !e.ok())
        storageProblem = e.code == hal::Errc::Full ? "storage full: result not journaled" : "journal: " + e.message;
    else
        journaled(id);
    send(out_);
    if (!problem.empty()) sendError("measurement_failed", problem, c.tag);
    if (!storageProblem.empty()) sendError("storage", storageProblem, c.tag);

    char title[48], words[64];
    std::snprintf(title, sizeof title, "#%ld scale %s", id, status);
    if (r.measured) std::snprintf(words, sizeof words, "ratio %.4f (tol %.2f %%)", r.ratio, c.tolerancePct);
    drawProblem(&screen_, title,
                r.measured ? std::string_view(words) : std::string_view(problem.empty() ? r.message : problem));
    showOrLog(screen_);
    state_ = State::Idle;
}

reading::SpecimenSpec specimenSpec(const Config &c)
{
    // The config's keys under their manifest names (Config's aliases), each value printed
    // exactly (17 digits round-trip a double); the config checked their ranges already.
    const std::pair<const char *, double> values[] = {
        {"n", c.n},
        {"mm_per_px", c.mmPerPx},
        {"k_mpa", c.kMpa},
        {"d0_mm", c.d0Mm},
        {"h0_mm", c.h0Mm},
        {"h_final_mm", c.hFinalMm},
        {"mm_per_px_tol", c.mmPerPxTolRel},
        {"h_final_tol_mm", c.hFinalTolMm},
        {"n_tol", c.nTol},
        {"tolerance_mu", c.toleranceMu},
        {"tolerance_rel", c.toleranceRel},
    };
    char text[40];
    auto lookup = [&values, &text](std::string_view key) -> const char * {
        for (const auto &[name, value] : values)
            if (key == name) {
                std::snprintf(text, sizeof text, "%.17g", value);
                return text;
            }
        return nullptr;
    };
    reading::SpecimenSpec s;
    std::string why;
    reading::specimenFromFields(lookup, false, &s, &why);
    return s;
}

void Device::buildRecord(long id, const char *origin, const std::string &tag, const reading::Reading &m,
                         std::string_view problem, const hal::CapturedFrame *frame, std::string_view image, long ms)
{
    out_.clear();
    reading::JsonBuilder j(&out_);
    char when[96];
    isoTime(hal_.clock.wallMs(), when);
    j.str("type", "result").integer("id", id);
    reading::JsonRecordSink sink(&j);
    // A frame never measured (capture, LED or calibration problem) is a record without a reading.
    reading::writeReading(problem.empty() ? &m : nullptr, problem, instrument_.model().name(), sink);
    j.str("time", when);
    j.str("image", image).str("source", frame ? std::string_view(frame->source) : std::string_view());
    j.num("n", cfg_.n)
        .num("k_mpa", cfg_.kMpa)
        .num("d0_mm", cfg_.d0Mm)
        .num("h0_mm", cfg_.h0Mm)
        .num("mm_per_px", cfg_.mmPerPx, 8);
    j.num("h_final_mm", cfg_.hFinalMm);
    // Which calibration mapped the boundaries, and the plane it mapped them into.
    j.str("calibration", cal_.present ? cal_.name : "");
    if (cal_.present && m.hasValue()) j.num("plane_height_mm", cfg_.h0Mm * (1 - m.reduction), 4);
    appendRecipe(j); // the version in effect: what the fields above and the camera's were set by
    j.str("material", cfg_.material).str("trigger", origin).integer("ms", ms);
    if (frame) {
        appendCaptureFields(j, *frame, triggerMs_);
        // The lit-frame check's verdict on the last frame tried, and how many were refused.
        j.str("lit", litVerdictName(lastLit_.verdict)).integer("unlit_frames", unlitFrames_);
    }
    if (!tag.empty()) j.str("tag", tag);
    j.end();
}

hal::Error Device::saveImage(std::string_view name, const vision::LumaView &v)
{
    char header[48];
    const int n = std::snprintf(header, sizeof header, "P5\n%d %d\n255\n", v.width, v.height);
    image_.assign(header, size_t(n));
    for (int y = 0; y < v.height; ++y) {
        const uint8_t *row = v.data + size_t(y) * size_t(v.stride);
        if (v.pixelStep == 1)
            image_.append(reinterpret_cast<const char *>(row), size_t(v.width));
        else
            for (int x = 0; x < v.width; ++x) image_.push_back(char(row[size_t(x) * size_t(v.pixelStep)]));
    }
    return journal_.saveImage(name, image_);
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
