#include "firmware/net/web_api.h"

#include <charconv>
#include <cstdio>

#include "firmware/command.h"
#include "firmware/net/aim_exchange.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/journal_tail.h"
#include "firmware/net/line_exchange.h"
#include "firmware/net/pgm_png.h"
#include "firmware/net/web_auth.h"
#include "firmware/net/web_page.h"
#include "hal/file/folder_storage.h"
#include "reading/record_line.h"

namespace icacam::fw::net {

HttpResponse error(int status, const char *code, std::string_view message)
{
    HttpResponse r;
    r.status = status;
    reading::JsonBuilder j(&r.body);
    j.str("type", "error").str("code", code).str("message", message);
    j.end();
    return r;
}

HttpResponse json(std::string body, int status)
{
    HttpResponse r;
    r.status = status;
    r.body = std::move(body);
    return r;
}

namespace {

// Commands that measure or change the device: never without a login.
bool changes(CommandKind k)
{
    return k == CommandKind::Trigger || k == CommandKind::Set || k == CommandKind::Aim || k == CommandKind::Snapshot ||
           k == CommandKind::ScaleCheck;
}

bool isJson(std::string_view contentType)
{
    return contentType.substr(0, 16) == "application/json";
}

void csvField(std::string *out, std::string_view v)
{
    if (v.find_first_of(",\"\n") == std::string_view::npos) {
        out->append(v);
        return;
    }
    out->push_back('"');
    for (char ch : v) {
        if (ch == '"') out->push_back('"');
        out->push_back(ch);
    }
    out->push_back('"');
}

} // namespace

bool queryValue(std::string_view query, std::string_view key, std::string_view *value)
{
    while (!query.empty()) {
        const size_t amp = query.find('&');
        const std::string_view pair = query.substr(0, amp);
        query.remove_prefix(amp == std::string_view::npos ? query.size() : amp + 1);
        const size_t eq = pair.find('=');
        if (pair.substr(0, eq) == key) {
            *value = eq == std::string_view::npos ? std::string_view() : pair.substr(eq + 1);
            return true;
        }
    }
    return false;
}

bool parseWhole(std::string_view text, long lo, long hi, long *out)
{
    long v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi) return false;
    *out = v;
    return true;
}

HttpResponse WebApi::handle(const HttpRequest &r)
{
    if (r.path.find("..") != std::string_view::npos || r.path.find('\\') != std::string_view::npos)
        return error(400, "bad_path", "paths with .. or \\ are refused");
    if (r.body.size() > kMaxBody) return error(413, "too_large", "request bodies are limited to 16 KiB");
    const bool get = r.method == "GET" || r.method == "HEAD", post = r.method == "POST";
    if (!get && !post) return error(405, "method", "GET or POST only");
    if (get && (r.path == "/" || r.path == "/index.html")) {
        HttpResponse page;
        page.contentType = "text/html; charset=utf-8";
        page.body = kWebPage;
        return page;
    }
    std::string user;
    const bool loggedIn = c_.auth.valid(r.session, r.nowMs, &user);
    if (r.path == "/api/session" && get) {
        std::string body;
        reading::JsonBuilder j(&body);
        j.boolean("logged_in", loggedIn).boolean("public_read", c_.publicRead);
        j.end();
        return json(std::move(body));
    }
    if (r.path == "/api/login") return post ? login(r) : error(405, "method", "POST only");
    if (r.path == "/api/logout" && post) {
        c_.auth.logout(r.session);
        HttpResponse out = json("{\"type\":\"logout\"}\n");
        out.setCookie = std::string(kCookie) + "=; Path=/; Max-Age=0; HttpOnly; SameSite=Strict";
        return out;
    }
    if (!loggedIn && !c_.publicRead) return error(401, "login", "log in first");
    if (r.path == "/api/command") return post ? command(r, loggedIn) : error(405, "method", "POST only");
    if (post && (r.path == "/api/recipe" || r.path == "/api/live")) {
        if (!loggedIn) return error(401, "login", "log in to change the recipe");
        return postRecipe(r, user, r.path == "/api/live");
    }
    if (!get) return error(405, "method", "GET only");
    if (r.path == "/api/recipe") return recipe();
    if (r.path == "/api/recipe/versions") return versions(r, false);
    if (r.path == "/api/recipe/version") return versions(r, true);
    if (r.path == "/api/audit") return audit();
    if (r.path == "/api/answer") {
        std::string_view tag;
        if (!queryValue(r.query, "tag", &tag) || tag.size() > 32) return error(400, "bad_argument", "tag=TAG");
        std::string body = "[";
        for (const std::string &line : c_.lines.answers(tag)) (body += body.size() > 1 ? "," : "") += line;
        body += "]\n";
        return json(std::move(body));
    }
    if (r.path == "/api/results") return results(r);
    if (r.path == "/api/result") return result(r);
    if (r.path == "/api/image") return image(r);
    if (r.path == "/api/journal.jsonl") {
        if (std::string e = c_.journal.refresh(); !e.empty()) return error(500, "journal", e);
        HttpResponse out;
        out.contentType = "application/x-ndjson";
        out.body = c_.journal.all();
        return out;
    }
    if (r.path == "/api/results.csv") return csv();
    if (r.path == "/api/aim") {
        const std::string line = c_.lines.newestOfType("aim");
        return line.empty() ? error(404, "no_aim", "not aiming: POST /api/command {\"cmd\":\"aim\"}")
                            : json(line + "\n");
    }
    if (r.path == "/api/aim.png") {
        HttpResponse out;
        long picture = 0;
        int step = 1;
        if (std::string e = c_.aim.png(&out.body, &picture, &step); !e.empty()) return error(500, "image", e);
        if (picture == 0) return error(404, "no_aim", "no aim picture yet");
        out.contentType = "image/png";
        return out;
    }
    return error(404, "not_found", "no such page");
}

HttpResponse WebApi::login(const HttpRequest &r)
{
    if (!isJson(r.contentType)) return error(415, "content_type", "send application/json");
    reading::FlatObject obj;
    if (std::string e = reading::parseFlatObject(r.body, &obj); !e.empty()) return error(400, "malformed", e);
    const reading::JsonField *pw = obj.find("password");
    if (!pw || pw->type != reading::JsonField::Type::String)
        return error(400, "bad_argument", "{\"password\":\"...\"}");
    // Who is logging in, for the audit trail: a name, as the person gives it.
    std::string_view user;
    if (const reading::JsonField *u = obj.find("user"); u && u->type == reading::JsonField::Type::String) {
        user = u->text;
        if (user.size() > WebAuth::kMaxUser) return error(400, "bad_argument", "user: at most 32 characters");
        for (char ch : user)
            if (uint8_t(ch) < 0x20 || ch == '"' || ch == '\\')
                return error(400, "bad_argument", "user: no control characters, quotes or backslashes");
    }
    std::string token;
    switch (c_.auth.login(pw->text, r.nowMs, &token, user)) {
    case WebAuth::Login::Ok: break;
    case WebAuth::Login::Wrong: return error(401, "wrong_password", "wrong password");
    case WebAuth::Login::HeldOff: return error(429, "held_off", "a wrong password holds logins off for a second");
    case WebAuth::Login::NoPassword:
        return error(403, "no_password", "no password is set: run icacam-fw --hash-password (docs/network.md)");
    }
    HttpResponse out = json("{\"type\":\"login\"}\n");
    out.setCookie = std::string(kCookie) + "=" + token + "; Path=/; HttpOnly; SameSite=Strict" +
                    (c_.secureCookie ? "; Secure" : "");
    return out;
}

HttpResponse WebApi::command(const HttpRequest &r, bool loggedIn)
{
    // JSON only: a cross-site form cannot send it without the browser asking first.
    if (!isJson(r.contentType)) return error(415, "content_type", "send application/json");
    if (r.body.empty() || r.body.front() != '{') return error(400, "malformed", "one JSON object, as on serial");
    const CommandParse p = parseCommand(r.body);
    if (!p.ok) return error(400, p.code, p.message);
    if (p.cmd.kind == CommandKind::Results) return error(400, "bad_argument", "results: GET /api/results");
    if (changes(p.cmd.kind) && !loggedIn) return error(401, "login", "log in to measure or change settings");
    // The same line as on serial, its id replaced by a tag the answers are found by.
    reading::FlatObject obj;
    if (std::string e = reading::parseFlatObject(r.body, &obj); !e.empty()) return error(400, "malformed", e);
    const std::string tag = nextTag();
    std::string line;
    reading::JsonBuilder j(&line);
    for (int i = 0; i < obj.count; ++i) {
        const reading::JsonField &f = obj.fields[i];
        if (f.key == "id") continue;
        switch (f.type) {
        case reading::JsonField::Type::String: j.str(f.key, f.text); break;
        case reading::JsonField::Type::Number: j.raw(f.key, f.text); break;
        case reading::JsonField::Type::Bool: j.boolean(f.key, f.boolean); break;
        case reading::JsonField::Type::Null: j.raw(f.key, "null"); break;
        }
    }
    j.str("id", tag);
    j.end();
    line.pop_back(); // the '\n'
    if (!c_.inbox.push(line)) return error(503, "busy", "the device has commands waiting: try again");
    std::string body;
    reading::JsonBuilder a(&body);
    a.str("type", "queued").str("tag", tag);
    a.end();
    return json(std::move(body), 202);
}

std::string WebApi::nextTag()
{
    char tag[32];
    std::snprintf(tag, sizeof tag, "web-%ld", nextTag_.fetch_add(1));
    return tag;
}

HttpResponse WebApi::results(const HttpRequest &r)
{
    long after = 0, limit = 100;
    std::string_view v;
    if (queryValue(r.query, "after", &v) && !parseWhole(v, 0, 1L << 40, &after))
        return error(400, "bad_argument", "after=ID (a whole number)");
    if (queryValue(r.query, "limit", &v) && !parseWhole(v, 1, 1000, &limit))
        return error(400, "bad_argument", "limit=N (1-1000)");
    long last = 0;
    if (queryValue(r.query, "last", &v) && !parseWhole(v, 1, 1000, &last))
        return error(400, "bad_argument", "last=N (1-1000)");
    if (std::string e = c_.journal.refresh(); !e.empty()) return error(500, "journal", e);
    std::string body = "[";
    for (const std::string &line : last > 0 ? c_.journal.last(size_t(last)) : c_.journal.after(after, size_t(limit)))
        (body += body.size() > 1 ? ",\n" : "") += line;
    body += "]\n";
    return json(std::move(body));
}

HttpResponse WebApi::result(const HttpRequest &r)
{
    long id = 0;
    std::string_view v;
    if (!queryValue(r.query, "id", &v) || !parseWhole(v, 1, 1L << 40, &id))
        return error(400, "bad_argument", "id=ID (a whole number)");
    if (std::string e = c_.journal.refresh(); !e.empty()) return error(500, "journal", e);
    std::string line;
    if (!c_.journal.line(id, &line)) return error(404, "not_found", "no record with that id");
    return json(line + "\n");
}

HttpResponse WebApi::image(const HttpRequest &r)
{
    long id = 0, step = 2;
    std::string_view v;
    if (!queryValue(r.query, "id", &v) || !parseWhole(v, 1, 1L << 40, &id))
        return error(400, "bad_argument", "id=ID (a whole number)");
    if (queryValue(r.query, "step", &v) && !parseWhole(v, 1, 8, &step)) return error(400, "bad_argument", "step=1-8");
    if (std::string e = c_.journal.refresh(); !e.empty()) return error(500, "journal", e);
    std::string line;
    if (!c_.journal.line(id, &line)) return error(404, "not_found", "no record with that id");
    reading::FlatObject obj;
    reading::parseFlatObject(line, &obj);
    const reading::JsonField *name = obj.find("image");
    // The record names its frame; only a plain name of the device's own pattern is opened.
    if (!name || name->text.empty()) return error(404, "no_image", "this record has no frame");
    if (name->text.find('/') != std::string::npos || name->text.rfind("img-", 0) != 0)
        return error(404, "no_image", "not a frame of the journal");
    hal::FolderStorage dir;
    if (hal::Error e = dir.open(c_.journalDir, 0); !e.ok()) return error(500, "journal", e.message);
    hal::Result<std::string> bytes = dir.read(name->text);
    if (!bytes.ok()) return error(404, "no_image", bytes.error.message);
    PgmView pgm;
    if (std::string e = parsePgm(bytes.value, &pgm); !e.empty()) return error(500, "image", e);
    HttpResponse out;
    out.contentType = "image/png";
    if (std::string e = pgmToPng(pgm, int(step), &out.body); !e.empty()) return error(500, "image", e);
    return out;
}

HttpResponse WebApi::csv()
{
    if (std::string e = c_.journal.refresh(); !e.empty()) return error(500, "journal", e);
    static const char *const kColumns[] = {"id",           "time",  "material", "status", "mu",    "mu_sigma",
                                           "tolerance_mu", "flags", "message",  "model",  "image", "trigger"};
    HttpResponse out;
    out.contentType = "text/csv; charset=utf-8";
    for (const char *c : kColumns) (out.body += out.body.empty() ? "" : ",") += c;
    out.body += '\n';
    reading::FlatObject obj;
    for (const std::string &line : c_.journal.after(0, size_t(1) << 30)) {
        if (line.rfind("{\"type\":\"result\"", 0) != 0 || !reading::parseFlatObject(line, &obj).empty()) continue;
        bool first = true;
        for (const char *c : kColumns) {
            if (!first) out.body += ',';
            first = false;
            if (const reading::JsonField *f = obj.find(c); f && f->type != reading::JsonField::Type::Null)
                csvField(&out.body, f->text);
        }
        out.body += '\n';
    }
    return out;
}

} // namespace icacam::fw::net
