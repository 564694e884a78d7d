// The recipe's routes: the version in effect (from the device, through the RecipeDesk), its
// versions and the audit trail (read from the journal folder's audit.jsonl and checked on
// every request), and saves and aim's live controls, queued for the device and answered by
// it at /api/answer like commands.
#include <cstdint>

#include "firmware/audit_log.h"
#include "firmware/net/web_api.h"
#include "firmware/recipe.h"
#include "firmware/recipe_desk.h"
#include "hal/file/folder_storage.h"
#include "reading/record_line.h"

namespace icacam::fw::net {

namespace {

constexpr size_t kMaxReason = 200;

// The `key = value` lines of a canonical text as a JSON object of strings.
std::string keysObject(std::string_view text)
{
    std::string out;
    reading::JsonBuilder j(&out);
    while (!text.empty()) {
        const size_t nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        if (const size_t eq = line.find(" = "); eq != std::string_view::npos)
            j.str(line.substr(0, eq), line.substr(eq + 3));
    }
    j.end();
    out.pop_back();
    return out;
}

void appendEntry(reading::JsonBuilder &j, const AuditEntry &e, bool chain)
{
    if (chain) j.integer("seq", e.seq);
    j.str("recipe", e.recipe).integer("version", e.version).str("hash", e.hash);
    j.str("time", e.time).str("who", e.who).str("why", e.why).str("changes", e.changes);
    if (chain) j.str("prev", e.prev).str("entry", e.entry);
}

bool printable(std::string_view v)
{
    for (char ch : v)
        if (uint8_t(ch) < 0x20) return false;
    return true;
}

} // namespace

HttpResponse WebApi::recipe()
{
    if (!c_.recipes) return error(503, "no_recipes", "this server has no device recipe");
    std::string live;
    const RecipeVersion v = c_.recipes->inEffect(&live);
    std::string body;
    reading::JsonBuilder j(&body);
    j.str("type", "recipe").str("recipe", v.id).integer("version", v.version).str("hash", v.hash);
    j.str("live", live).raw("keys", keysObject(v.text));
    j.end();
    return json(std::move(body));
}

HttpResponse WebApi::postRecipe(const HttpRequest &r, std::string_view user, bool live)
{
    if (!c_.recipes) return error(503, "no_recipes", "this server has no device recipe");
    if (r.contentType.substr(0, 16) != "application/json") return error(415, "content_type", "send application/json");
    reading::FlatObject obj;
    if (std::string e = reading::parseFlatObject(r.body, &obj); !e.empty()) return error(400, "malformed", e);
    RecipeDesk::Request q;
    q.kind = live ? RecipeDesk::Request::Kind::Live : RecipeDesk::Request::Kind::Save;
    q.who = user.empty() ? "web" : std::string(user) + " (web)";
    for (int i = 0; i < obj.count; ++i) {
        const reading::JsonField &f = obj.fields[i];
        const bool text = f.type == reading::JsonField::Type::String;
        if (!text && f.type != reading::JsonField::Type::Number)
            return error(400, "bad_argument", f.key.substr(0, 64) + ": a string or a number");
        if (!printable(f.text)) return error(400, "bad_argument", f.key.substr(0, 64) + ": no control characters");
        if (!live && f.key == "reason" && text) {
            if (f.text.size() > kMaxReason) return error(400, "bad_argument", "reason: at most 200 characters");
            q.why = f.text;
        } else if (!live && f.key == "recipe" && text) {
            if (!validRecipeId(f.text))
                return error(400, "bad_argument", "recipe: 1-32 letters, digits, '-', '_' or '.'");
            q.id = f.text;
        } else if (isRecipeKey(f.key) && (!live || f.key.rfind("camera.", 0) == 0)) {
            ((q.text += f.key) += " = ") += f.text;
            q.text += '\n';
        } else {
            return error(400, "bad_argument",
                         "'" + f.key.substr(0, 64) +
                             (live ? "' is not a camera key of the recipe" : "' is not a recipe key"));
        }
    }
    if (!live && q.why.empty()) return error(400, "no_reason", "a reason is required: {\"reason\":\"...\"}");
    q.tag = nextTag();
    const std::string tag = q.tag;
    if (!c_.recipes->post(std::move(q))) return error(503, "busy", "a recipe change is waiting: try again");
    std::string body;
    reading::JsonBuilder a(&body);
    a.str("type", "queued").str("tag", tag);
    a.end();
    return json(std::move(body), 202);
}

HttpResponse WebApi::versions(const HttpRequest &r, bool one)
{
    hal::FolderStorage dir;
    if (hal::Error e = dir.open(c_.journalDir, 0); !e.ok()) return error(500, "journal", e.message);
    // The head before the trail: an entry written in between leaves the head behind, not ahead.
    hal::Result<std::string> head = dir.read(kAuditHead), log = dir.read(kAuditFile);
    std::vector<AuditEntry> entries;
    checkAudit(log.ok() ? std::string_view(log.value) : std::string_view(),
               head.ok() ? std::string_view(head.value) : std::string_view(), &entries);
    if (one) {
        std::string_view id, v;
        long version = 0;
        if (!queryValue(r.query, "recipe", &id) || !queryValue(r.query, "version", &v) ||
            !parseWhole(v, 1, 1L << 40, &version))
            return error(400, "bad_argument", "recipe=ID&version=N");
        for (const AuditEntry &e : entries)
            if (e.recipe == id && e.version == version) {
                std::string body;
                reading::JsonBuilder j(&body);
                j.str("type", "recipe_version");
                appendEntry(j, e, false);
                j.raw("keys", keysObject(e.settings));
                j.end();
                return json(std::move(body));
            }
        return error(404, "not_found", "no such version (or its entry fails the audit check)");
    }
    std::string body = "[";
    for (auto e = entries.rbegin(); e != entries.rend(); ++e) {
        if (body.size() > 1) body += ",\n";
        reading::JsonBuilder j(&body);
        appendEntry(j, *e, false);
        j.end();
        body.pop_back();
    }
    body += "]\n";
    return json(std::move(body));
}

HttpResponse WebApi::audit()
{
    hal::FolderStorage dir;
    if (hal::Error e = dir.open(c_.journalDir, 0); !e.ok()) return error(500, "journal", e.message);
    hal::Result<std::string> head = dir.read(kAuditHead), log = dir.read(kAuditFile);
    std::vector<AuditEntry> entries;
    AuditCheck c = checkAudit(log.ok() ? std::string_view(log.value) : std::string_view(),
                              head.ok() ? std::string_view(head.value) : std::string_view(), &entries);
    if (!log.ok() && head.ok()) c.problems.push_back(std::string(kAuditFile) + " is missing but its head is there");
    std::string body;
    reading::JsonBuilder j(&body);
    j.str("type", "audit").boolean("intact", c.ok()).integer("entries", c.entries);
    std::string problems = "[", trail = "[";
    for (const std::string &p : c.problems) {
        if (problems.size() > 1) problems += ',';
        reading::JsonBuilder::escape(&problems, p); // quoted
    }
    for (auto e = entries.rbegin(); e != entries.rend(); ++e) {
        if (trail.size() > 1) trail += ",\n";
        reading::JsonBuilder t(&trail);
        appendEntry(t, *e, true);
        t.end();
        trail.pop_back();
    }
    j.raw("problems", problems + "]").raw("trail", trail + "]");
    j.end();
    return json(std::move(body));
}

} // namespace icacam::fw::net
