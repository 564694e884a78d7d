// Arbitrary bytes as a manifest: parse must never crash, and every row is a record.
#include <cstddef>
#include <cstdint>
#include <string>

#include "host_tools/manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    icacam::host::Manifest m;
    std::string err;
    const std::string text(reinterpret_cast<const char *>(data), size);
    if (icacam::host::parseManifest(text, &m, &err)) {
        for (const auto &row : m.rows) {
            double v;
            (void)icacam::host::parseNumber(row.get("n"), &v);
            (void)row.get("id");
        }
    }
    return 0;
}
