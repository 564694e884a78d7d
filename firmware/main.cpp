// icacam-fw: the device program's composition root. Reads the config, builds the HAL
// backends it names (one factory per seam: firmware/backends/), and runs the device loop
// until SIGTERM/SIGINT.
//
// Exit codes suit systemd (Restart=on-failure, RestartPreventExitStatus=78):
//   0 stopped by a signal, 64 bad command line, 78 bad configuration (restarting cannot
//   help: the unit does not restart it). A missing part is no exit: the
//   camera, display, serial line, trigger button and LED ring are each looked for again while
//   the rest of the device runs, and each missing one is named on stderr (journalctl), on
//   serial, on the display and in the journal (firmware/parts.h, firmware/camera_health.h).
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "firmware/audit_log.h"
#include "firmware/backends/backend_config.h"
#include "firmware/backends/camera_backend.h"
#include "firmware/backends/display_backend.h"
#include "firmware/backends/serial_backend.h"
#include "firmware/backends/trigger_led_backend.h"
#include "firmware/config.h"
#include "firmware/device.h"
#include "firmware/device_calibration.h"
#include "firmware/recipe_camera.h"
#ifdef ICACAM_HAVE_NET
#include "firmware/net/network.h"
#endif
#include "firmware/sd_notify.h"
#include "friction/friction_models.h"
#include "hal/file/clocks.h"
#include "hal/file/folder_storage.h"

namespace {

using namespace icacam;

volatile std::sig_atomic_t gStop = 0;
void onSignal(int)
{
    gStop = 1;
}

constexpr int kExitUsage = 64, kExitConfig = 78;

std::string usage()
{
    std::string models;
    for (std::string_view name : friction::kModelNames) (models += models.empty() ? "" : ", ") += name;
    return std::string("usage: icacam-fw --config FILE [--check]\n"
                       "       icacam-fw --help-config\n"
                       "       icacam-fw --hash-password < password\n"
                       "       icacam-fw --check-audit DIR\n"
                       "Runs the icacam device program on the backends the config names.\n"
                       "  --config FILE  the device configuration (key = value lines; no default)\n"
                       "  --check        validate the config (and the calibration file it names) and exit\n"
                       "  --help-config  every config key with its default\n"
                       "  --hash-password  the web login's password file line for the password on stdin\n"
                       "  --check-audit DIR  check the recipe audit trail in the journal folder DIR (exit 0 intact,\n"
                       "                 1 damaged: each finding printed, 66 unreadable)\n"
                       "The friction model is the config's reading.model (default ") +
           friction::kDefaultModel + "; known: " + models +
           ").\n"
           "Exit codes: 0 stopped by a signal, 64 bad command line, 78 bad configuration. A missing\n"
           "device is no exit: it is named and looked for again. See docs/firmware.md for the keys, the\n"
           "serial protocol and the journal.\n";
}

int failed(const char *what, const hal::Error &e, int code)
{
    std::fprintf(stderr, "icacam-fw: %s: %s\n", what, e.message.c_str());
    return code;
}

void logLine(std::string_view line)
{
    std::fprintf(stderr, "icacam-fw: %.*s\n", int(line.size()), line.data());
}

// A part that refused to open for a reason in the config itself (a baud rate the UART does
// not have): a configuration mistake, not a missing part.
bool configMistake(const fw::Part &p)
{
    return p.state() == fw::Part::State::Missing && p.problemCode() == hal::Errc::Invalid;
}

// `--check-audit DIR`: the audit trail's chain and head checked, each finding on stdout.
int checkAuditCommand(const std::string &dir)
{
    hal::FolderStorage storage;
    if (hal::Error e = storage.open(dir, 0); !e.ok()) return failed("--check-audit", e, 66);
    hal::Result<std::string> log = storage.read(fw::kAuditFile), head = storage.read(fw::kAuditHead);
    if (!log.ok() && !head.ok()) return failed("--check-audit", log.error, 66);
    std::vector<fw::AuditEntry> entries;
    const fw::AuditCheck c = fw::checkAudit(log.ok() ? std::string_view(log.value) : std::string_view(),
                                            head.ok() ? std::string_view(head.value) : std::string_view(), &entries);
    if (!log.ok()) std::printf("%s: missing (its head is there)\n", fw::kAuditFile);
    for (const std::string &p : c.problems) std::printf("%s\n", p.c_str());
    std::printf("%s: %ld entries, %s\n", dir.c_str(), c.entries, c.ok() && log.ok() ? "intact" : "DAMAGED");
    return c.ok() && log.ok() ? 0 : 1;
}

struct Arguments {
    std::string configPath;
    bool checkOnly = false;
};

// The same forms as the icacam subcommands: --config FILE or --config=FILE. The exit code
// when the command line is all there is to do (help, or a mistake).
std::optional<int> parseArguments(int argc, char **argv, Arguments *args)
{
    auto usageError = [](const std::string &why) {
        std::fprintf(stderr, "icacam-fw: error: %s\n%s", why.c_str(), usage().c_str());
        return kExitUsage;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--config" || a.rfind("--config=", 0) == 0) {
            if (a.size() > 8)
                args->configPath = a.substr(9);
            else if (i + 1 < argc)
                args->configPath = argv[++i];
            else
                return usageError("--config needs a value");
            if (args->configPath.empty()) return usageError("--config needs a value");
        } else if (a == "--check")
            args->checkOnly = true;
        else if (a == "--help-config") {
            std::printf("config keys:\n%s", fw::configHelp().c_str());
            return 0;
#ifdef ICACAM_HAVE_NET
        } else if (a == "--hash-password") {
            return fw::net::hashPasswordCommand();
#endif
        } else if (a == "--check-audit") {
            if (i + 1 >= argc) return usageError("--check-audit needs the journal folder");
            return checkAuditCommand(argv[i + 1]);
        } else if (a == "-h" || a == "--help") {
            std::printf("%s", usage().c_str());
            return 0;
        } else
            return usageError((a.size() > 1 && a[0] == '-' ? "unknown option '" : "unexpected argument '") + a + "'");
    }
    if (args->configPath.empty()) return usageError("--config is required");
    return std::nullopt;
}

// Reads the config and reports every mistake in it at once: the keys (with their lines),
// the backends this build does not carry, the calibration file. False: a configuration
// mistake (kExitConfig).
bool loadConfig(const std::string &path, fw::Config *cfg)
{
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "icacam-fw: cannot read config '%s'\n", path.c_str());
        return false;
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto issues = fw::parseConfig(text, cfg);
    for (const auto &is : issues) {
        if (is.line > 0)
            std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), is.line, is.message.c_str());
        else
            std::fprintf(stderr, "%s: %s\n", path.c_str(), is.message.c_str());
    }
    bool ok = issues.empty();
    for (const std::string &issue :
         {fw::cameraBackendIssue(*cfg), fw::triggerBackendIssue(*cfg), fw::ledBackendIssue(*cfg),
          fw::displayBackendIssue(*cfg), fw::serialBackendIssue(*cfg)})
        if (!issue.empty()) {
            std::fprintf(stderr, "%s: %s\n", path.c_str(), issue.c_str());
            ok = false;
        }
#ifndef ICACAM_HAVE_NET
    if (cfg->httpPort > 0 || !cfg->mqttHost.empty()) {
        std::fprintf(stderr,
                     "%s: http.port / mqtt.host: this icacam-fw is built without the network "
                     "(libmicrohttpd, libmosquitto, libsodium)\n",
                     path.c_str());
        ok = false;
    }
#endif
    cfg->baseDir = std::filesystem::path(path).parent_path().string();
    // The calibration file is part of the configuration: unreadable, of another format or
    // for larger frames than the camera's is a configuration mistake (exit 78).
    if (fw::DeviceCalibration cal; issues.empty())
        if (std::string e = fw::loadDeviceCalibration(*cfg, &cal); !e.empty()) {
            std::fprintf(stderr, "%s: %s\n", path.c_str(), e.c_str());
            ok = false;
        }
    return ok;
}

// The device on the backends the config names, until a signal stops it.
int runDevice(const fw::Config &cfg)
{
    hal::SystemClock clock;
    // The file backends' light: the file LED switches it, the file camera's images are lit by
    // it (hal/file/scripted_light.h); a script names the ring's faults to try.
    hal::ScriptedLight light(clock);
    const bool fileLight = cfg.cameraBackend == "file" && cfg.ledBackend == "file";
    if (hal::Error e = light.open(fw::pathFromConfig(cfg, cfg.ledScript)); !e.ok())
        return failed("led.script", e, kExitConfig);
    auto makeCamera = [&clock, &light, fileLight](const fw::Config &c) {
        return fw::makeCamera(c, clock, fileLight ? &light : nullptr);
    };
    auto camera = makeCamera(cfg);
    if (!camera.ok()) return failed("camera", camera.error, kExitConfig);
    // The same backend, made again when a recipe changes the controls it takes at start.
    fw::RecipeCamera recipeCamera(makeCamera, std::move(camera.value), cfg);
    // The parts besides the camera: opened now, and while one is missing the device runs
    // without it and opens it again every camera.retry_ms.
    std::string serialName;
    fw::DisplayPart display([&cfg] { return fw::makeDisplay(cfg); });
    fw::SerialPart serial([&cfg, &serialName]() -> hal::Result<std::unique_ptr<hal::SerialPort>> {
        auto s = fw::makeSerial(cfg);
        if (!s.ok()) return {nullptr, s.error};
        serialName = s.value.name;
        return {std::move(s.value.port), {}};
    });
    fw::TriggerPart trigger([&cfg, &clock] { return fw::makeTrigger(cfg, clock); });
    fw::LedPart led([&cfg, &clock, &light] { return fw::makeLed(cfg, clock, &light); });
    fw::Parts parts(display, serial, trigger, led, clock, cfg.cameraRetryMs);
    parts.setLog(logLine);
    parts.openAll();
    for (int i = 0; i < fw::Parts::kCount; ++i)
        if (configMistake(parts.at(i)))
            return failed(parts.at(i).name(), hal::Error::make(hal::Errc::Invalid, parts.at(i).problem()), kExitConfig);
    hal::FolderStorage storage;
    // journal.dir is the config's: a folder that cannot be made or written is a mistake there
    // (or in the unit's StateDirectory), which restarting does not mend.
    if (hal::Error e = storage.open(fw::pathFromConfig(cfg, cfg.journalDir), uint64_t(cfg.journalQuotaMb) << 20);
        !e.ok())
        return failed("journal", e, kExitConfig);
    // The friction model by name, the same set and default as `icacam measure --model`
    // (reading.model: the config check refused any other name).
    const friction::FrictionModel *model = friction::frictionModel(cfg.model);
    if (!model)
        return failed("model", hal::Error::make(hal::Errc::Invalid, "unknown reading.model " + cfg.model), kExitConfig);
    fw::Device device({recipeCamera, trigger, led, display, serial, storage, clock, &parts, &recipeCamera}, cfg,
                      *model);
#ifdef ICACAM_HAVE_NET
    // The network is configured, not a part that may be absent: an address it cannot bind or a
    // certificate it cannot read is a configuration mistake, said once, not a restart loop.
    fw::net::Network network;
    if (hal::Error e =
            network.attach(cfg,
                           {fw::pathFromConfig(cfg, cfg.journalDir), fw::pathFromConfig(cfg, cfg.httpPasswordFile),
                            fw::pathFromConfig(cfg, cfg.httpTlsCert), fw::pathFromConfig(cfg, cfg.httpTlsKey)},
                           device);
        !e.ok())
        return failed("network", e, kExitConfig);
#endif
    std::signal(SIGTERM, onSignal);
    std::signal(SIGINT, onSignal);
    std::signal(SIGPIPE, SIG_IGN);
    if (hal::Error e = device.start(); !e.ok()) return failed("start", e, kExitConfig);
    std::fprintf(stderr, "icacam-fw: running; serial %s\n",
                 serial.ok() ? ("on " + serialName).c_str() : ("missing: " + serial.problem()).c_str());
    // systemd (Type=notify, WatchdogSec=): ready once started, alive on every pass of the
    // loop (firmware/sd_notify.h); nothing when not run by systemd.
    fw::SystemdNotifier systemd = fw::SystemdNotifier::fromEnvironment();
    if (hal::Error e = systemd.ready("idle"); !e.ok())
        std::fprintf(stderr, "icacam-fw: systemd: %s\n", e.message.c_str());
    std::string missing = parts.missingNames() + (device.camera().ok() ? "" : " camera");
    (void)systemd.status(missing.empty() ? "idle" : "missing: " + missing);
    int64_t nextStatusMs = 0;
    while (!gStop) {
        device.tick();
        systemd.keepAlive(clock.monotonicMs());
        // `systemctl status` names what is missing, when that changes (looked at once a second).
        if (const int64_t now = clock.monotonicMs(); now >= nextStatusMs) {
            nextStatusMs = now + 1000;
            if (std::string names = parts.missingNames() + (device.camera().ok() ? "" : " camera"); names != missing) {
                missing = names;
                (void)systemd.status(missing.empty() ? "idle" : "missing: " + missing);
            }
        }
        clock.sleepMs(5);
    }
    systemd.stopping();
    std::fprintf(stderr, "icacam-fw: stopped\n");
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    Arguments args;
    if (const std::optional<int> done = parseArguments(argc, argv, &args)) return *done;
    icacam::fw::Config cfg;
    if (!loadConfig(args.configPath, &cfg)) return kExitConfig;
    if (args.checkOnly) {
        std::printf("%s: ok\n", args.configPath.c_str());
        return 0;
    }
    return runDevice(cfg);
}
