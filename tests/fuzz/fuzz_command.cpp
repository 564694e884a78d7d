// libFuzzer target: the serial command parser and line assembler must answer anything.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "firmware/command.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    std::string_view bytes(reinterpret_cast<const char *>(data), size);
    icacam::fw::LineAssembler lines(1024);
    std::string_view rest = bytes;
    for (;;) {
        const auto ev = lines.push(&rest);
        if (ev == icacam::fw::LineAssembler::Event::None) break;
        if (ev == icacam::fw::LineAssembler::Event::Line) {
            const auto p = icacam::fw::parseCommand(lines.line());
            if (!p.ok && p.message.empty()) __builtin_trap(); // every refusal says why
        }
    }
    (void)icacam::fw::parseCommand(bytes);
    return 0;
}
