#include "firmware/capture_fields.h"

namespace icacam::fw {

void appendCaptureFields(reading::JsonBuilder &j, const hal::CapturedFrame &f, int64_t triggerMs)
{
    j.integer("latency_us", f.latencyUs).integer("trigger_latency_ms", f.timestampMs - triggerMs);
    j.integer("stale_frames", f.staleFrames).integer("frame_seq", f.sequence);
    const hal::CameraControls &c = f.controls;
    if (c.exposureUs >= 0) j.integer("exposure_us", c.exposureUs);
    if (c.analogueGain >= 0) j.num("gain", c.analogueGain, 5);
    if (c.redGain >= 0) j.num("red_gain", c.redGain, 5);
    if (c.blueGain >= 0) j.num("blue_gain", c.blueGain, 5);
    if (c.lensPosition >= 0) j.num("lens_position", c.lensPosition, 5);
}

} // namespace icacam::fw
