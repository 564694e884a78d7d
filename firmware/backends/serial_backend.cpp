#include "firmware/backends/serial_backend.h"

#include "firmware/backends/backend_config.h"
#include "hal/file/pty_serial.h"
#ifdef ICACAM_HAVE_TERMIOS
#include "hal/termios/termios_serial.h"
#endif

namespace icacam::fw {

namespace {

using SerialResult = hal::Result<SerialBackend>;

#ifdef ICACAM_HAVE_TERMIOS
constexpr bool kTermios = true;
SerialResult openUart(const Config &cfg)
{
    auto uart = std::make_unique<hal::TermiosSerial>();
    if (hal::Error e = uart->open(cfg.serialDevice, cfg.serialBaud); !e.ok()) return {{}, e};
    return {{std::move(uart), cfg.serialDevice + " at " + std::to_string(cfg.serialBaud) + " baud"}, {}};
}
#else
constexpr bool kTermios = false;
SerialResult openUart(const Config &)
{
    return SerialResult::fail(hal::Errc::Invalid, "termios not built");
}
#endif

} // namespace

std::string serialBackendIssue(const Config &cfg)
{
    if (cfg.serialBackend == "pty" || (kTermios && cfg.serialBackend == "uart")) return "";
    return notBuiltIssue("serial.backend", cfg.serialBackend, "pty");
}

hal::Result<SerialBackend> makeSerial(const Config &cfg)
{
    if (cfg.serialBackend == "pty") {
        auto pty = std::make_unique<hal::PtySerial>();
        const std::string link = pathFromConfig(cfg, cfg.serialLink);
        if (hal::Error e = pty->open(link); !e.ok()) return {{}, e};
        std::string name = pty->slavePath() + " (" + link + ")";
        return {{std::move(pty), std::move(name)}, {}};
    }
    if (kTermios && cfg.serialBackend == "uart") return openUart(cfg);
    return SerialResult::fail(hal::Errc::Invalid, serialBackendIssue(cfg));
}

} // namespace icacam::fw
