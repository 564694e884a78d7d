// Arbitrary bytes as a frame of any size and any declared scale: the instrument's read() must
// return a value or an error, never crash, read out of bounds or overflow.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "friction/paper_model.h"
#include "reading/instrument.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static icacam::friction::PaperModel model;
    static icacam::reading::Instrument instrument;
    static bool configured = instrument.configure(4096, 4096, model) == icacam::vision::ErrorCode::None;
    if (!configured || size < 8) return 0;
    // Header: width, height (1…1024), scale byte, n byte; the rest are pixels (repeated).
    const int w = 1 + ((data[0] | data[1] << 8) % 1024);
    const int h = 1 + ((data[2] | data[3] << 8) % 1024);
    const double mmPerPx = 0.002 + data[4] * 0.0005;
    const double n = data[5] / 255.0;
    const int pixelStep = 1 + (data[6] & 1);
    static uint8_t frame[1024 * 1024 * 2];
    const size_t need = size_t(w) * size_t(h) * size_t(pixelStep);
    const size_t body = size - 8;
    for (size_t i = 0; i < need; ++i) frame[i] = body ? data[8 + i % body] : 0;
    const icacam::vision::LumaView v{frame, w, h, w * pixelStep, pixelStep};
    const icacam::reading::SpecimenSpec spec{n, 500, 10, 15, mmPerPx};
    const auto m = instrument.read(v, spec);
    if (m.hasValue() && !(m.mu == m.mu)) __builtin_trap(); // a value must be a number
    return 0;
}
