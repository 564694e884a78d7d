#pragma once
// When a control change made on a running CSI camera has reached the frames. libcamera
// applies a request's controls a few frames later (the sensor's exposure and gain registers
// latch at frame boundaries, with the delays the pipeline's DelayedControls keep), and
// every completed request's metadata says what its frame was exposed with (ExposureTime,
// AnalogueGain, LensPosition). A frame shows the change when each changed value it reports
// is nearer the asked value than the one before: the sensor rounds exposure to whole lines
// and gain to its register's steps, so the reported value is seldom the asked one exactly,
// and the asked value is clamped to the camera's limits first, so a value out of range does
// not wait for what never comes. A pure function, tested without a camera.
#include "hal/camera.h"

namespace icacam::hal {

struct ControlChange {
    CameraControls before; // what frames were exposed with until now (-1: not known)
    CameraControls asked;  // the changed fields, within the camera's limits (others -1)
};

// True when the reported controls show every change the frame reports; a field the frame
// does not report (-1), or whose value before is not known, does not hold it back.
bool showsChange(const ControlChange &change, const CameraControls &reported);

} // namespace icacam::hal
