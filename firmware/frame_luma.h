#pragma once
// The seam between the camera's frame (hal/frame.h) and the vision library's luma view: the
// HAL knows nothing of vision, so the firmware hands a captured frame to vision::lumaOf.
#include <cstddef>
#include <cstdint>

#include "firmware/lit_frame.h"
#include "hal/frame.h"
#include "vision/luma_view.h"

namespace icacam::fw {

// The frame's luma as vision::lumaOf views it: in place, or (packed RGB) converted into
// scratch, which the caller sized once with vision::lumaScratchBytes. Allocates nothing.
// Errors: as vision::lumaOf.
vision::ErrorCode frameLuma(const hal::FrameView &frame, uint8_t *scratch, size_t scratchBytes, vision::LumaView *out);

// The same luma as the lit-frame check reads it.
inline LumaPlane lumaPlane(const vision::LumaView &v)
{
    return {v.data, v.width, v.height, v.stride, v.pixelStep};
}

} // namespace icacam::fw
