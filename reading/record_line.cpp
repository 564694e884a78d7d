#include "reading/record_line.h"

#include <array>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace icacam::reading {

const JsonField *FlatObject::find(std::string_view key) const
{
    for (int i = 0; i < count; ++i)
        if (fields[i].key == key) return &fields[i];
    return nullptr;
}

namespace {

struct Cursor {
    std::string_view s;
    size_t i = 0;
    void ws()
    {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\n')) ++i;
    }
    bool eat(char c)
    {
        ws();
        if (i < s.size() && s[i] == c) {
            ++i;
            return true;
        }
        return false;
    }
    std::string at() const { return " at byte " + std::to_string(i); }
};

void appendUtf8(std::string *out, uint32_t cp)
{
    if (cp < 0x80)
        out->push_back(char(cp));
    else if (cp < 0x800) {
        out->push_back(char(0xC0 | (cp >> 6)));
        out->push_back(char(0x80 | (cp & 0x3F)));
    } else {
        out->push_back(char(0xE0 | (cp >> 12)));
        out->push_back(char(0x80 | ((cp >> 6) & 0x3F)));
        out->push_back(char(0x80 | (cp & 0x3F)));
    }
}

std::string parseString(Cursor &c, std::string *out)
{
    if (!c.eat('"')) return "expected a string" + c.at();
    out->clear();
    while (c.i < c.s.size()) {
        const char ch = c.s[c.i++];
        if (ch == '"') return "";
        if (uint8_t(ch) < 0x20) return "control character in a string" + c.at();
        if (ch != '\\') {
            out->push_back(ch);
            continue;
        }
        if (c.i >= c.s.size()) break;
        const char e = c.s[c.i++];
        switch (e) {
        case '"':
        case '\\':
        case '/': out->push_back(e); break;
        case 'b': out->push_back('\b'); break;
        case 'f': out->push_back('\f'); break;
        case 'n': out->push_back('\n'); break;
        case 'r': out->push_back('\r'); break;
        case 't': out->push_back('\t'); break;
        case 'u': {
            if (c.i + 4 > c.s.size()) return "short \\u escape" + c.at();
            uint32_t cp = 0;
            for (int k = 0; k < 4; ++k) {
                const char h = c.s[c.i++];
                const int d = h >= '0' && h <= '9'   ? h - '0'
                              : h >= 'a' && h <= 'f' ? h - 'a' + 10
                              : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                                     : -1;
                if (d < 0) return "bad \\u escape" + c.at();
                cp = cp * 16 + uint32_t(d);
            }
            appendUtf8(out, (cp >= 0xD800 && cp < 0xE000) ? '?' : cp);
            break;
        }
        default: return "bad escape" + c.at();
        }
    }
    return "unterminated string";
}

} // namespace

std::string parseFlatObject(std::string_view text, FlatObject *out)
{
    out->count = 0;
    Cursor c{text};
    if (!c.eat('{')) return "expected '{'" + c.at();
    if (c.eat('}')) {
        c.ws();
        return c.i == text.size() ? "" : "text after the object" + c.at();
    }
    for (;;) {
        if (out->count >= FlatObject::kMaxFields)
            return "too many fields (at most " + std::to_string(FlatObject::kMaxFields) + ")";
        JsonField &f = out->fields[out->count];
        c.ws();
        if (std::string e = parseString(c, &f.key); !e.empty()) return e;
        if (!c.eat(':')) return "expected ':'" + c.at();
        c.ws();
        if (c.i >= text.size()) return "missing value" + c.at();
        const char ch = text[c.i];
        if (ch == '"') {
            f.type = JsonField::Type::String;
            if (std::string e = parseString(c, &f.text); !e.empty()) return e;
        } else if (ch == '{' || ch == '[') {
            return "nested objects and arrays are not supported" + c.at();
        } else if (text.substr(c.i, 4) == "true" || text.substr(c.i, 5) == "false") {
            f.type = JsonField::Type::Bool;
            f.boolean = ch == 't';
            c.i += f.boolean ? 4 : 5;
        } else if (text.substr(c.i, 4) == "null") {
            f.type = JsonField::Type::Null;
            c.i += 4;
        } else {
            const size_t b = c.i;
            while (c.i < text.size() && (std::isdigit(uint8_t(text[c.i])) || text[c.i] == '-' || text[c.i] == '+' ||
                                         text[c.i] == '.' || text[c.i] == 'e' || text[c.i] == 'E'))
                ++c.i;
            f.text = std::string(text.substr(b, c.i - b));
            char *end = nullptr;
            f.number = f.text.empty() || f.text.size() > 64 ? NAN : std::strtod(f.text.c_str(), &end);
            if (f.text.empty() || end != f.text.c_str() + f.text.size() || !std::isfinite(f.number))
                return "bad value" + c.at();
            f.type = JsonField::Type::Number;
        }
        for (int k = 0; k < out->count; ++k)
            if (out->fields[k].key == f.key) return "duplicate key '" + f.key.substr(0, 32) + "'";
        ++out->count;
        if (c.eat(',')) continue;
        if (c.eat('}')) break;
        return "expected ',' or '}'" + c.at();
    }
    c.ws();
    return c.i == text.size() ? "" : "text after the object" + c.at();
}

void JsonBuilder::escape(std::string *out, std::string_view s)
{
    out->push_back('"');
    for (char ch : s) {
        const auto u = uint8_t(ch);
        if (ch == '"' || ch == '\\') {
            out->push_back('\\');
            out->push_back(ch);
        } else if (ch == '\n')
            out->append("\\n");
        else if (u < 0x20 || u == 0x7F) {
            char b[8];
            std::snprintf(b, sizeof b, "\\u%04x", unsigned(u));
            out->append(b);
        } else
            out->push_back(ch);
    }
    out->push_back('"');
}

void JsonBuilder::keyPart(std::string_view key)
{
    if (!first_) out_->push_back(',');
    first_ = false;
    escape(out_, key);
    out_->push_back(':');
}

JsonBuilder &JsonBuilder::str(std::string_view key, std::string_view value)
{
    keyPart(key);
    escape(out_, value);
    return *this;
}

JsonBuilder &JsonBuilder::num(std::string_view key, double value, int digits)
{
    keyPart(key);
    if (!std::isfinite(value)) {
        out_->append("null");
        return *this;
    }
    char b[40];
    std::snprintf(b, sizeof b, "%.*g", digits, value);
    out_->append(b);
    return *this;
}

JsonBuilder &JsonBuilder::fixed(std::string_view key, double value, int decimals)
{
    keyPart(key);
    if (!std::isfinite(value)) {
        out_->append("null");
        return *this;
    }
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", decimals, value);
    out_->append(b);
    return *this;
}

JsonBuilder &JsonBuilder::integer(std::string_view key, long long value)
{
    keyPart(key);
    out_->append(std::to_string(value));
    return *this;
}

JsonBuilder &JsonBuilder::boolean(std::string_view key, bool value)
{
    keyPart(key);
    out_->append(value ? "true" : "false");
    return *this;
}

JsonBuilder &JsonBuilder::raw(std::string_view key, std::string_view json)
{
    keyPart(key);
    out_->append(json);
    return *this;
}

namespace {
constexpr std::string_view kCrcKey = ",\"crc32\":\"";
}

uint32_t recordCrc32(std::string_view data)
{
    // IEEE 802.3 polynomial, reflected, table built once at compile time.
    static constexpr auto kTable = [] {
        std::array<uint32_t, 256> t{};
        for (uint32_t i = 0; i < 256; ++i) {
            uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    uint32_t c = 0xFFFFFFFFu;
    for (char ch : data) c = kTable[(c ^ uint8_t(ch)) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

void sealRecordLine(std::string *line)
{
    char tail[32];
    std::snprintf(tail, sizeof tail, "%.*s%08x\"}", int(kCrcKey.size()), kCrcKey.data(), recordCrc32(*line));
    line->append(tail);
}

bool recordLineIntact(std::string_view line)
{
    const size_t at = line.rfind(kCrcKey);
    if (at == std::string_view::npos || line.size() != at + kCrcKey.size() + 10) return false;
    if (line.substr(line.size() - 2) != "\"}") return false;
    char want[9];
    std::snprintf(want, sizeof want, "%08x", recordCrc32(line.substr(0, at)));
    return line.substr(at + kCrcKey.size(), 8) == want;
}

} // namespace icacam::reading
