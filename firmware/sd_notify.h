#pragma once
// systemd's service notification protocol, without libsystemd: readiness (Type=notify), a
// status line for `systemctl status`, and the watchdog keep-alive (WatchdogSec=).
//
// The protocol (sd_notify(3); a self-contained implementation is systemd's own
// man/notify-selfcontained-example.c, and systemd.io/PORTABILITY_AND_STABILITY lists the
// protocol as stable): the service manager puts an AF_UNIX datagram socket's address in
// $NOTIFY_SOCKET (a path, or "@name" for the abstract namespace); each notification is one
// datagram of newline-separated VARIABLE=value assignments. The watchdog (sd_watchdog_enabled
// (3)): $WATCHDOG_USEC is the interval, $WATCHDOG_PID, when set, the process it is meant
// for; the service sends "WATCHDOG=1" more often than that, every half interval being the
// recommendation. Without $NOTIFY_SOCKET (run by hand, in tests) every call does nothing
// and succeeds, as sd_notify() does.
//
// Call points for the device program (the composition root wires them):
//  * after the config is read and Device::start() returned: ready("idle") (READY=1; with
//    Type=notify, systemd counts the start from here, so a config error still fails the
//    start and stops with its exit code);
//  * every pass of the main loop: keepAlive(clock.monotonicMs()); a pass is bounded by
//    camera.timeout_ms per capture, far under WatchdogSec / 2 (deploy/icacam-fw.service);
//  * when a device goes missing or comes back: status("no camera: ...") / status("idle"),
//    the same words as the display, so `systemctl status icacam-fw` shows them;
//  * on SIGTERM, before the devices are closed: stopping().
// No heap: messages are assembled in a fixed buffer (status text is cut to fit).
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "hal/error.h"
#include "hal/unique_fd.h"

namespace icacam::fw {

class SystemdNotifier {
public:
    static constexpr size_t kMaxMessage = 512;

    // From $NOTIFY_SOCKET, $WATCHDOG_USEC and $WATCHDOG_PID.
    static SystemdNotifier fromEnvironment();
    // socket "": inactive. watchdogUs 0: no watchdog. watchdogPid 0: for this process.
    SystemdNotifier(std::string socket, int64_t watchdogUs, pid_t watchdogPid);

    bool active() const { return !socket_.empty(); }
    // The watchdog interval meant for this process (0: none).
    int64_t watchdogIntervalUs() const { return watchdogUs_; }

    hal::Error ready(std::string_view status = {}); // READY=1 (and STATUS=)
    hal::Error status(std::string_view text);       // STATUS=
    hal::Error stopping();                          // STOPPING=1
    // WATCHDOG=1, at most every half interval (nowMs: the HAL's monotonic clock). Nothing
    // without a watchdog for this process.
    hal::Error keepAlive(int64_t nowMs);
    // One datagram, as it is. Errors: Invalid (empty, too long, or an address that is
    // neither a path nor "@name"), Io.
    hal::Error send(std::string_view message);

private:
    std::string socket_;
    int64_t watchdogUs_ = 0;
    int64_t lastKeepAliveMs_ = 0;
    bool keptAlive_ = false;
    hal::UniqueFd fd_;
};

} // namespace icacam::fw
