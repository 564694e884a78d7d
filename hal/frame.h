#pragma once
// A frame as a camera hands it out. The HAL has its own frame type so that the device
// interfaces and their backends need nothing of the vision library; the firmware views the
// frame's luma for vision (firmware/frame_luma.h), in place or through a buffer sized once.
#include <cstddef>
#include <cstdint>

namespace icacam::hal {

enum class PixelFormat : uint8_t { Grey8, RGB24, BGR24, XRGB32, YUYV, NV12, YUV420 };

// One frame in the camera's memory. Planar formats give the luma plane first.
struct FrameView {
    PixelFormat format = PixelFormat::Grey8;
    const uint8_t *data = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;   // bytes per row of the first plane
    size_t bytes = 0; // bytes available from data
};

} // namespace icacam::hal
