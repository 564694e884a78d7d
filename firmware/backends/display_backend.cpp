#include "firmware/backends/display_backend.h"

#include <cstdio>

#include "firmware/backends/backend_config.h"
#include "hal/file/png_display.h"
#ifdef ICACAM_HAVE_SSD1306
#include "hal/ssd1306/ssd1306_display.h"
#endif

namespace icacam::fw {

namespace {

using DisplayResult = hal::Result<std::unique_ptr<hal::Display>>;

struct NoDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

#ifdef ICACAM_HAVE_SSD1306
constexpr bool kSsd1306 = true;

// The OLED with the I2C bus it is on: the display holds its bus by reference.
class I2cOled final : public hal::Display {
public:
    explicit I2cOled(hal::OledOptions options) : oled_(bus_, options) {}
    hal::Error open(int bus, int address) { return bus_.open(bus, address); }
    hal::Error init() { return oled_.init(); }
    hal::Error show(const hal::MonoBitmap &picture) override { return oled_.show(picture); }

private:
    hal::I2cDevBus bus_;
    hal::Ssd1306Display oled_;
};

DisplayResult openOled(const Config &cfg)
{
    auto oled = std::make_unique<I2cOled>(
        hal::OledOptions{cfg.displayDriver == "sh1106", cfg.displayRotate == 180, cfg.displayContrast});
    if (hal::Error e = oled->open(cfg.i2cBus, cfg.i2cAddress); !e.ok()) return {nullptr, e};
    // A display that does not answer now is reported by each show(), not fatal: the
    // measurement still goes out on serial and into the journal.
    if (hal::Error e = oled->init(); !e.ok()) std::fprintf(stderr, "icacam-fw: display: %s\n", e.message.c_str());
    return {std::move(oled), {}};
}
#else
constexpr bool kSsd1306 = false;
DisplayResult openOled(const Config &)
{
    return DisplayResult::fail(hal::Errc::Invalid, "ssd1306 not built");
}
#endif

} // namespace

std::string displayBackendIssue(const Config &cfg)
{
    const std::string &b = cfg.displayBackend;
    if (b == "none" || b == "file" || (kSsd1306 && b == "ssd1306")) return "";
    return notBuiltIssue("display.backend", b, "file");
}

hal::Result<std::unique_ptr<hal::Display>> makeDisplay(const Config &cfg)
{
    if (cfg.displayBackend == "none") return {std::make_unique<NoDisplay>(), {}};
    if (cfg.displayBackend == "file") {
        auto png = std::make_unique<hal::PngDisplay>();
        if (hal::Error e = png->open(pathFromConfig(cfg, cfg.displayDir), cfg.displayScale); !e.ok())
            return {nullptr, e};
        return {std::move(png), {}};
    }
    if (kSsd1306 && cfg.displayBackend == "ssd1306") return openOled(cfg);
    return DisplayResult::fail(hal::Errc::Invalid, displayBackendIssue(cfg));
}

} // namespace icacam::fw
