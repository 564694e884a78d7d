// libFuzzer target: the config parser reports problems, never crashes, and a config it
// accepts satisfies the documented ranges.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "firmware/config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    icacam::fw::Config cfg;
    const auto issues = icacam::fw::parseConfig(std::string_view(reinterpret_cast<const char *>(data), size), &cfg);
    if (issues.empty() && !(cfg.n > 0 && cfg.mmPerPx > 0 && !cfg.journalDir.empty())) __builtin_trap();
    return 0;
}
