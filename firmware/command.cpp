#include "firmware/command.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace icacam::fw {

namespace {

CommandParse fail(const char *code, std::string msg)
{
    CommandParse p;
    p.code = code;
    p.message = std::move(msg);
    return p;
}

bool kindOf(std::string_view name, CommandKind *k)
{
    static const struct {
        const char *name;
        CommandKind kind;
    } kNames[] = {
        {"help", CommandKind::Help},
        {"status", CommandKind::Status},
        {"trigger", CommandKind::Trigger},
        {"get", CommandKind::Get},
        {"set", CommandKind::Set},
        {"results", CommandKind::Results},
        {"scalecheck", CommandKind::ScaleCheck},
        {"aim", CommandKind::Aim},
        {"snapshot", CommandKind::Snapshot},
    };
    for (const auto &n : kNames)
        if (name == n.name) {
            *k = n.kind;
            return true;
        }
    return false;
}

std::string printable(std::string_view s)
{
    std::string out;
    for (char c : s.substr(0, 40)) out.push_back(uint8_t(c) >= 0x20 && uint8_t(c) < 0x7F ? c : '?');
    return out;
}

bool parseCount(double v, int *count)
{
    if (!(v >= 1 && v <= kMaxResultsAsked) || v != std::floor(v)) return false;
    *count = int(v);
    return true;
}

// One number of a scale check, within its range; "" or the refusal.
std::string scaleNumber(const char *name, double v, double lo, double hi, double *out)
{
    if (!(v >= lo && v <= hi)) {
        char b[96];
        std::snprintf(b, sizeof b, "scalecheck: %s must be between %g and %g", name, lo, hi);
        return b;
    }
    *out = v;
    return "";
}

bool wordNumber(std::string_view w, double *v)
{
    if (w.empty() || w.size() > 24) return false;
    const std::string s(w);
    char *end = nullptr;
    *v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(*v);
}

constexpr const char *kScaleUsage = "usage: scalecheck DIAMETER_MM [TOLERANCE_PCT [THICKNESS_MM]]";

// {"cmd":"set","key":"n","value":0.2,"id":"x"}: the command's fields by name.
CommandParse parseJsonCommand(std::string_view line)
{
    CommandParse p;
    reading::FlatObject obj;
    if (std::string err = reading::parseFlatObject(line, &obj); !err.empty())
        return fail("malformed", "bad JSON: " + err);
    const reading::JsonField *cmd = obj.find("cmd");
    if (!cmd || cmd->type != reading::JsonField::Type::String) return fail("malformed", "missing \"cmd\" string");
    if (const reading::JsonField *id = obj.find("id"))
        p.cmd.tag = id->text.substr(0, 64); // a string's text or a number's literal
    if (!kindOf(cmd->text, &p.cmd.kind))
        return fail("unknown_command", "unknown command '" + printable(cmd->text) + "' (try help)");
    if (const reading::JsonField *k = obj.find("key")) {
        if (k->type != reading::JsonField::Type::String) return fail("bad_argument", "\"key\" must be a string");
        p.cmd.key = k->text;
    }
    if (const reading::JsonField *v = obj.find("value")) {
        if (v->type != reading::JsonField::Type::String && v->type != reading::JsonField::Type::Number)
            return fail("bad_argument", "\"value\" must be a number or a string");
        p.cmd.value = v->text;
    } else if (p.cmd.kind == CommandKind::Set) {
        return fail("bad_argument", "set needs \"key\" and \"value\"");
    }
    if (const reading::JsonField *n = obj.find("n")) {
        if (n->type != reading::JsonField::Type::Number || !parseCount(n->number, &p.cmd.count))
            return fail("bad_argument", "\"n\" must be a whole number from 1 to 1000");
    }
    if (p.cmd.kind == CommandKind::Set && p.cmd.key.empty()) return fail("bad_argument", "set needs \"key\"");
    if (p.cmd.kind == CommandKind::Aim) {
        if (const reading::JsonField *sec = obj.find("seconds")) {
            if (sec->type != reading::JsonField::Type::Number || !(sec->number >= 0 && sec->number <= kMaxAimSeconds) ||
                sec->number != std::floor(sec->number))
                return fail("bad_argument", "\"seconds\" must be a whole number from 0 (off) to 600");
            p.cmd.aimSeconds = int(sec->number);
        }
    }
    if (p.cmd.kind == CommandKind::ScaleCheck) {
        const struct {
            const char *key;
            double lo, hi;
            double *dst;
            bool required;
        } fields[] = {
            {"diameter_mm", 1, 300, &p.cmd.diameterMm, true},
            {"tolerance_pct", 0.01, 20, &p.cmd.tolerancePct, false},
            {"thickness_mm", 0, 50, &p.cmd.thicknessMm, false},
        };
        for (const auto &f : fields) {
            const reading::JsonField *v = obj.find(f.key);
            if (!v) {
                if (f.required) return fail("bad_argument", "scalecheck needs \"diameter_mm\"");
                continue;
            }
            if (v->type != reading::JsonField::Type::Number)
                return fail("bad_argument", std::string("\"") + f.key + "\" must be a number");
            if (std::string e = scaleNumber(f.key, v->number, f.lo, f.hi, f.dst); !e.empty())
                return fail("bad_argument", e);
        }
    }
    p.ok = true;
    return p;
}

// Words, as typed at a terminal: cmd [arg [arg]] (scalecheck takes three).
CommandParse parseWordCommand(std::string_view line)
{
    CommandParse p;
    std::string_view words[4];
    int nw = 0;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && line[i] == ' ') ++i;
        if (i >= line.size()) break;
        if (nw == 4) return fail("bad_argument", "too many words");
        const size_t b = i;
        while (i < line.size() && line[i] != ' ') ++i;
        words[nw++] = line.substr(b, i - b);
    }
    if (!kindOf(words[0], &p.cmd.kind))
        return fail("unknown_command", "unknown command '" + printable(words[0]) + "' (try help)");
    if (nw == 4 && p.cmd.kind != CommandKind::ScaleCheck) return fail("bad_argument", "too many words");
    if (p.cmd.kind == CommandKind::ScaleCheck) {
        if (nw < 2) return fail("bad_argument", kScaleUsage);
        const char *names[] = {"DIAMETER_MM", "TOLERANCE_PCT", "THICKNESS_MM"};
        const double lo[] = {1, 0.01, 0}, hi[] = {300, 20, 50};
        double *dst[] = {&p.cmd.diameterMm, &p.cmd.tolerancePct, &p.cmd.thicknessMm};
        for (int k = 1; k < nw; ++k) {
            double v = 0;
            if (!wordNumber(words[k], &v))
                return fail("bad_argument", std::string(kScaleUsage) + " (" + names[k - 1] + " is not a number)");
            if (std::string e = scaleNumber(names[k - 1], v, lo[k - 1], hi[k - 1], dst[k - 1]); !e.empty())
                return fail("bad_argument", e);
        }
    } else if (p.cmd.kind == CommandKind::Aim) {
        if (nw > 2) return fail("bad_argument", "usage: aim [SECONDS | off]");
        if (nw == 2) {
            double v = 0;
            if (words[1] == "off")
                p.cmd.aimSeconds = 0;
            else if (wordNumber(words[1], &v) && v >= 0 && v <= kMaxAimSeconds && v == std::floor(v))
                p.cmd.aimSeconds = int(v);
            else
                return fail("bad_argument", "usage: aim [SECONDS | off] (SECONDS a whole number up to 600)");
        }
    } else if (p.cmd.kind == CommandKind::Set) {
        if (nw != 3) return fail("bad_argument", "usage: set KEY VALUE");
        p.cmd.key = std::string(words[1]);
        p.cmd.value = std::string(words[2]);
    } else if (p.cmd.kind == CommandKind::Get) {
        if (nw > 2) return fail("bad_argument", "usage: get [KEY]");
        if (nw == 2) p.cmd.key = std::string(words[1]);
    } else if (p.cmd.kind == CommandKind::Results) {
        if (nw > 2) return fail("bad_argument", "usage: results [N]");
        if (nw == 2) {
            char *end = nullptr;
            const std::string w(words[1].substr(0, 16));
            const double v = std::strtod(w.c_str(), &end);
            if (end != w.c_str() + w.size() || words[1].size() > 16 || !parseCount(v, &p.cmd.count))
                return fail("bad_argument", "results: N must be a whole number from 1 to 1000");
        }
    } else if (nw > 1) {
        return fail("bad_argument", "'" + std::string(words[0]) + "' takes no arguments");
    }
    p.ok = true;
    return p;
}

} // namespace

CommandParse parseCommand(std::string_view line)
{
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (line.empty()) return fail("malformed", "empty line");
    return line.front() == '{' ? parseJsonCommand(line) : parseWordCommand(line);
}

LineAssembler::Event LineAssembler::push(std::string_view *data)
{
    if (ready_) {
        buf_.clear();
        ready_ = false;
    }
    while (!data->empty()) {
        const char c = data->front();
        data->remove_prefix(1);
        if (c == '\n') {
            if (discarding_) {
                discarding_ = false;
                buf_.clear();
                continue;
            }
            ready_ = true;
            return Event::Line;
        }
        if (discarding_) continue;
        if (buf_.size() >= max_) {
            discarding_ = true;
            buf_.clear();
            ready_ = true; // the empty buffer is cleared again on the next push
            return Event::Overflow;
        }
        buf_.push_back(c);
    }
    return Event::None;
}

} // namespace icacam::fw
