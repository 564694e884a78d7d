#pragma once
// The device configuration: a text file of `key = value` lines ('#' comments, optional
// `[section]` headers that prefix the keys), validated as a whole at start-up so that every
// mistake is reported at once with its line number. The keys are listed in docs/firmware.md
// and by `icacam-fw --help-config`.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "friction/friction_models.h"
#include "hal/camera.h"

namespace icacam::fw {

struct Config {
    // [specimen] what is being measured; changeable over serial ("live")
    double n = 0;    // strain-hardening exponent (required)
    double kMpa = 0; // strength coefficient, 0 = unknown
    double d0Mm = 10, h0Mm = 15;
    double hFinalMm = 0;          // final height after upsetting; 0 = not given (50 % assumed)
    double workingDistanceMm = 0; // the lens's distance to the end face; 0 = not given
    double toneGamma = 1;         // the camera's tone curve, encoded = linear^(1/γ); 1 = linear
    std::string material;
    // [reading] the friction model (friction/friction_models.h), as `icacam measure --model`
    std::string model = friction::kDefaultModel;
    // [tolerance] the lab's tolerance on μ and the declared inputs' (1 σ); changeable over serial
    double toleranceMu = 0.01, toleranceRel = 0.05; // ok: 2 σ_μ within max(abs, rel · μ)
    double nTol = 0.01, hFinalTolMm = 0.05, mmPerPxTolRel = 0.005;
    // [calibration] one of the two is required
    double mmPerPx = 0;          // scale in the end-face plane (with a file: only sizes the search)
    std::string calibrationFile; // from `icacam calibrate` (docs/calibration.md)
    // [camera]
    std::string cameraBackend = "file";
    std::string cameraFrames; // file backend: folder or list file
    std::string cameraFormat = "grey8";
    int cameraMaxWidth = 4096, cameraMaxHeight = 3072;
    int cameraStrideAlign = 1;
    int captureTimeoutMs = 2000;
    int cameraLoop = 0;
    std::string cameraDevice;              // v4l2: node ("" = /dev/icacam-camera, else /dev/video0)
    std::string cameraId;                  // libcamera: id or part of the sensor model ("" = first)
    int cameraWidth = 0, cameraHeight = 0; // 0 = the sensor's largest mode within max_*
    // Imaging controls; -1 = not set (libcamera: its fixed defaults; v4l2: left as it is).
    int exposureUs = -1;
    double analogueGain = -1;
    double redGain = -1, blueGain = -1;
    double lensPosition = -1;
    double sharpness = -1;
    std::string noiseReduction = "default"; // default | off | fast | high_quality
    int stampDelayUs = -1;                  // v4l2: stamp after exposure end (-1: a frame interval)
    int whiteBalanceK = 5000;               // v4l2: fixed colour temperature (-1: leave the camera's)
    std::string cameraTuning;               // libcamera: "" fixed tone curve, "system", or a tuning file
    int cameraRetryMs = 2000;               // a missing camera is looked for again this often
    int cameraProbeMs = 5000;               // idle: one frame this often shows the camera is there
    // [trigger] and [led]
    std::string triggerBackend = "file";
    std::string triggerScript; // file backend: script file or FIFO ("" = serial only)
    int debounceMs = 30, longPressMs = 1500;
    std::string gpioChip = "/dev/gpiochip0";
    std::string triggerLine = "GPIO17";  // line name (GPIO17) or offset on gpio_chip (17)
    std::string triggerActive = "low";   // the level that means pressed
    std::string triggerBias = "pull-up"; // pull-up | pull-down | disabled | as-is
    std::string ledChip;                 // "" = trigger.gpio_chip
    std::string ledLine = "GPIO27";      // one line, or a segmented ring's lines in azimuth order
    std::string ledActive = "high";      // the level that lights the ring
    std::string ledBackend = "file";
    std::string ledLog;
    std::string ledScript; // file backend: when the ring really lights (hal/file/scripted_light.h)
    int ledSettleMs = 20;
    // A ring wired in segments, lit one at a time before the whole ring (the contact edge
    // from the surface's tilt, vision/contact_tilt.h): how many (1: one line, none lit
    // alone), segment 0's centre as an image azimuth (degrees from +x toward +y, rows down;
    // the others follow at 360 / segments), and the segment frames' exposure (0: the
    // recipe's camera.exposure_us times the segments, as bright as the whole ring's frame).
    int ledSegments = 1;
    double ledSegment0Deg = 0;
    int ledSegmentExposureUs = 0;
    // Every frame measured is checked lit top to bottom against a frame taken with the ring
    // off (firmware/lit_frame.h): a frame refused is captured again, this many times in all,
    // and a band is lit when the ring adds this many luma levels to it.
    int litAttempts = 3;
    int litMinRise = 12;
    // [display]
    std::string displayBackend = "file";
    std::string displayDir;
    int displayScale = 1;
    int i2cBus = 1, i2cAddress = 0x3C;
    std::string displayDriver = "ssd1306"; // ssd1306 | sh1106 (the 1.3 inch panels)
    int displayRotate = 0;                 // 0 | 180
    int displayContrast = 127;
    // [serial]
    std::string serialBackend = "pty";
    std::string serialLink;                    // pty backend: symlink to the slave
    std::string serialDevice = "/dev/serial0"; // Raspberry Pi OS: the header UART, whichever it is
    int serialBaud = 115200;
    // [journal]
    std::string journalDir;
    std::string journalImages = "pgm"; // pgm | none
    int journalQuotaMb = 0;            // 0 = the card's free space
    int journalMemory = 64;            // results kept in RAM for `results`
    // [http] and [mqtt]: the device on the lab's network (docs/network.md); each off unless
    // its port or host is set
    std::string httpAddress = "127.0.0.1";
    int httpPort = 0; // 0 = no web page
    std::string httpPasswordFile = "/etc/icacam/web-password";
    int httpPublicRead = 0; // 1 = the read-only pages and API without a login
    std::string httpTlsCert, httpTlsKey;
    std::string mqttHost; // "" = no MQTT
    int mqttPort = 1883;
    std::string mqttTopic = "icacam";
    std::string mqttClientId; // "" = icacam-<host name>
    int mqttKeepaliveS = 30;
    // Not a key: the config file's folder, against which relative paths set over serial
    // (calibration.file) are resolved.
    std::string baseDir;
};

struct ConfigIssue {
    int line = 0; // 0: not tied to a line
    std::string message;
};

// Parses and validates text; issues empty means cfg is complete and valid. Never throws.
std::vector<ConfigIssue> parseConfig(std::string_view text, Config *cfg);

// Sets one key from its text value (used by the parser and by `set` over serial).
// liveOnly: only the specimen and calibration keys. Returns "" or a message.
std::string setConfigKey(Config *cfg, std::string_view key, std::string_view value, bool liveOnly);
// The value of a key as text ("" and false for an unknown key).
bool getConfigKey(const Config &cfg, std::string_view key, std::string *value, bool *isNumber);
// Names of keys; live: only those settable over serial.
std::vector<std::string> configKeys(bool liveOnly);
// What no single key can check: the specimen's keys against each other ("" when consistent).
std::string specimenIssue(const Config &cfg);
// Every rule that ties keys together (the specimen's heights, colour gains set in pairs, a
// backend's required paths, ...): what parseConfig checks after the keys, for any whole
// config, e.g. one with a recipe applied. Empty when consistent.
std::vector<std::string> crossKeyIssues(const Config &cfg);
// The LED ring's lines (led.gpio_line split at commas, trimmed), segment 0 first.
std::vector<std::string> ledLines(const Config &cfg);
// A segmented ring's keys against each other and the camera's exposure ("" when consistent).
std::string ledSegmentIssue(const Config &cfg);
// The segment frames' exposure in µs (led.segment_exposure_us, else camera.exposure_us times
// led.segments, at most 10 s); only meaningful where ledSegmentIssue is "".
int segmentExposureUs(const Config &cfg);
// The serial name of a live key given by its full name or serial name ("" if none).
std::string liveKeyName(std::string_view key);
std::string configHelp();
// The imaging controls the config asks for (-1 where not set).
hal::CameraControls cameraControlsOf(const Config &cfg);
// camera.noise_reduction as libcamera's level (-1 default, 0 off, 1 fast, 2 high quality).
int noiseReductionLevel(std::string_view name);

} // namespace icacam::fw
