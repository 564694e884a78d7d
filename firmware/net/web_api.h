#pragma once
// The JSON API and the page, as a function of the request: what the HTTP server
// (web_server.*) hands in, what it sends back. No sockets here, so the routes are tested and
// fuzzed directly.
//   GET  /                     the page (login, Reading, History)
//   GET  /api/session          {"logged_in","public_read"}
//   POST /api/login            {"password":"..."} -> a session cookie; /api/logout
//   POST /api/command          a serial command as JSON ({"cmd":"trigger"}), queued for the
//                              device: 202 {"tag"}; its answers at GET /api/answer?tag=TAG
//   GET  /api/results?after=ID&limit=N   journal records after ID (oldest first); ?last=N
//                              the newest N
//   GET  /api/result?id=ID     one record;  GET /api/image?id=ID&step=S  its frame as PNG
//   GET  /api/journal.jsonl    the journal;  GET /api/results.csv  the results as CSV
//   GET  /api/aim              aim mode's newest "aim" line; GET /api/aim.png its picture
//   GET  /api/recipe           the version in effect (its keys and values), aim's live controls
//   POST /api/recipe           {"reason":"...","recipe":"ID","KEY":value,...}: a new version,
//                              queued for the device: 202 {"tag"}, answered at /api/answer
//   POST /api/live             {"camera.exposure_us":8000,...}: aim mode's live controls
//   GET  /api/recipe/versions  every version (newest first); /api/recipe/version?recipe=ID&version=N
//   GET  /api/audit            the audit trail, checked: {"intact","problems","entries"}
// Reading needs a session unless http.public_read; commands that change or measure
// (trigger, set, aim, snapshot, scalecheck), recipe saves and live controls always need one.
#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>

namespace icacam::fw {
class RecipeDesk;
}

namespace icacam::fw::net {

class AimExchange;
class CommandInbox;
class JournalTail;
class LineExchange;
class WebAuth;

struct HttpRequest {
    std::string_view method, path, query, body;
    std::string_view contentType;
    std::string_view session; // the session cookie's value
    int64_t nowMs = 0;
};

struct HttpResponse {
    int status = 200;
    std::string contentType = "application/json";
    std::string body;
    std::string setCookie;
};

struct WebContext {
    JournalTail &journal;
    std::string journalDir; // the frames are read from here
    CommandInbox &inbox;
    LineExchange &lines;
    AimExchange &aim;
    WebAuth &auth;
    bool publicRead = false;
    bool secureCookie = false;     // served over TLS
    RecipeDesk *recipes = nullptr; // the device's recipe (nullptr: the recipe routes answer 503)
};

class WebApi {
public:
    static constexpr size_t kMaxBody = 16 * 1024;
    static constexpr const char *kCookie = "icacam_session";

    explicit WebApi(WebContext ctx) : c_(std::move(ctx)) {}
    HttpResponse handle(const HttpRequest &r);

private:
    HttpResponse login(const HttpRequest &r);
    HttpResponse command(const HttpRequest &r, bool loggedIn);
    HttpResponse results(const HttpRequest &r);
    HttpResponse result(const HttpRequest &r);
    HttpResponse image(const HttpRequest &r);
    HttpResponse csv();
    // Recipes (web_recipe.cpp).
    HttpResponse recipe();
    HttpResponse postRecipe(const HttpRequest &r, std::string_view user, bool live);
    HttpResponse versions(const HttpRequest &r, bool one);
    HttpResponse audit();
    std::string nextTag();

    WebContext c_;
    std::atomic<long> nextTag_{1};
};

// {"type":"error","code","message"} with an HTTP status; a JSON body.
HttpResponse error(int status, const char *code, std::string_view message);
HttpResponse json(std::string body, int status = 200);
// The value of key in a query string ("a=1&b=2"); false when absent.
bool queryValue(std::string_view query, std::string_view key, std::string_view *value);
// A whole number in [lo, hi]; false otherwise.
bool parseWhole(std::string_view text, long lo, long hi, long *out);

} // namespace icacam::fw::net
