#include "firmware/net/network.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>

#include "firmware/net/aim_exchange.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/journal_tail.h"
#include "firmware/net/line_exchange.h"
#include "firmware/net/mqtt_publisher.h"
#include "firmware/net/web_api.h"
#include "firmware/net/web_auth.h"
#include "firmware/net/web_server.h"
#include "hal/file/folder_storage.h"

namespace icacam::fw::net {

namespace {

bool readFile(const std::string &path, std::string *out)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

} // namespace

struct Network::Parts {
    hal::FolderStorage journalDir;
    std::unique_ptr<MqttPublisher> mqtt;
    std::unique_ptr<JournalTail> journal;
    CommandInbox inbox;
    RecipeDesk recipes;
    LineExchange lines;
    AimExchange aim;
    std::unique_ptr<WebAuth> auth;
    std::unique_ptr<WebApi> api;
    std::unique_ptr<WebServer> server;
};

Network::Network() : parts_(std::make_unique<Parts>()) {}

Network::~Network()
{
    stop();
}

void Network::stop()
{
    if (parts_->server) parts_->server->stop();
    if (parts_->mqtt) parts_->mqtt->stop();
}

int Network::httpPort() const
{
    return parts_->server ? parts_->server->port() : 0;
}

hal::Error Network::attach(const Config &cfg, const Paths &paths, Device &device)
{
    Parts &p = *parts_;
    const std::string journalFile = paths.journalDir + "/journal.jsonl";
    if (!cfg.mqttHost.empty()) {
        if (hal::Error e = p.journalDir.open(paths.journalDir, 0); !e.ok()) return e;
        MqttSettings s{cfg.mqttHost, cfg.mqttPort, cfg.mqttTopic, cfg.mqttClientId, cfg.mqttKeepaliveS};
        p.mqtt = std::make_unique<MqttPublisher>(s, p.journalDir, journalFile);
        if (hal::Error e = p.mqtt->start(); !e.ok()) return e;
        device.addListener(p.mqtt.get());
    }
    if (cfg.httpPort > 0) {
        // No password file: the pages can still be read when open, nothing can be changed.
        std::string hash;
        if (!readFile(paths.passwordFile, &hash))
            std::fprintf(stderr, "icacam-fw: http: no password file %s: logins refused (docs/network.md)\n",
                         paths.passwordFile.c_str());
        p.auth = std::make_unique<WebAuth>(hash.substr(0, hash.find('\n')));
        p.journal = std::make_unique<JournalTail>(journalFile);
        WebServerSettings s{cfg.httpAddress, cfg.httpPort, "", ""};
        if (!paths.tlsCert.empty()) {
            if (!readFile(paths.tlsCert, &s.tlsCertPem))
                return hal::Error::make(hal::Errc::NotFound, "http.tls_cert: cannot read " + paths.tlsCert);
            if (!readFile(paths.tlsKey, &s.tlsKeyPem))
                return hal::Error::make(hal::Errc::NotFound, "http.tls_key: cannot read " + paths.tlsKey);
        }
        p.api = std::make_unique<WebApi>(WebContext{*p.journal, paths.journalDir, p.inbox, p.lines, p.aim, *p.auth,
                                                    cfg.httpPublicRead == 1, !paths.tlsCert.empty(), &p.recipes});
        p.server = std::make_unique<WebServer>(*p.api);
        if (hal::Error e = p.server->start(s); !e.ok()) return e;
        device.addListener(&p.lines);
        device.addListener(&p.aim);
        device.setInbox(&p.inbox);
        device.setRecipeDesk(&p.recipes);
        std::fprintf(stderr, "icacam-fw: web page on %s://%s:%d/\n", paths.tlsCert.empty() ? "http" : "https",
                     cfg.httpAddress.c_str(), p.server->port());
    }
    return {};
}

int hashPasswordCommand()
{
    std::string password;
    if (!std::getline(std::cin, password) || password.empty()) {
        std::fprintf(stderr, "icacam-fw: --hash-password reads the password from the first line of stdin\n");
        return 64;
    }
    if (!password.empty() && password.back() == '\r') password.pop_back();
    const std::string h = WebAuth::hash(password);
    if (h.empty()) {
        std::fprintf(stderr, "icacam-fw: libsodium could not hash the password\n");
        return 70;
    }
    std::printf("%s\n", h.c_str());
    return 0;
}

} // namespace icacam::fw::net
