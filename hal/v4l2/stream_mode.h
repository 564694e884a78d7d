#pragma once
// Which of a V4L2 camera's modes (pixel format, size, frame interval) to stream. A pure
// function of the list the device enumerates (VIDIOC_ENUM_FMT, ENUM_FRAMESIZES,
// ENUM_FRAMEINTERVALS), tested on a C920-like list without a device.
//
// Why the frame interval counts: a USB 2.0 webcam sends uncompressed YUYV at its large
// sizes only a few times a second (a 1920x1080 YUYV frame is 4 MB; high-speed isochronous
// transfers carry about 24 MB/s), while its MJPEG stream keeps 30 fps at the same sizes. The
// largest area alone picks the slow mode, and the LED ring then stays on for several frame
// intervals per press, with a frame's exposure up to 1/fps long.
#include <cstdint>
#include <span>

namespace icacam::hal {

struct V4l2Mode {
    uint32_t fourcc = 0; // V4L2_PIX_FMT_*
    int width = 0, height = 0;
    // The fastest frame interval listed for this format and size (seconds = num / den);
    // 0 / 0 when the device lists none.
    uint32_t intervalNum = 0, intervalDen = 0;

    double fps() const { return intervalNum && intervalDen ? double(intervalDen) / intervalNum : 0; }
};

struct V4l2ModeChoice {
    bool found = false;
    V4l2Mode mode;
};

// Modes within maxWidth x maxHeight (exactly width x height when both are > 0) are the
// candidates. Those reaching minFps (a mode without listed intervals counts as reaching it)
// are preferred; when none does, the fastest candidates are. Among them the largest area
// wins; ties go to the formats viewed in place (`preferred` first, then GREY, NV12, YUYV)
// before MJPEG, which is decoded, then to the faster mode.
V4l2ModeChoice chooseV4l2Mode(std::span<const V4l2Mode> modes, int maxWidth, int maxHeight, int width, int height,
                              uint32_t preferred, double minFps = 15.0);

} // namespace icacam::hal
