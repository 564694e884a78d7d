// Aim mode and snapshots: setting the camera up at the press with what the device has.
#include <algorithm>
#include <cstdio>

#include "firmware/aim_view.h"
#include "firmware/device.h"
#include "firmware/frame_luma.h"
#include "firmware/screen.h"
#include "firmware/snapshot_png.h"

namespace icacam::fw {

namespace {
constexpr int64_t kAimPeriodMs = 250; // four pictures a second: enough to turn a focus ring by

// RFC 4648 base64 with padding, into *out.
void base64(std::string_view in, std::string *out)
{
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    out->clear();
    for (size_t i = 0; i < in.size(); i += 3) {
        const size_t n = in.size() - i < 3 ? in.size() - i : 3;
        uint32_t v = uint32_t(uint8_t(in[i])) << 16;
        if (n > 1) v |= uint32_t(uint8_t(in[i + 1])) << 8;
        if (n > 2) v |= uint32_t(uint8_t(in[i + 2]));
        out->push_back(kAlphabet[(v >> 18) & 63]);
        out->push_back(kAlphabet[(v >> 12) & 63]);
        out->push_back(n > 1 ? kAlphabet[(v >> 6) & 63] : '=');
        out->push_back(n > 2 ? kAlphabet[v & 63] : '=');
    }
}
} // namespace

reading::Reading Device::measureForSetup(const vision::LumaView &luma)
{
    // The specimen as configured, read as a measurement reads it (the boundaries are drawn
    // in the image from the reading's geometry).
    return instrument_.read(luma, specimenSpec(cfg_));
}

void Device::startAim(int seconds, const std::string &tag)
{
    const int64_t now = hal_.clock.monotonicMs();
    aimTag_ = tag;
    if (aimUntilMs_ < 0) {
        if (!cameraHealth_.ready()) {
            sendError("aim_failed",
                      std::string("camera ") + CameraHealth::stateName(cameraHealth_.state()) + ": " +
                          cameraHealth_.problem(),
                      tag);
            return;
        }
        // The ring stays on while aiming: the picture is the one a measurement will see.
        if (hal::Error e = hal_.led.set(true); !e.ok()) {
            sendError("aim_failed", "LED: " + e.message, tag);
            return;
        }
        hal_.clock.sleepMs(cfg_.ledSettleMs);
        aimLitMs_ = hal_.clock.monotonicMs();
        aimFrames_ = 0;
        aimNextMs_ = aimLitMs_;
    }
    aimUntilMs_ = now + int64_t(seconds) * 1000;
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "aim").str("state", "on").integer("seconds", seconds);
    if (!tag.empty()) j.str("tag", tag);
    j.end();
    send(out_);
    aimTick(); // the first picture now
}

void Device::stopAim(const char *why)
{
    if (aimUntilMs_ < 0) return;
    aimUntilMs_ = -1;
    (void)hal_.led.set(false);
    endLiveControls();
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "aim").str("state", "off").str("by", why).integer("pictures", aimFrames_);
    if (!aimTag_.empty()) j.str("tag", aimTag_);
    j.end();
    send(out_);
    showIdle("");
}

void Device::aimTick()
{
    const int64_t now = hal_.clock.monotonicMs();
    if (now >= aimUntilMs_) {
        stopAim("time");
        return;
    }
    if (now < aimNextMs_) return;
    aimNextMs_ = now + kAimPeriodMs;
    hal::CapturedFrame frame;
    // The newest picture, not the oldest one queued: only a frame exposed from now on (the
    // camera hands back the ones waiting), lit since the ring settled.
    const hal::Error e = hal_.camera.capture({std::max(aimLitMs_, now), cfg_.captureTimeoutMs}, &frame);
    cameraHealth_.onCapture(e, e.ok() ? &frame : nullptr);
    vision::LumaView luma;
    std::string problem = e.ok() ? "" : std::string("camera ") + hal::errcName(e.code) + ": " + e.message;
    if (problem.empty())
        if (const vision::ErrorCode le = frameLuma(frame.view, lumaScratch_.get(), lumaScratchBytes_, &luma);
            le != vision::ErrorCode::None)
            problem = std::string("frame: ") + vision::errorMessage(le);
    if (!problem.empty()) {
        sendError("aim_failed", problem, aimTag_);
        drawProblem(&screen_, "aim: no picture", problem);
        showOrLog(screen_);
        if (!cameraHealth_.ok()) stopAim("camera");
        return;
    }
    const reading::Reading m = measureForSetup(luma);
    const AimReading r = aimReading(luma, m);
    ++aimFrames_;
    for (int i = 0; i < listenerCount_; ++i) listeners_[i]->onAimPicture(luma);
    drawAim(&screen_, luma, r);
    showOrLog(screen_);
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "aim").integer("picture", aimFrames_).num("focus", r.focus, 4).boolean("found", r.found);
    if (r.found) {
        j.num("x", r.centreX, 5)
            .num("y", r.centreY, 5)
            .num("r_outer_px", r.rOuterPx, 5)
            .num("r_inner_px", r.rInnerPx, 5);
        j.num("edge_sigma_px", r.edgeSigmaPx, 3);
    }
    j.str("hint", r.hint).integer("width", luma.width).integer("height", luma.height);
    j.integer("remaining_s", (aimUntilMs_ - now + 999) / 1000);
    if (!aimTag_.empty()) j.str("tag", aimTag_);
    j.end();
    send(out_);
}

void Device::snapshot(const Command &c)
{
    std::string problem;
    hal::CapturedFrame frame;
    vision::LumaView luma;
    const bool captured = captureFrame(&frame, &luma, &problem);
    state_ = State::Report;
    if (!captured || !problem.empty()) {
        sendError("snapshot_failed", problem, c.tag);
        state_ = State::Idle;
        return;
    }
    const reading::Reading m = measureForSetup(luma);
    const AimReading r = aimReading(luma, m);
    // Named by the next record id it would take and the time, so snapshots sort with the
    // journal without using up an id.
    char name[48];
    std::snprintf(name, sizeof name, "snap-%06ld-%lld.png", lastId_ + 1,
                  static_cast<long long>(hal_.clock.wallMs() / 1000));
    image_.clear();
    if (std::string err = encodeSnapshotPng(luma, m, &image_); !err.empty()) {
        sendError("snapshot_failed", err, c.tag);
        state_ = State::Idle;
        return;
    }
    if (hal::Error e = journal_.saveImage(name, image_); !e.ok()) {
        sendError("storage", "snapshot not saved: " + e.message, c.tag);
        state_ = State::Idle;
        return;
    }
    out_.clear();
    reading::JsonBuilder j(&out_);
    j.str("type", "snapshot").str("image", name).integer("width", luma.width).integer("height", luma.height);
    j.integer("bytes", static_cast<long long>(image_.size())).boolean("found", r.found).num("focus", r.focus, 4);
    j.str("hint", r.hint).str("status", reading::statusName(m.status));
    if (!m.hasValue()) j.str("message", vision::errorMessage(m.error));
    j.str("source", frame.source);
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    send(out_);
    char title[40];
    std::snprintf(title, sizeof title, "snapshot %s", r.found ? "saved" : "(no face)");
    drawProblem(&screen_, title, name);
    showOrLog(screen_);
    state_ = State::Idle;
}

void Device::fetch(const Command &c)
{
    // A snapshot to a PC over the serial line itself (`icacam ctl snapshot --out FILE`): the
    // journal folder may be out of an operator's reach, and the line is what every
    // installation has. A header with the size, the bytes in base64 lines, an end line.
    const hal::Result<std::string> file = hal_.storage.read(c.name);
    if (!file.ok()) {
        sendError("fetch_failed", c.name + ": " + file.error.message, c.tag);
        return;
    }
    const std::string &bytes = file.value;
    constexpr size_t kChunk = 576; // 768 base64 characters a line, far under kMaxLine
    const size_t lines = (bytes.size() + kChunk - 1) / kChunk;
    out_.clear();
    reading::JsonBuilder head(&out_);
    head.str("type", "file").str("name", c.name).integer("bytes", static_cast<long long>(bytes.size()));
    head.integer("lines", static_cast<long long>(lines));
    if (!c.tag.empty()) head.str("tag", c.tag);
    head.end();
    send(out_);
    std::string b64;
    for (size_t i = 0; i < lines; ++i) {
        base64(std::string_view(bytes).substr(i * kChunk, kChunk), &b64);
        out_.clear();
        reading::JsonBuilder j(&out_);
        j.str("type", "data").integer("i", static_cast<long long>(i)).str("b64", b64);
        j.end();
        send(out_);
    }
    out_.clear();
    reading::JsonBuilder end(&out_);
    end.str("type", "file_end").str("name", c.name).integer("bytes", static_cast<long long>(bytes.size()));
    if (!c.tag.empty()) end.str("tag", c.tag);
    end.end();
    send(out_);
}

} // namespace icacam::fw
