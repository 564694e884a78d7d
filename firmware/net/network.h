#pragma once
// The device on the lab's network, as the config asks for it: results to MQTT (mqtt.host),
// the web page and JSON API (http.port). Each runs on threads of its own and talks to the
// device only through a DeviceListener and the CommandInbox.
#include <memory>

#include "firmware/config.h"
#include "firmware/device.h"
#include "hal/error.h"

namespace icacam::fw::net {

class MqttPublisher;

class Network {
public:
    Network();
    ~Network();
    // Starts what cfg configures and attaches it to device (before device.start()); journalDir
    // is cfg's journal.dir as a path. Nothing configured: nothing started.
    hal::Error attach(const Config &cfg, const std::string &journalDir, Device &device);
    void stop();

private:
    struct Parts;
    std::unique_ptr<Parts> parts_;
};

} // namespace icacam::fw::net
