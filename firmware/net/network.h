#pragma once
// The device on the lab's network, as the config asks for it: results to MQTT (mqtt.host),
// the web page and JSON API (http.port). Each runs on threads of its own and talks to the
// device only through DeviceListeners and the CommandInbox.
#include <memory>
#include <string>

#include "firmware/config.h"
#include "firmware/device.h"
#include "hal/error.h"

namespace icacam::fw::net {

class Network {
public:
    Network();
    ~Network();
    // Starts what cfg configures and attaches it to device (before device.start()); the
    // paths are cfg's, resolved against the config file's folder. Nothing configured:
    // nothing started.
    struct Paths {
        std::string journalDir, passwordFile, tlsCert, tlsKey;
    };
    hal::Error attach(const Config &cfg, const Paths &paths, Device &device);
    void stop();
    // The web server's port (0 when it does not run).
    int httpPort() const;

private:
    struct Parts;
    std::unique_ptr<Parts> parts_;
};

// `icacam-fw --hash-password`: the first line of stdin as the password file's line on
// stdout. The exit code.
int hashPasswordCommand();

} // namespace icacam::fw::net
