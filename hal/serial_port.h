#pragma once
// A byte stream to the host PC: UART, USB gadget tty or (for tests) a pseudo-terminal.
#include <cstddef>
#include <string_view>

#include "hal/error.h"

namespace icacam::hal {

class SerialPort {
public:
    virtual ~SerialPort() = default;
    // Reads what has arrived, up to cap bytes, without blocking (0 when nothing).
    virtual Result<size_t> read(char *buf, size_t cap) = 0;
    // Writes all of data, waiting at most a short bounded time if the far end is slow;
    // a stuck far end loses output (Errc::Full), it never stalls the device.
    virtual Error write(std::string_view data) = 0;
};

} // namespace icacam::hal
