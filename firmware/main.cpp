// icacam-fw: the device program's composition root. Reads the config, builds the HAL
// backends it names, and runs the device loop until SIGTERM/SIGINT.
//
// Exit codes suit systemd (Restart=on-failure, RestartPreventExitStatus=78):
//   0 stopped by a signal, 64 bad command line, 78 bad configuration (restarting cannot
//   help), 69 a device other than the camera could not be opened, 70 internal error. A
//   missing camera is not an exit: the device shows it and looks for it again.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "firmware/config.h"
#include "firmware/device.h"
#include "firmware/device_calibration.h"
#include "friction/friction_models.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/png_display.h"
#include "hal/file/pty_serial.h"
#ifdef ICACAM_HAVE_GPIOD
#include "hal/gpiod/gpiod_lines.h"
#endif
#ifdef ICACAM_HAVE_V4L2
#include "hal/v4l2/v4l2_camera.h"
#endif
#ifdef ICACAM_HAVE_SSD1306
#include "hal/ssd1306/ssd1306_display.h"
#endif
#ifdef ICACAM_HAVE_LIBCAMERA
#include "hal/libcamera/libcamera_camera.h"
#endif
#ifdef ICACAM_HAVE_TERMIOS
#include "hal/termios/termios_serial.h"
#endif

namespace {

volatile std::sig_atomic_t gStop = 0;
void onSignal(int)
{
    gStop = 1;
}

constexpr int kExitUsage = 64, kExitUnavailable = 69, kExitConfig = 78;

std::string usage()
{
    std::string models;
    for (std::string_view name : icacam::friction::kModelNames) (models += models.empty() ? "" : ", ") += name;
    return std::string("usage: icacam-fw --config FILE [--check]\n"
                       "       icacam-fw --help-config\n"
                       "Runs the icacam device program on the backends the config names.\n"
                       "  --config FILE  the device configuration (key = value lines; no default)\n"
                       "  --check        validate the config (and the calibration file it names) and exit\n"
                       "  --help-config  every config key with its default\n"
                       "The friction model is the config's reading.model (default ") +
           icacam::friction::kDefaultModel + "; known: " + models +
           ").\n"
           "Exit codes: 0 stopped by a signal, 64 bad command line, 78 bad configuration, 69 a device\n"
           "could not be opened. See docs/firmware.md for the keys, the serial protocol and the journal.\n";
}

std::string resolve(const std::string &base, const std::string &p)
{
    if (p.empty() || p.front() == '/') return p;
    return (std::filesystem::path(base) / p).lexically_normal().string();
}

int unavailable(const char *what, const icacam::hal::Error &e)
{
    std::fprintf(stderr, "icacam-fw: %s: %s\n", what, e.message.c_str());
    return kExitUnavailable;
}

} // namespace

int main(int argc, char **argv)
{
    using namespace icacam;
    std::string configPath;
    bool checkOnly = false;
    // The same forms as the icacam subcommands: --config FILE or --config=FILE.
    auto usageError = [](const std::string &why) {
        std::fprintf(stderr, "icacam-fw: error: %s\n%s", why.c_str(), usage().c_str());
        return kExitUsage;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--config" || a.rfind("--config=", 0) == 0) {
            if (a.size() > 8)
                configPath = a.substr(9);
            else if (i + 1 < argc)
                configPath = argv[++i];
            else
                return usageError("--config needs a value");
            if (configPath.empty()) return usageError("--config needs a value");
        } else if (a == "--check")
            checkOnly = true;
        else if (a == "--help-config") {
            std::printf("config keys:\n%s", fw::configHelp().c_str());
            return 0;
        } else if (a == "-h" || a == "--help") {
            std::printf("%s", usage().c_str());
            return 0;
        } else
            return usageError((a.size() > 1 && a[0] == '-' ? "unknown option '" : "unexpected argument '") + a + "'");
    }
    if (configPath.empty()) return usageError("--config is required");

    std::ifstream in(configPath);
    if (!in) {
        std::fprintf(stderr, "icacam-fw: cannot read config '%s'\n", configPath.c_str());
        return kExitConfig;
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fw::Config cfg;
    const auto issues = fw::parseConfig(text, &cfg);
    for (const auto &is : issues) {
        if (is.line > 0)
            std::fprintf(stderr, "%s:%d: %s\n", configPath.c_str(), is.line, is.message.c_str());
        else
            std::fprintf(stderr, "%s: %s\n", configPath.c_str(), is.message.c_str());
    }
    // Composition: this build carries the file-backed HAL; hardware backends come with their
    // own targets (hal/libcamera, hal/gpiod, hal/ssd1306 …) and are chosen here by name.
    auto onlyFile = [&](const char *key, const std::string &v, const char *ok) {
        if (v != ok) {
            std::fprintf(stderr, "%s: %s = %s: this icacam-fw is built with the %s backend only\n", configPath.c_str(),
                         key, v.c_str(), ok);
            return false;
        }
        return true;
    };
    bool ok = issues.empty();
    // Hardware backends compiled into this build (hal/gpiod, hal/v4l2).
    auto built = [&](const char *key, const std::string &v, const char *hw, bool have) {
        return (have && v == hw) || onlyFile(key, v, "file");
    };
#ifdef ICACAM_HAVE_GPIOD
    constexpr bool kGpiod = true;
#else
    constexpr bool kGpiod = false;
#endif
#ifdef ICACAM_HAVE_V4L2
    constexpr bool kV4l2 = true;
#else
    constexpr bool kV4l2 = false;
#endif
#ifdef ICACAM_HAVE_LIBCAMERA
    constexpr bool kLibcamera = true;
#else
    constexpr bool kLibcamera = false;
#endif
    ok = ((kLibcamera && cfg.cameraBackend == "libcamera") ||
          built("camera.backend", cfg.cameraBackend, "v4l2", kV4l2)) &&
         ok;
    ok = built("trigger.backend", cfg.triggerBackend, "gpiod", kGpiod) && ok;
    ok = built("led.backend", cfg.ledBackend, "gpiod", kGpiod) && ok;
#ifdef ICACAM_HAVE_SSD1306
    constexpr bool kSsd1306 = true;
#else
    constexpr bool kSsd1306 = false;
#endif
#ifdef ICACAM_HAVE_TERMIOS
    constexpr bool kTermios = true;
#else
    constexpr bool kTermios = false;
#endif
    ok = (cfg.displayBackend == "none" || built("display.backend", cfg.displayBackend, "ssd1306", kSsd1306)) && ok;
    ok = ((kTermios && cfg.serialBackend == "uart") || onlyFile("serial.backend", cfg.serialBackend, "pty")) && ok;
    const std::string base = std::filesystem::path(configPath).parent_path().string();
    cfg.baseDir = base;
    // The calibration file is part of the configuration: unreadable, of another format or
    // for larger frames than the camera's is a configuration mistake (exit 78).
    if (fw::DeviceCalibration cal; issues.empty())
        if (std::string e = fw::loadDeviceCalibration(cfg, &cal); !e.empty()) {
            std::fprintf(stderr, "%s: %s\n", configPath.c_str(), e.c_str());
            ok = false;
        }
    if (!ok) return kExitConfig;
    if (checkOnly) {
        std::printf("%s: ok\n", configPath.c_str());
        return 0;
    }

    hal::SystemClock clock;
    // Imaging controls as configured; the file camera reports them back with each frame.
    const hal::CameraControls asked = fw::cameraControlsOf(cfg);
    hal::FileCamera camera(clock,
                           {resolve(base, cfg.cameraFrames), cfg.cameraStrideAlign, cfg.cameraLoop != 0, 0, asked});
    hal::FileTrigger fileTrigger(clock);
    if (cfg.triggerBackend == "file" && !cfg.triggerScript.empty())
        if (hal::Error e = fileTrigger.open(resolve(base, cfg.triggerScript)); !e.ok())
            return unavailable("trigger", e);
    hal::FileLed fileLed(clock);
    if (cfg.ledBackend == "file")
        if (hal::Error e = fileLed.open(resolve(base, cfg.ledLog)); !e.ok()) return unavailable("LED", e);
    hal::Camera *cameraUsed = &camera;
    hal::TriggerButton *triggerUsed = &fileTrigger;
    hal::LedRing *ledUsed = &fileLed;
#ifdef ICACAM_HAVE_V4L2
    // A UVC camera: camera.device, else the udev rule's /dev/icacam-camera (deploy/), else
    // the first one.
    const std::string videoNode = !cfg.cameraDevice.empty()                       ? cfg.cameraDevice
                                  : std::filesystem::exists("/dev/icacam-camera") ? "/dev/icacam-camera"
                                                                                  : "/dev/video0";
    hal::V4l2Camera v4l2Camera(clock, {videoNode, 4, asked, cfg.cameraWidth, cfg.cameraHeight, cfg.stampDelayUs});
    if (cfg.cameraBackend == "v4l2") cameraUsed = &v4l2Camera;
#endif
#ifdef ICACAM_HAVE_LIBCAMERA
    // A CSI camera: fixed exposure and gain, locked colour gains; unset ones keep the
    // LibcameraOptions defaults (auto-exposure and AWB stay off either way).
    hal::LibcameraOptions csi;
    csi.camera = cfg.cameraId;
    csi.width = cfg.cameraWidth;
    csi.height = cfg.cameraHeight;
    if (asked.exposureUs >= 0) csi.controls.exposureUs = asked.exposureUs;
    if (asked.analogueGain >= 0) csi.controls.analogueGain = asked.analogueGain;
    if (asked.redGain >= 0) csi.controls.redGain = asked.redGain, csi.controls.blueGain = asked.blueGain;
    csi.controls.lensPosition = asked.lensPosition;
    csi.controls.sharpness = asked.sharpness;
    csi.controls.noiseReduction = asked.noiseReduction;
    hal::LibcameraCamera csiCamera(clock, csi);
    if (cfg.cameraBackend == "libcamera") cameraUsed = &csiCamera;
#endif
#ifdef ICACAM_HAVE_GPIOD
    // Button to ground with the SoC's pull-up (pressed = low); LED ring through a driver
    // transistor (on = high). docs/hardware.md has the wiring.
    hal::GpiodTrigger gpioTrigger(clock);
    if (cfg.triggerBackend == "gpiod") {
        hal::GpioLineSpec button;
        button.chipPath = cfg.gpioChip;
        hal::parseGpioLine(cfg.triggerLine, &button);
        button.activeLow = cfg.triggerActive == "low";
        button.pullUp = cfg.triggerBias == "pull-up";
        button.pullDown = cfg.triggerBias == "pull-down";
        button.biasOff = cfg.triggerBias == "disabled";
        button.debounceUs = cfg.debounceMs * 1000 / 2; // the kernel takes the bounce, the firmware the rest
        if (hal::Error e = gpioTrigger.open(button); !e.ok()) return unavailable("trigger", e);
        triggerUsed = &gpioTrigger;
    }
    hal::GpiodLed gpioLed;
    if (cfg.ledBackend == "gpiod") {
        hal::GpioLineSpec ring;
        ring.chipPath = cfg.ledChip.empty() ? cfg.gpioChip : cfg.ledChip;
        hal::parseGpioLine(cfg.ledLine, &ring);
        ring.activeLow = cfg.ledActive == "low";
        if (hal::Error e = gpioLed.open(ring); !e.ok()) return unavailable("LED", e);
        ledUsed = &gpioLed;
    }
#endif
    hal::PngDisplay display;
    if (cfg.displayBackend == "file")
        if (hal::Error e = display.open(resolve(base, cfg.displayDir), cfg.displayScale); !e.ok())
            return unavailable("display", e);
    hal::PtySerial serial;
    if (cfg.serialBackend == "pty")
        if (hal::Error e = serial.open(resolve(base, cfg.serialLink)); !e.ok()) return unavailable("serial", e);
    hal::SerialPort *serialUsed = &serial;
    std::string serialName = serial.slavePath() + " (" + resolve(base, cfg.serialLink) + ")";
#ifdef ICACAM_HAVE_TERMIOS
    hal::TermiosSerial uart;
    if (cfg.serialBackend == "uart") {
        if (hal::Error e = uart.open(cfg.serialDevice, cfg.serialBaud); !e.ok()) return unavailable("serial", e);
        serialUsed = &uart;
        serialName = cfg.serialDevice + " at " + std::to_string(cfg.serialBaud) + " baud";
    }
#endif
    hal::Display *displayUsed = &display;
#ifdef ICACAM_HAVE_SSD1306
    hal::I2cDevBus i2c;
    hal::Ssd1306Display oled(i2c, {cfg.displayDriver == "sh1106", cfg.displayRotate == 180, cfg.displayContrast});
    if (cfg.displayBackend == "ssd1306") {
        // A display that does not answer now is reported by each show(), not fatal: the
        // measurement still goes out on serial and into the journal.
        if (hal::Error e = i2c.open(cfg.i2cBus, cfg.i2cAddress); !e.ok()) return unavailable("display", e);
        if (hal::Error e = oled.init(); !e.ok()) std::fprintf(stderr, "icacam-fw: display: %s\n", e.message.c_str());
        displayUsed = &oled;
    }
#endif
    hal::FolderStorage storage;
    if (hal::Error e = storage.open(resolve(base, cfg.journalDir), uint64_t(cfg.journalQuotaMb) << 20); !e.ok())
        return unavailable("journal", e);

    struct NoDisplay final : hal::Display {
        hal::Error show(const hal::MonoBitmap &) override { return {}; }
    } noDisplay;
    // The friction model by name, the same set and default as `icacam measure --model`
    // (reading.model: the config check refused any other name).
    const friction::FrictionModel *model = friction::frictionModel(cfg.model);
    if (!model) return unavailable("model", hal::Error::make(hal::Errc::Invalid, "unknown reading.model " + cfg.model));
    fw::Device device({*cameraUsed, *triggerUsed, *ledUsed,
                       cfg.displayBackend == "none" ? static_cast<hal::Display &>(noDisplay) : *displayUsed,
                       *serialUsed, storage, clock},
                      cfg, *model);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGINT, onSignal);
    std::signal(SIGPIPE, SIG_IGN);
    if (hal::Error e = device.start(); !e.ok()) return unavailable("start", e);
    std::fprintf(stderr, "icacam-fw: running; serial on %s\n", serialName.c_str());
    while (!gStop) {
        device.tick();
        clock.sleepMs(5);
    }
    std::fprintf(stderr, "icacam-fw: stopped\n");
    return 0;
}
