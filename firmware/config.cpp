#include "firmware/config.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace icacam::fw {

namespace {

struct KeyDef {
    const char *key;
    const char *alias; // short name accepted over serial
    double Config::*number;
    int Config::*integer;
    std::string Config::*text;
    double min, max;
    const char *choices; // '|' separated, for text keys with fixed values
    bool live;
    const char *help;
};

// reading.model's choices: the factory's names (friction/friction_models.h), '|' separated.
const std::string kModelChoices = [] {
    std::string c;
    for (std::string_view name : friction::kModelNames) (c += c.empty() ? "" : "|") += name;
    return c;
}();

const KeyDef kKeys[] = {
    {"specimen.n", "n", &Config::n, nullptr, nullptr, 0.001, 1.0, nullptr, true,
     "strain-hardening exponent (required; the μ model covers 0.05-0.5)"},
    {"specimen.k_mpa", "k_mpa", &Config::kMpa, nullptr, nullptr, 0, 10000, nullptr, true,
     "strength coefficient K in MPa, 0 = unknown"},
    {"specimen.d0_mm", "d0_mm", &Config::d0Mm, nullptr, nullptr, 1, 200, nullptr, true, "initial diameter"},
    {"specimen.h0_mm", "h0_mm", &Config::h0Mm, nullptr, nullptr, 1, 300, nullptr, true, "initial height"},
    {"specimen.h_final_mm", "h_final_mm", &Config::hFinalMm, nullptr, nullptr, 0, 300, nullptr, true,
     "final height after upsetting, below h0_mm (0 = not given: the model's 50 % reduction)"},
    {"specimen.material", "material", nullptr, nullptr, &Config::material, 0, 32, nullptr, true,
     "material label, up to 32 characters"},
    {"reading.model", nullptr, nullptr, nullptr, &Config::model, 0, 0, kModelChoices.c_str(), false,
     "friction model, as icacam measure --model (paper_reduction: the paper's fit carried to 50 % "
     "reduction and H0/D0 1.5; fe: the project's CalculiX tables)"},
    {"tolerance.mu", "tolerance_mu", &Config::toleranceMu, nullptr, nullptr, 0, 1, nullptr, true,
     "status ok only when 2 sigma of mu is within max(tolerance.mu, tolerance.rel * mu)"},
    {"tolerance.rel", "tolerance_rel", &Config::toleranceRel, nullptr, nullptr, 0, 1, nullptr, true,
     "relative part of the tolerance on mu"},
    {"tolerance.n", "n_tol", &Config::nTol, nullptr, nullptr, 0, 0.2, nullptr, true,
     "standard uncertainty of the declared n"},
    {"tolerance.h_final_mm", "h_final_tol_mm", &Config::hFinalTolMm, nullptr, nullptr, 0, 5, nullptr, true,
     "standard uncertainty of a declared final height (mm)"},
    {"tolerance.mm_per_px", "mm_per_px_tol", &Config::mmPerPxTolRel, nullptr, nullptr, 0, 0.5, nullptr, true,
     "relative standard uncertainty of calibration.mm_per_px"},
    {"calibration.mm_per_px", "mm_per_px", &Config::mmPerPx, nullptr, nullptr, 1e-5, 1, nullptr, true,
     "scale in the end-face plane (this or calibration.file is required; with a file it only sizes the search)"},
    {"calibration.working_distance_mm", "working_distance_mm", &Config::workingDistanceMm, nullptr, nullptr, 0, 10000,
     nullptr, true,
     "the lens's distance to the end face (0 = not given: the barrel's silhouette is held against R_max as a "
     "telecentric view sees it; a close camera sees it inside)"},
    {"calibration.file", "calibration_file", nullptr, nullptr, &Config::calibrationFile, 0, 4096, nullptr, true,
     "camera calibration from `icacam calibrate`: maps each boundary into the end-face plane at "
     "h_final_mm (else h0_mm / 2) above the fixture"},
    {"camera.backend", nullptr, nullptr, nullptr, &Config::cameraBackend, 0, 0, "file|libcamera|v4l2", false,
     "camera driver"},
    {"camera.frames", nullptr, nullptr, nullptr, &Config::cameraFrames, 0, 4096, nullptr, false,
     "file backend: folder of images or list file"},
    {"camera.format", nullptr, nullptr, nullptr, &Config::cameraFormat, 0, 0, "grey8|rgb24", false, "pixel format"},
    {"camera.max_width", nullptr, nullptr, &Config::cameraMaxWidth, nullptr, 16, 16384, nullptr, false,
     "largest frame width accepted"},
    {"camera.max_height", nullptr, nullptr, &Config::cameraMaxHeight, nullptr, 16, 16384, nullptr, false,
     "largest frame height accepted"},
    {"camera.stride_align", nullptr, nullptr, &Config::cameraStrideAlign, nullptr, 1, 4096, nullptr, false,
     "file backend: pad rows to this many bytes, as an ISP does"},
    {"camera.timeout_ms", nullptr, nullptr, &Config::captureTimeoutMs, nullptr, 10, 60000, nullptr, false,
     "capture watchdog"},
    {"camera.loop", nullptr, nullptr, &Config::cameraLoop, nullptr, 0, 1, nullptr, false,
     "file backend: 1 = start over after the last image"},
    {"camera.device", nullptr, nullptr, nullptr, &Config::cameraDevice, 0, 4096, nullptr, false,
     "v4l2: capture node (\"\" = /dev/icacam-camera from the udev rule, else /dev/video0)"},
    {"camera.id", nullptr, nullptr, nullptr, &Config::cameraId, 0, 256, nullptr, false,
     "libcamera: camera id (`cam --list`) or part of the sensor model, e.g. imx708 (\"\" = the first)"},
    {"camera.width", nullptr, nullptr, &Config::cameraWidth, nullptr, 0, 16384, nullptr, false,
     "stream width (0 = the sensor's largest mode / the device's largest size within max_width)"},
    {"camera.height", nullptr, nullptr, &Config::cameraHeight, nullptr, 0, 16384, nullptr, false,
     "stream height (0 = as for width)"},
    {"camera.exposure_us", nullptr, nullptr, &Config::exposureUs, nullptr, -1, 10000000, nullptr, false,
     "manual exposure, auto-exposure off (-1: libcamera 10000, v4l2 left as is; v4l2 sets 100 us steps)"},
    {"camera.analogue_gain", nullptr, &Config::analogueGain, nullptr, nullptr, -1, 1000, nullptr, false,
     "sensor gain (-1: libcamera 1.0, v4l2 left as is; v4l2: the device's gain units)"},
    {"camera.red_gain", nullptr, &Config::redGain, nullptr, nullptr, -1, 10000, nullptr, false,
     "colour gain of red, auto white balance off (-1: libcamera 1.6; v4l2: red_balance units)"},
    {"camera.blue_gain", nullptr, &Config::blueGain, nullptr, nullptr, -1, 10000, nullptr, false,
     "colour gain of blue, as red_gain"},
    {"camera.lens_position", "lens_position", &Config::lensPosition, nullptr, nullptr, -1, 10000, nullptr, true,
     "autofocus off at this lens position (libcamera: dioptres = 1 / distance in m, Camera Module 3; "
     "v4l2: focus_absolute units; -1: leave the lens)"},
    {"camera.sharpness", nullptr, &Config::sharpness, nullptr, nullptr, -1, 1000, nullptr, false,
     "ISP sharpening (libcamera: 0 off, 1 default; it shifts edges, 0 is advised; -1: leave)"},
    {"camera.noise_reduction", nullptr, nullptr, nullptr, &Config::noiseReduction, 0, 0,
     "default|off|fast|high_quality", false, "ISP noise reduction (libcamera)"},
    {"camera.stamp_delay_us", "stamp_delay_us", nullptr, &Config::stampDelayUs, nullptr, -1, 1000000, nullptr, true,
     "v4l2: most time from a frame's exposure end to its buffer timestamp (-1: one frame interval)"},
    {"camera.retry_ms", nullptr, nullptr, &Config::cameraRetryMs, nullptr, 100, 600000, nullptr, false,
     "a missing or silent camera, and a missing display, serial line, button or LED line, is looked for again "
     "this often"},
    {"camera.tone_gamma", nullptr, &Config::toneGamma, nullptr, nullptr, 1, 3, nullptr, false,
     "the frames' tone curve as a power, encoded = linear^(1/tone_gamma): the ring's edges are located in linear "
     "light (1 = levels proportional to light; about 2.2 for an sRGB-like curve; libcamera with camera.tuning "
     "\"\": the curve the tuning override writes; docs/camera-setup.md)"},
    {"camera.white_balance_k", nullptr, nullptr, &Config::whiteBalanceK, nullptr, -1, 15000, nullptr, false,
     "v4l2: white balance fixed at this colour temperature in kelvin when red/blue gains are not set "
     "(-1: leave the camera's auto white balance)"},
    {"camera.tuning", nullptr, nullptr, nullptr, &Config::cameraTuning, 0, 4096, nullptr, false,
     "libcamera: \"\" the sensor's tuning file with adaptive contrast off and the tone curve camera.tone_gamma "
     "says (linear at 1), "
     "\"system\" libcamera's own file as installed, or the path of a tuning file"},
    {"camera.probe_ms", nullptr, nullptr, &Config::cameraProbeMs, nullptr, 0, 3600000, nullptr, false,
     "idle: a frame this often (none while frames flow) finds a camera lost between presses (0: never)"},
    {"trigger.backend", nullptr, nullptr, nullptr, &Config::triggerBackend, 0, 0, "file|gpiod", false, "button driver"},
    {"trigger.script", nullptr, nullptr, nullptr, &Config::triggerScript, 0, 4096, nullptr, false,
     "file backend: trigger script file or FIFO"},
    {"trigger.debounce_ms", nullptr, nullptr, &Config::debounceMs, nullptr, 1, 1000, nullptr, false,
     "presses shorter than this are bounce"},
    {"trigger.long_press_ms", nullptr, nullptr, &Config::longPressMs, nullptr, 100, 60000, nullptr, false,
     "held this long: shows the settings page instead of measuring"},
    {"trigger.gpio_chip", nullptr, nullptr, nullptr, &Config::gpioChip, 0, 256, nullptr, false,
     "gpiod: chip device (a line given by name is looked for on every chip)"},
    {"trigger.gpio_line", nullptr, nullptr, nullptr, &Config::triggerLine, 1, 64, nullptr, false,
     "gpiod: button line, by name (GPIO17) or offset on gpio_chip (17)"},
    {"trigger.active", nullptr, nullptr, nullptr, &Config::triggerActive, 0, 0, "low|high", false,
     "gpiod: the level of a pressed button (low: button to ground)"},
    {"trigger.bias", nullptr, nullptr, nullptr, &Config::triggerBias, 0, 0, "pull-up|pull-down|disabled|as-is", false,
     "gpiod: the SoC's resistor on the button line"},
    {"led.backend", nullptr, nullptr, nullptr, &Config::ledBackend, 0, 0, "file|gpiod", false, "LED ring driver"},
    {"led.log", nullptr, nullptr, nullptr, &Config::ledLog, 0, 4096, nullptr, false, "file backend: LED state log"},
    {"led.script", nullptr, nullptr, nullptr, &Config::ledScript, 0, 4096, nullptr, false,
     "file backend: the ring's faults, one line per switch-on (ok | late MS | dead | flash MS); the file "
     "camera's images are lit by it"},
    {"led.gpio_chip", nullptr, nullptr, nullptr, &Config::ledChip, 0, 256, nullptr, false,
     "gpiod: chip of the LED line (\"\" = trigger.gpio_chip)"},
    {"led.gpio_line", nullptr, nullptr, nullptr, &Config::ledLine, 1, 256, nullptr, false,
     "gpiod: LED ring line, by name (GPIO27) or offset; a segmented ring's lines separated by commas, "
     "segment 0 first, in the order of increasing image azimuth"},
    {"led.active", nullptr, nullptr, nullptr, &Config::ledActive, 0, 0, "high|low", false,
     "gpiod: the level that lights the ring (high: through an N-MOSFET)"},
    {"led.settle_ms", nullptr, nullptr, &Config::ledSettleMs, nullptr, 0, 1000, nullptr, false,
     "wait after switching the ring on before capturing"},
    {"led.segments", nullptr, nullptr, &Config::ledSegments, nullptr, 1, 8, nullptr, false,
     "segments of the ring lit one at a time before the whole ring, for the contact edge from the surface's "
     "tilt (1: the ring is one line; 3-8: a line each, led.gpio_line lists them)"},
    {"led.segment0_deg", "segment0_deg", &Config::ledSegment0Deg, nullptr, nullptr, 0, 360, nullptr, true,
     "segmented ring: segment 0's centre as seen in the image, degrees from the image's +x toward +y (rows down); "
     "a measurement that finds it elsewhere says where"},
    {"led.segment_exposure_us", nullptr, nullptr, &Config::ledSegmentExposureUs, nullptr, 0, 10000000, nullptr, false,
     "segmented ring: the segment frames' exposure (0: camera.exposure_us times led.segments)"},
    {"led.lit_attempts", nullptr, nullptr, &Config::litAttempts, nullptr, 1, 10, nullptr, false,
     "frames tried per measurement: one not lit top to bottom is refused and captured again; then "
     "the error 'LED ring not lit'"},
    {"led.min_rise", nullptr, nullptr, &Config::litMinRise, nullptr, 1, 255, nullptr, false,
     "luma levels the ring must add, over the frame taken with it off, to every band of the specimen's region"},
    {"display.backend", nullptr, nullptr, nullptr, &Config::displayBackend, 0, 0, "file|ssd1306|none", false,
     "display driver"},
    {"display.dir", nullptr, nullptr, nullptr, &Config::displayDir, 0, 4096, nullptr, false,
     "file backend: folder for the PNG pictures"},
    {"display.scale", nullptr, nullptr, &Config::displayScale, nullptr, 1, 8, nullptr, false,
     "file backend: enlarge pictures"},
    {"display.i2c_bus", nullptr, nullptr, &Config::i2cBus, nullptr, 0, 255, nullptr, false, "ssd1306: /dev/i2c-N"},
    {"display.i2c_address", nullptr, nullptr, &Config::i2cAddress, nullptr, 3, 119, nullptr, false,
     "ssd1306: 7-bit address (60 = 0x3C)"},
    {"display.driver", nullptr, nullptr, nullptr, &Config::displayDriver, 0, 0, "ssd1306|sh1106", false,
     "ssd1306: the controller (sh1106: the 1.3 inch panels sold as SSD1306)"},
    {"display.rotate", nullptr, nullptr, &Config::displayRotate, nullptr, 0, 180, nullptr, false,
     "ssd1306: 0 or 180 degrees"},
    {"display.contrast", nullptr, nullptr, &Config::displayContrast, nullptr, 0, 255, nullptr, false,
     "ssd1306: contrast 0-255"},
    {"serial.backend", nullptr, nullptr, nullptr, &Config::serialBackend, 0, 0, "pty|uart", false, "serial driver"},
    {"serial.link", nullptr, nullptr, nullptr, &Config::serialLink, 0, 4096, nullptr, false,
     "pty backend: symlink to the pty for the host side"},
    {"serial.device", nullptr, nullptr, nullptr, &Config::serialDevice, 0, 4096, nullptr, false, "uart: tty device"},
    {"serial.baud", nullptr, nullptr, &Config::serialBaud, nullptr, 1200, 4000000, nullptr, false, "uart: baud rate"},
    {"journal.dir", nullptr, nullptr, nullptr, &Config::journalDir, 1, 4096, nullptr, false,
     "folder of the journal and images (required)"},
    {"journal.images", nullptr, nullptr, nullptr, &Config::journalImages, 0, 0, "pgm|none", false,
     "save each frame with its result"},
    {"journal.quota_mb", nullptr, nullptr, &Config::journalQuotaMb, nullptr, 0, 1000000, nullptr, false,
     "limit the journal folder (0 = free space of the card)"},
    {"journal.memory", nullptr, nullptr, &Config::journalMemory, nullptr, 1, 1000, nullptr, false,
     "results kept for the `results` command"},
    {"http.address", nullptr, nullptr, nullptr, &Config::httpAddress, 1, 64, nullptr, false,
     "web page and JSON API: the IPv4 address to listen on (0.0.0.0: every interface)"},
    {"http.port", nullptr, nullptr, &Config::httpPort, nullptr, 0, 65535, nullptr, false,
     "web page and JSON API: TCP port (0 = off)"},
    {"http.password_file", nullptr, nullptr, nullptr, &Config::httpPasswordFile, 1, 4096, nullptr, false,
     "the web login's password, stored hashed (written by deploy/install.sh or icacam-fw --hash-password)"},
    {"http.public_read", nullptr, nullptr, &Config::httpPublicRead, nullptr, 0, 1, nullptr, false,
     "1 = the read-only pages and API open without a login (changes always need one)"},
    {"http.tls_cert", nullptr, nullptr, nullptr, &Config::httpTlsCert, 0, 4096, nullptr, false,
     "HTTPS: certificate file (PEM; with http.tls_key)"},
    {"http.tls_key", nullptr, nullptr, nullptr, &Config::httpTlsKey, 0, 4096, nullptr, false,
     "HTTPS: private key file (PEM; with http.tls_cert)"},
    {"mqtt.host", nullptr, nullptr, nullptr, &Config::mqttHost, 0, 255, nullptr, false,
     "MQTT broker to publish every result to (\"\" = off)"},
    {"mqtt.port", nullptr, nullptr, &Config::mqttPort, nullptr, 1, 65535, nullptr, false, "MQTT broker's port"},
    {"mqtt.topic", nullptr, nullptr, nullptr, &Config::mqttTopic, 1, 128, nullptr, false,
     "topic prefix: results on TOPIC/result, the retained online/offline state on TOPIC/state"},
    {"mqtt.client_id", nullptr, nullptr, nullptr, &Config::mqttClientId, 0, 64, nullptr, false,
     "MQTT client id (\"\" = icacam-<host name>)"},
    {"mqtt.keepalive_s", nullptr, nullptr, &Config::mqttKeepaliveS, nullptr, 5, 3600, nullptr, false,
     "MQTT keepalive: a broker that goes silent is noticed within 1.5 times this"},
};

const KeyDef *findKey(std::string_view key, bool allowAlias)
{
    for (const KeyDef &k : kKeys)
        if (key == k.key || (allowAlias && k.alias && key == k.alias)) return &k;
    return nullptr;
}

bool parseDouble(std::string_view s, double *v)
{
    if (s.empty() || s.size() > 64) return false;
    char buf[72];
    s.copy(buf, s.size());
    buf[s.size()] = 0;
    char *end = nullptr;
    *v = std::strtod(buf, &end);
    return end == buf + s.size() && std::isfinite(*v);
}

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::string fmt(double v)
{
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

} // namespace

std::string setConfigKey(Config *cfg, std::string_view key, std::string_view value, bool liveOnly)
{
    const KeyDef *k = findKey(key, liveOnly);
    if (!k) return "unknown key '" + std::string(key.substr(0, 64)) + "'";
    if (liveOnly && !k->live) return "'" + std::string(key) + "' cannot be changed while running";
    if (k->number || k->integer) {
        double v = 0;
        if (!parseDouble(value, &v))
            return std::string(k->key) + ": '" + std::string(value.substr(0, 64)) + "' is not a number";
        if (v < k->min || v > k->max)
            return std::string(k->key) + " must be between " + fmt(k->min) + " and " + fmt(k->max) + ", not " + fmt(v);
        if (k->integer) {
            if (v != std::floor(v)) return std::string(k->key) + " must be a whole number";
            cfg->*(k->integer) = int(v);
        } else {
            cfg->*(k->number) = v;
        }
        return "";
    }
    if (k->choices) {
        std::string_view c = k->choices;
        while (!c.empty()) {
            const size_t bar = c.find('|');
            if (c.substr(0, bar) == value) {
                cfg->*(k->text) = std::string(value);
                return "";
            }
            if (bar == std::string_view::npos) break;
            c.remove_prefix(bar + 1);
        }
        return std::string(k->key) + " must be one of " + k->choices + ", not '" + std::string(value.substr(0, 64)) +
               "'";
    }
    if (value.size() < size_t(k->min) || value.size() > size_t(k->max))
        return std::string(k->key) + " must be " + fmt(k->min) + " to " + fmt(k->max) + " characters long";
    for (char ch : value)
        if (uint8_t(ch) < 0x20 || ch == '"' || ch == '\\')
            return std::string(k->key) + ": control characters, quotes and backslashes are not allowed";
    cfg->*(k->text) = std::string(value);
    return "";
}

bool getConfigKey(const Config &cfg, std::string_view key, std::string *value, bool *isNumber)
{
    const KeyDef *k = findKey(key, true);
    if (!k) return false;
    *isNumber = k->number || k->integer;
    if (k->number)
        *value = fmt(cfg.*(k->number));
    else if (k->integer)
        *value = std::to_string(cfg.*(k->integer));
    else
        *value = cfg.*(k->text);
    return true;
}

std::string specimenIssue(const Config &cfg)
{
    if (cfg.hFinalMm > 0 && cfg.hFinalMm >= cfg.h0Mm)
        return "specimen.h_final_mm (" + fmt(cfg.hFinalMm) + ") must be below specimen.h0_mm (" + fmt(cfg.h0Mm) +
               "); 0 = not given";
    return {};
}

std::vector<std::string> ledLines(const Config &cfg)
{
    std::vector<std::string> lines;
    std::string_view rest = cfg.ledLine;
    while (true) {
        const size_t comma = rest.find(',');
        lines.emplace_back(trim(rest.substr(0, comma)));
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    return lines;
}

std::string ledSegmentIssue(const Config &cfg)
{
    if (cfg.ledSegments == 1) {
        if (cfg.ledLine.find(',') != std::string::npos)
            return "led.gpio_line lists " + std::to_string(ledLines(cfg).size()) +
                   " lines: set led.segments to their number (a segmented ring)";
        return {};
    }
    if (cfg.ledSegments < 3) return "led.segments is 1 (one line) or 3-8 (fewer cannot tell the tilt's direction)";
    // The segment frames are compared pixel by pixel, so they share one fixed exposure, and
    // the whole ring's frame after them goes back to the recipe's: both must be numbers.
    if (cfg.exposureUs < 0) return "led.segments needs a fixed exposure: camera.exposure_us";
    if (cfg.ledBackend == "gpiod") {
        const std::vector<std::string> lines = ledLines(cfg);
        if (int(lines.size()) != cfg.ledSegments)
            return "led.gpio_line lists " + std::to_string(lines.size()) +
                   " line(s) for led.segments = " + std::to_string(cfg.ledSegments) +
                   ": one line per segment, segment 0 first";
        for (const std::string &l : lines)
            if (l.empty()) return "led.gpio_line has an empty entry";
    }
    return {};
}

int segmentExposureUs(const Config &cfg)
{
    if (cfg.ledSegmentExposureUs > 0) return cfg.ledSegmentExposureUs;
    const long long us = (long long)(cfg.exposureUs) * cfg.ledSegments;
    return us > 10000000 ? 10000000 : int(us);
}

std::vector<std::string> crossKeyIssues(const Config &cfg)
{
    std::vector<std::string> issues;
    if (std::string e = specimenIssue(cfg); !e.empty()) issues.push_back(e);
    if (cfg.cameraBackend == "file" && cfg.cameraFrames.empty())
        issues.push_back("camera.frames is required with camera.backend = file");
    if (cfg.displayBackend == "file" && cfg.displayDir.empty())
        issues.push_back("display.dir is required with display.backend = file");
    if (cfg.displayRotate != 0 && cfg.displayRotate != 180) issues.push_back("display.rotate must be 0 or 180");
    if ((cfg.redGain < 0) != (cfg.blueGain < 0))
        issues.push_back("camera.red_gain and camera.blue_gain are set together (both or neither)");
    if (cfg.httpTlsCert.empty() != cfg.httpTlsKey.empty())
        issues.push_back("http.tls_cert and http.tls_key are set together (both or neither)");
    if (cfg.mqttTopic.find_first_of("+#") != std::string::npos)
        issues.push_back("mqtt.topic must not contain the wildcards + or #");
    if (std::string e = ledSegmentIssue(cfg); !e.empty()) issues.push_back(e);
    if (cfg.serialBackend == "pty" && cfg.serialLink.empty())
        issues.push_back("serial.link is required with serial.backend = pty");
    return issues;
}

std::vector<std::string> configKeys(bool liveOnly)
{
    std::vector<std::string> out;
    for (const KeyDef &k : kKeys)
        if (!liveOnly || k.live) out.emplace_back(liveOnly ? k.alias : k.key);
    return out;
}

std::string liveKeyName(std::string_view key)
{
    const KeyDef *k = findKey(key, true);
    return k && k->live ? k->alias : "";
}

hal::CameraControls cameraControlsOf(const Config &cfg)
{
    return {cfg.exposureUs,
            cfg.analogueGain,
            cfg.redGain,
            cfg.blueGain,
            cfg.lensPosition,
            cfg.sharpness,
            noiseReductionLevel(cfg.noiseReduction)};
}

int noiseReductionLevel(std::string_view name)
{
    if (name == "off") return 0;
    if (name == "fast") return 1;
    if (name == "high_quality") return 2;
    return -1;
}

std::string configHelp()
{
    const Config defaults;
    std::string out;
    for (const KeyDef &k : kKeys) {
        out += "  ";
        out += k.key;
        out += std::string(size_t(std::max(1, 24 - int(std::string_view(k.key).size()))), ' ');
        out += k.help;
        if (k.choices) out += std::string(" (") + k.choices + ")";
        char value[64] = "";
        if (k.number)
            std::snprintf(value, sizeof value, "%g", defaults.*k.number);
        else if (k.integer)
            std::snprintf(value, sizeof value, "%d", defaults.*k.integer);
        out += std::string(" [default ") + (k.text ? "\"" + defaults.*k.text + "\"" : std::string(value)) + "]";
        if (k.live) out += " [settable over serial]";
        out += '\n';
    }
    return out;
}

std::vector<ConfigIssue> parseConfig(std::string_view text, Config *cfg)
{
    std::vector<ConfigIssue> issues;
    std::string section;
    int lineNo = 0;
    bool seenN = false, seenScale = false, seenJournal = false;
    while (!text.empty()) {
        ++lineNo;
        const size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        line = trim(line);
        if (line.empty()) continue;
        if (issues.size() >= 50) {
            issues.push_back({lineNo, "too many errors, stopping"});
            break;
        }
        if (line.front() == '[') {
            if (line.back() != ']' || line.size() < 3) {
                issues.push_back({lineNo, "a section header looks like [name]"});
                continue;
            }
            section = std::string(trim(line.substr(1, line.size() - 2)));
            continue;
        }
        const size_t eq = line.find('=');
        if (eq == std::string_view::npos) {
            issues.push_back({lineNo, "expected 'key = value'"});
            continue;
        }
        std::string key = std::string(trim(line.substr(0, eq)));
        std::string_view value = trim(line.substr(eq + 1));
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
        if (!section.empty() && key.find('.') == std::string::npos) key = section + "." + key;
        if (std::string err = setConfigKey(cfg, key, value, false); !err.empty()) {
            issues.push_back({lineNo, err});
            continue;
        }
        seenN |= key == "specimen.n";
        seenScale |= key == "calibration.mm_per_px" || (key == "calibration.file" && !value.empty());
        seenJournal |= key == "journal.dir";
    }
    if (!seenN) issues.push_back({0, "specimen.n is required (the strain-hardening exponent)"});
    if (!seenScale) issues.push_back({0, "calibration.mm_per_px or calibration.file is required (the camera's scale)"});
    if (!seenJournal) issues.push_back({0, "journal.dir is required (where results are kept)"});
    for (std::string &e : crossKeyIssues(*cfg)) issues.push_back({0, std::move(e)});
    return issues;
}

} // namespace icacam::fw
