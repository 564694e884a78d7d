#pragma once
// A real serial line (UART /dev/ttyAMA0, USB gadget /dev/ttyGS0) in raw mode, 8N1, no flow
// control, at a configurable baud rate. Reads never block; writes wait a bounded time for a
// slow far end and then drop (Errc::Full), as the SerialPort seam requires.
#include <string>

#include "hal/serial_port.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class TermiosSerial final : public SerialPort {
public:
    // Errors: NotFound, Invalid (a baud rate termios has no constant for), Io.
    Error open(const std::string &device, int baud, int writeTimeoutMs = 200);
    Result<size_t> read(char *buf, size_t cap) override;
    Error write(std::string_view data) override;
    long droppedBytes() const { return dropped_; }

private:
    UniqueFd fd_;
    std::string device_;
    int writeTimeoutMs_ = 200;
    long dropped_ = 0;
};

} // namespace icacam::hal
