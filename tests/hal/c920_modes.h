#pragma once
// A C920-class USB 2.0 webcam's mode list: the sizes such a camera lists for YUYV and MJPEG
// (as `ffmpeg -f video4linux2 -list_formats all` prints them for one), with the frame rates
// a USB 2.0 link allows: uncompressed YUYV at 2 bytes a pixel shares about 24 MB/s of
// isochronous bandwidth, so its large sizes run a few frames a second (1920x1080: 4 MB a
// frame, 5 fps), while MJPEG keeps 30 fps at every size.
#include <linux/videodev2.h>

#include <vector>

#include "hal/v4l2/stream_mode.h"

namespace icacam::test {

inline std::vector<hal::V4l2Mode> c920Modes()
{
    struct Size {
        int w, h;
        uint32_t yuyvFps;
    };
    const Size sizes[] = {{640, 480, 30}, {160, 90, 30},   {160, 120, 30},  {176, 144, 30},  {320, 180, 30},
                          {320, 240, 30}, {352, 288, 30},  {432, 240, 30},  {640, 360, 30},  {800, 448, 30},
                          {800, 600, 24}, {864, 480, 24},  {960, 720, 15},  {1024, 576, 15}, {1280, 720, 10},
                          {1600, 896, 7}, {1920, 1080, 5}, {2304, 1296, 2}, {2304, 1536, 2}};
    std::vector<hal::V4l2Mode> modes;
    for (const Size &s : sizes) modes.push_back({V4L2_PIX_FMT_YUYV, s.w, s.h, 1, s.yuyvFps});
    for (const Size &s : sizes)
        if (s.w <= 1920) modes.push_back({V4L2_PIX_FMT_MJPEG, s.w, s.h, 1, 30});
    return modes;
}

} // namespace icacam::test
