// What the device says of itself: the greeting at start, `status`, and the camera's state
// whenever it changes.
#include "firmware/device.h"

#include <cstdio>

namespace icacam::fw {

void Device::sayHello(const JournalRecovery &rec)
{
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
}

void Device::appendStatus(reading::JsonBuilder &j)
{
    auto free = hal_.storage.freeBytes();
    j.str("type", "status")
        .str("state", stateName(state_))
        .integer("records", journal_.count())
        .integer("last_id", lastId_)
        .integer("uptime_ms", hal_.clock.monotonicMs() - startMs_)
        .integer("free_bytes", free.ok() ? (long long)free.value : -1)
        .boolean("led", hal_.led.isOn())
        .str("model", instrument_.model().name());
    // A segmented ring: how many segments the config asks for and the ring switches.
    if (cfg_.ledSegments > 1) j.integer("led_segments", cfg_.ledSegments).integer("led_switches", hal_.led.segments());
    appendRecipe(j);
    appendCameraStatus(j);
    appendPartsStatus(j);
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

} // namespace icacam::fw
