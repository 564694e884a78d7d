#include "firmware/net/web_server.h"

#include <arpa/inet.h>
#include <microhttpd.h>
#include <netinet/in.h>

#include <chrono>
#include <cstring>

namespace icacam::fw::net {

namespace {

int64_t nowMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// The page and the API are the device's own: nothing from elsewhere is loaded or framed.
constexpr const char *kPolicy = "default-src 'self'; script-src 'self' 'unsafe-inline'; style-src 'self' "
                                "'unsafe-inline'; img-src 'self' data:; frame-ancestors 'none'";

uint64_t addressKey(MHD_Connection *c)
{
    const MHD_ConnectionInfo *info = MHD_get_connection_info(c, MHD_CONNECTION_INFO_CLIENT_ADDRESS);
    if (!info || !info->client_addr) return 0;
    const sockaddr *sa = info->client_addr;
    uint64_t key = 0;
    if (sa->sa_family == AF_INET) {
        std::memcpy(&key, &reinterpret_cast<const sockaddr_in *>(sa)->sin_addr, 4);
    } else if (sa->sa_family == AF_INET6) {
        const auto *a6 = reinterpret_cast<const sockaddr_in6 *>(sa);
        std::memcpy(&key, &a6->sin6_addr, 8); // the network's half: one bucket per /64
    }
    return key;
}

MHD_Result send(MHD_Connection *c, const HttpResponse &r, bool head)
{
    MHD_Response *resp = MHD_create_response_from_buffer(head ? 0 : r.body.size(), const_cast<char *>(r.body.data()),
                                                         MHD_RESPMEM_MUST_COPY);
    if (!resp) return MHD_NO;
    MHD_add_response_header(resp, MHD_HTTP_HEADER_CONTENT_TYPE, r.contentType.c_str());
    MHD_add_response_header(resp, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    MHD_add_response_header(resp, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(resp, "Content-Security-Policy", kPolicy);
    if (!r.setCookie.empty()) MHD_add_response_header(resp, MHD_HTTP_HEADER_SET_COOKIE, r.setCookie.c_str());
    const MHD_Result ok = MHD_queue_response(c, unsigned(r.status), resp);
    MHD_destroy_response(resp);
    return ok;
}

HttpResponse refusal(int status, const char *code, const char *message)
{
    HttpResponse r;
    r.status = status;
    r.body = std::string("{\"type\":\"error\",\"code\":\"") + code + "\",\"message\":\"" + message + "\"}\n";
    return r;
}

} // namespace

struct WebServer::Request {
    std::string body;
    bool refused = false;
    bool posted = false; // a login handed to the worker: answered when the connection resumes
    LoginJob login;
};

WebServer::~WebServer()
{
    stop();
}

void WebServer::stop()
{
    // Every suspended login resumed first (a daemon stops with none suspended), and any login
    // posted from now on refused; the queue itself outlives the daemon's thread, which may be
    // posting to it until MHD_stop_daemon returns.
    if (logins_) logins_->stop();
    if (daemon_) MHD_stop_daemon(daemon_);
    daemon_ = nullptr;
    logins_.reset();
}

int WebServer::onRequest(void *connection, const char *url, const char *method, const char *upload, size_t *uploadSize,
                         void **state)
{
    auto *c = static_cast<MHD_Connection *>(connection);
    auto *req = static_cast<Request *>(*state);
    if (!req) { // the headers are in: decide before any body is read
        req = new Request;
        *state = req;
        if (!rate_.allow(addressKey(c), nowMs())) {
            req->refused = true;
            return send(c, refusal(429, "rate", "too many requests: slow down"), false);
        }
        if (const char *len = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_CONTENT_LENGTH)) {
            char *end = nullptr;
            const unsigned long long n = std::strtoull(len, &end, 10);
            if (end == len || *end != 0 || n > WebApi::kMaxBody) {
                req->refused = true;
                return send(c, refusal(413, "too_large", "request bodies are limited to 16 KiB"), false);
            }
            req->body.reserve(size_t(n));
        }
        return MHD_YES;
    }
    if (req->refused) { // the rest of a refused body is read and dropped
        *uploadSize = 0;
        return MHD_YES;
    }
    if (*uploadSize > 0) {
        if (req->body.size() + *uploadSize > WebApi::kMaxBody) {
            req->refused = true;
            *uploadSize = 0;
            return send(c, refusal(413, "too_large", "request bodies are limited to 16 KiB"), false);
        }
        req->body.append(upload, *uploadSize);
        *uploadSize = 0;
        return MHD_YES;
    }
    if (req->posted) { // resumed: the worker's answer, or none (too many logins waiting, or stopping)
        if (req->login.answered) return send(c, req->login.answer, false);
        return send(c, refusal(503, "busy", "logins are being checked: try again in a moment"), false);
    }
    std::string_view path(url), query;
    // libmicrohttpd hands the path without its query; the arguments are read back as one string.
    std::string q;
    MHD_get_connection_values(
        c, MHD_GET_ARGUMENT_KIND,
        [](void *cls, MHD_ValueKind, const char *key, const char *value) -> MHD_Result {
            auto *out = static_cast<std::string *>(cls);
            if (out->size() > 2048) return MHD_NO;
            (*out += out->empty() ? "" : "&") += key;
            if (value) (*out += '=') += value;
            return MHD_YES;
        },
        &q);
    query = q;
    HttpRequest r;
    r.method = method;
    r.path = path;
    r.query = query;
    r.body = req->body;
    const char *type = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_CONTENT_TYPE);
    r.contentType = type ? type : "";
    const char *cookie = MHD_lookup_connection_value(c, MHD_COOKIE_KIND, WebApi::kCookie);
    r.session = cookie ? cookie : "";
    r.nowMs = nowMs();
    if (r.method == "POST" && r.path == "/api/login" && logins_) {
        LoginJob &j = req->login;
        j.method = r.method;
        j.path = r.path;
        j.query = r.query;
        j.body = std::move(req->body);
        j.contentType = r.contentType;
        j.session = r.session;
        j.nowMs = r.nowMs;
        j.connection = c;
        req->posted = true;
        // Suspended before it is posted: the worker's resume never comes first.
        MHD_suspend_connection(c);
        if (!logins_->post(&j)) MHD_resume_connection(c); // answered 503 when it resumes
        return MHD_YES;
    }
    return send(c, api_.handle(r), r.method == "HEAD");
}

hal::Error WebServer::start(const WebServerSettings &s)
{
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(uint16_t(s.port));
    if (inet_pton(AF_INET, s.address.c_str(), &addr.sin_addr) != 1)
        return hal::Error::make(hal::Errc::Invalid, "http.address: not an IPv4 address: " + s.address);
    unsigned flags = MHD_USE_AUTO_INTERNAL_THREAD | MHD_USE_ERROR_LOG | MHD_ALLOW_SUSPEND_RESUME;
    cert_ = s.tlsCertPem;
    key_ = s.tlsKeyPem;
    const bool tls = !cert_.empty();
    if (tls) {
        if (MHD_is_feature_supported(MHD_FEATURE_TLS) != MHD_YES)
            return hal::Error::make(hal::Errc::Invalid, "this libmicrohttpd has no TLS");
        flags |= MHD_USE_TLS;
    }
    auto access = [](void *cls, MHD_Connection *c, const char *url, const char *method, const char *,
                     const char *upload, size_t *uploadSize, void **state) -> MHD_Result {
        return static_cast<WebServer *>(cls)->onRequest(c, url, method, upload, uploadSize, state) ? MHD_YES : MHD_NO;
    };
    auto completed = [](void *, MHD_Connection *, void **state, MHD_RequestTerminationCode) {
        delete static_cast<Request *>(*state);
        *state = nullptr;
    };
    MHD_OptionItem opts[] = {
        {MHD_OPTION_SOCK_ADDR, 0, &addr},
        {MHD_OPTION_CONNECTION_LIMIT, kMaxConnections, nullptr},
        {MHD_OPTION_PER_IP_CONNECTION_LIMIT, kMaxPerAddress, nullptr},
        {MHD_OPTION_CONNECTION_TIMEOUT, kIdleTimeoutS, nullptr},
        {MHD_OPTION_CONNECTION_MEMORY_LIMIT, kConnectionMemory, nullptr},
        {MHD_OPTION_NOTIFY_COMPLETED, intptr_t(static_cast<MHD_RequestCompletedCallback>(completed)), nullptr},
        {tls ? MHD_OPTION_HTTPS_MEM_CERT : MHD_OPTION_END, 0, const_cast<char *>(cert_.c_str())},
        {tls ? MHD_OPTION_HTTPS_MEM_KEY : MHD_OPTION_END, 0, const_cast<char *>(key_.c_str())},
        {MHD_OPTION_END, 0, nullptr},
    };
    logins_ = std::make_unique<LoginQueue>(
        checkLogin_ ? checkLogin_ : LoginQueue::Check([this](const HttpRequest &r) { return api_.handle(r); }),
        [](LoginJob *j) { MHD_resume_connection(static_cast<MHD_Connection *>(j->connection)); });
    daemon_ =
        MHD_start_daemon(flags, uint16_t(s.port), nullptr, nullptr, static_cast<MHD_AccessHandlerCallback>(access),
                         this, MHD_OPTION_ARRAY, opts, MHD_OPTION_END);
    if (!daemon_) {
        logins_.reset();
        return hal::Error::make(hal::Errc::Io, "cannot listen on " + s.address + ":" + std::to_string(s.port) +
                                                   (tls ? " (HTTPS: check the certificate and key)" : ""));
    }
    if (const MHD_DaemonInfo *info = MHD_get_daemon_info(daemon_, MHD_DAEMON_INFO_BIND_PORT)) port_ = info->port;
    return {};
}

} // namespace icacam::fw::net
