#pragma once
// A serial port stand-in for device tests: feeds `in` to the device and records what it
// wrote in `out`; `last(type)` parses the last JSON line of a type.
#include <algorithm>
#include <string>
#include <string_view>

#include "hal/serial_port.h"
#include "reading/record_line.h"

namespace icacam::test {

struct RecordingSerial final : hal::SerialPort {
    std::string in, out;
    hal::Result<size_t> read(char *buf, size_t cap) override
    {
        const size_t n = std::min(cap, in.size());
        in.copy(buf, n);
        in.erase(0, n);
        return {n, {}};
    }
    hal::Error write(std::string_view d) override
    {
        out.append(d);
        return {};
    }
    // The last line of the given type, parsed (empty when none).
    reading::FlatObject last(const std::string &type) const
    {
        reading::FlatObject found;
        size_t at = 0;
        while (at < out.size()) {
            const size_t nl = out.find('\n', at);
            const std::string line = out.substr(at, nl - at);
            at = nl == std::string::npos ? out.size() : nl + 1;
            reading::FlatObject o;
            if (reading::parseFlatObject(line, &o).empty() && o.find("type") && o.find("type")->text == type) found = o;
        }
        return found;
    }
};

} // namespace icacam::test
