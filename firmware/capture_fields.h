#pragma once
// What the journal and the serial line carry about how a frame was taken: when its exposure
// started relative to the light and the trigger, how many earlier frames were refused, and
// the control values the camera reports it used (not the ones asked for).
#include <cstdint>

#include "hal/camera.h"
#include "reading/record_line.h"

namespace icacam::fw {

// latency_us: LED settled → exposure start; trigger_latency_ms: trigger → exposure start;
// stale_frames, frame_seq; exposure_us, gain, red_gain, blue_gain, lens_position when the
// camera reports them.
void appendCaptureFields(reading::JsonBuilder &j, const hal::CapturedFrame &f, int64_t triggerMs);

} // namespace icacam::fw
