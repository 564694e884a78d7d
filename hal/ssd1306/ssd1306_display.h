#pragma once
// The SSD1306 128 × 64 OLED on I2C (Solomon Systech SSD1306 datasheet rev 1.1, §8.1.5 I2C
// interface and §10 command table). The bus is a seam: I2cDevBus talks to /dev/i2c-N, a
// test records the transactions.
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

class Ssd1306Display final : public Display {
public:
    static constexpr size_t kChunk = 128; // data bytes per transaction (one page row)

    explicit Ssd1306Display(I2cBus &bus) : bus_(bus) {}
    // Sends the power-up sequence (charge pump on, horizontal addressing, display on).
    Error init();
    // Sends the whole picture; after a failed transfer the next call starts with init()
    // again (a display that lost power comes back blank and asleep).
    Error show(const MonoBitmap &picture) override;

private:
    Error commands(const uint8_t *cmds, size_t n);
    I2cBus &bus_;
    bool ready_ = false;
};

} // namespace icacam::hal
