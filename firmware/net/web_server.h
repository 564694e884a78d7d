#pragma once
// The HTTP server (libmicrohttpd, its own polling thread) in front of WebApi: bound to
// http.address:http.port, HTTPS when a certificate and key are configured; bodies over
// WebApi::kMaxBody refused with 413 before they are read, requests over the rate refused
// with 429, a connection that sends nothing for kIdleTimeoutS closed (a slowloris client
// holds nothing long), connections limited in number overall and per address. A login is
// checked on a worker of its own (login_queue.h), its connection suspended meanwhile, so
// pages and pictures are served while a password is checked; a login beyond the ones the
// worker holds is answered 503 at once.
#include <cstdint>
#include <memory>
#include <string>

#include "firmware/net/login_queue.h"
#include "firmware/net/rate_limiter.h"
#include "firmware/net/web_api.h"
#include "hal/error.h"

struct MHD_Daemon;

namespace icacam::fw::net {

struct WebServerSettings {
    std::string address = "127.0.0.1";
    int port = 0;
    std::string tlsCertPem, tlsKeyPem; // contents; both "" = plain HTTP
};

class WebServer {
public:
    static constexpr unsigned kIdleTimeoutS = 10;
    static constexpr unsigned kMaxConnections = 64, kMaxPerAddress = 16;
    static constexpr size_t kConnectionMemory = 64 * 1024;

    // checkLogin: how a login request is answered on the worker (empty: api.handle); a test
    // holds it there to see the server go on meanwhile.
    explicit WebServer(WebApi &api, LoginQueue::Check checkLogin = {}) : api_(api), checkLogin_(std::move(checkLogin))
    {}
    ~WebServer();
    hal::Error start(const WebServerSettings &s);
    void stop();
    int port() const { return port_; }

    // For libmicrohttpd's callbacks.
    struct Request;
    int onRequest(void *connection, const char *url, const char *method, const char *upload, size_t *uploadSize,
                  void **state);

private:
    WebApi &api_;
    LoginQueue::Check checkLogin_;
    std::unique_ptr<LoginQueue> logins_;
    RateLimiter rate_{50, 100}; // per address: 50 requests a second, bursts of 100
    MHD_Daemon *daemon_ = nullptr;
    std::string cert_, key_;
    int port_ = 0;
};

} // namespace icacam::fw::net
