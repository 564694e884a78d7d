#pragma once
// A real serial line (UART /dev/ttyAMA0, USB gadget /dev/ttyGS0) in raw mode, 8N1, no flow
// control, at a configurable baud rate. Reads never block; writes wait a bounded time for a
// slow far end and then drop (Errc::Full), as the SerialPort seam requires. A hang-up (USB
// gadget unplugged, the host's adapter gone) is reported once as Errc::Closed; then the
// device is opened again, at most every reopenMs, until it answers (reads give 0 bytes, writes
// Closed, meanwhile).
#include <cstdint>
#include <string>

#include "hal/serial_port.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class TermiosSerial final : public SerialPort {
public:
    // Errors: NotFound, Invalid (a baud rate termios has no constant for), Io.
    Error open(const std::string &device, int baud, int writeTimeoutMs = 200, int reopenMs = 1000);
    Result<size_t> read(char *buf, size_t cap) override;
    Error write(std::string_view data) override;
    long droppedBytes() const { return dropped_; }
    long reopened() const { return reopened_; }

private:
    Error openNow();
    bool reopenDue(); // closed after a hang-up: true once it is open again
    void hungUp();
    UniqueFd fd_;
    std::string device_;
    int writeTimeoutMs_ = 200;
    int baud_ = 115200;
    int reopenMs_ = 1000;
    int64_t reopenAtMs_ = -1; // >= 0: hung up, try again then
    long dropped_ = 0;
    long reopened_ = 0;
};

} // namespace icacam::hal
