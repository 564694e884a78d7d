#pragma once
// The SSD1306 128 × 64 OLED on I2C (Solomon Systech SSD1306 datasheet rev 1.1, §8.1.5 I2C
// interface and §10 command table), and the SH1106 of the 1.3 inch panels sold under the
// same name (Sino Wealth SH1106 datasheet: 132-column RAM, the panel on columns 2…129, page
// addressing only, no charge-pump command). Both are written page by page in page
// addressing mode, which both understand. The bus is a seam: I2cDevBus talks to
// /dev/i2c-N, a test records the transactions.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hal/display.h"
#include "hal/unique_fd.h"

namespace icacam::hal {

class I2cBus {
public:
    virtual ~I2cBus() = default;
    // One I2C write transaction to the display's address. Errors: Io (NACK: no device).
    virtual Error write(const uint8_t *data, size_t len) = 0;
};

// Linux i2c-dev: /dev/i2c-<bus>, I2C_SLAVE set once; a NACK shows as ENXIO / EREMOTEIO.
class I2cDevBus final : public I2cBus {
public:
    Error open(int bus, int address);
    Error write(const uint8_t *data, size_t len) override;

private:
    UniqueFd fd_;
    std::string name_;
};

struct OledOptions {
    bool sh1106 = false; // the controller of the 1.3 inch panels
    bool rotate180 = false;
    int contrast = 0x7F; // 0…255
};

class Ssd1306Display final : public Display {
public:
    static constexpr size_t kChunk = 128; // data bytes per transaction (one page row)

    explicit Ssd1306Display(I2cBus &bus, OledOptions options = {}) : bus_(bus), options_(options) {}
    // Sends the power-up sequence and clears the display RAM before switching the panel on
    // (it powers up holding noise).
    Error init();
    // Sends the whole picture; after a failed transfer the next call starts with init()
    // again (a display that lost power comes back blank and asleep).
    Error show(const MonoBitmap &picture) override;

private:
    Error commands(const uint8_t *cmds, size_t n);
    Error writePage(int page, const uint8_t *bytes, size_t n, int firstColumn);
    I2cBus &bus_;
    OledOptions options_;
    bool ready_ = false;
};

} // namespace icacam::hal
