#pragma once
// The serial port as a pseudo-terminal: the device side is the pty master; a host program
// (a test, `icacam ctl`, picocom, `socat`) opens the slave, whose path is published as a
// symlink. The slave is kept open here too (raw mode, no echo) so a host that closes and
// reopens it never makes the device see a hang-up, as with a real UART.
#include <string>

#include "hal/serial_port.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class PtySerial final : public SerialPort {
public:
    // Creates the pty; if linkPath is not empty, (re)points that symlink at the slave.
    Error open(const std::string &linkPath, int writeTimeoutMs = 200);
    ~PtySerial() override;
    const std::string &slavePath() const { return slavePath_; }

    Result<size_t> read(char *buf, size_t cap) override;
    Error write(std::string_view data) override;

private:
    UniqueFd master_, slave_;
    std::string slavePath_, linkPath_;
    int writeTimeoutMs_ = 200;
    bool stalled_ = false;
};

} // namespace icacam::hal
