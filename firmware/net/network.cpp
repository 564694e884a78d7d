#include "firmware/net/network.h"

#include "firmware/net/mqtt_publisher.h"
#include "hal/file/folder_storage.h"

namespace icacam::fw::net {

struct Network::Parts {
    hal::FolderStorage journalDir;
    std::unique_ptr<MqttPublisher> mqtt;
};

Network::Network() : parts_(std::make_unique<Parts>()) {}

Network::~Network()
{
    stop();
}

void Network::stop()
{
    if (parts_->mqtt) parts_->mqtt->stop();
}

hal::Error Network::attach(const Config &cfg, const std::string &journalDir, Device &device)
{
    if (cfg.mqttHost.empty()) return {};
    if (hal::Error e = parts_->journalDir.open(journalDir, 0); !e.ok()) return e;
    MqttSettings s{cfg.mqttHost, cfg.mqttPort, cfg.mqttTopic, cfg.mqttClientId, cfg.mqttKeepaliveS};
    parts_->mqtt = std::make_unique<MqttPublisher>(s, parts_->journalDir, journalDir + "/journal.jsonl");
    if (hal::Error e = parts_->mqtt->start(); !e.ok()) return e;
    device.addListener(parts_->mqtt.get());
    return {};
}

} // namespace icacam::fw::net
