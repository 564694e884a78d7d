#pragma once
// The serial line's factory: serial.backend "pty" (a pseudo-terminal, its slave published
// as serial.link) always, "uart" (a UART or USB-gadget tty) when this build carries
// hal/termios.
#include <memory>
#include <string>

#include "firmware/config.h"
#include "hal/serial_port.h"

namespace icacam::fw {

struct SerialBackend {
    std::unique_ptr<hal::SerialPort> port;
    std::string name; // where the host reaches it, for the start-up line
};

// "" when this build carries serial.backend, else the config mistake in words.
std::string serialBackendIssue(const Config &cfg);

// The serial line, opened. Errors: the backend's open() (NotFound, Io, Invalid baud rate),
// Invalid (a backend this build does not carry).
hal::Result<SerialBackend> makeSerial(const Config &cfg);

} // namespace icacam::fw
