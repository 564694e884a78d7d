#pragma once
// Just enough JSON for one-line messages: a flat object of strings, numbers, booleans and
// nulls in, a builder out. Nested values are refused: the protocol has none.
#include <cstddef>
#include <string>
#include <string_view>

namespace icacam::fw {

struct JsonField {
    enum class Type { String, Number, Bool, Null } type = Type::Null;
    std::string key;
    std::string text; // string value (unescaped) or the number's literal
    double number = 0;
    bool boolean = false;
};

struct FlatObject {
    // A journal record has about 60 fields (the reading, its budget and diagnostics, the
    // device's settings and capture).
    static constexpr int kMaxFields = 96;
    JsonField fields[kMaxFields];
    int count = 0;
    const JsonField *find(std::string_view key) const;
};

// Parses one object; "" on success, else what is wrong (with the byte offset).
std::string parseFlatObject(std::string_view text, FlatObject *out);

// Appends JSON to a caller-owned string (reused between lines, so no allocation once grown).
class JsonBuilder {
public:
    explicit JsonBuilder(std::string *out) : out_(out) { out_->push_back('{'); }
    JsonBuilder &str(std::string_view key, std::string_view value);
    JsonBuilder &num(std::string_view key, double value, int digits = 6);
    JsonBuilder &fixed(std::string_view key, double value, int decimals); // %.Nf, null if not finite
    JsonBuilder &integer(std::string_view key, long long value);
    JsonBuilder &boolean(std::string_view key, bool value);
    JsonBuilder &raw(std::string_view key, std::string_view json); // value already JSON
    void end() { out_->append("}\n"); }
    static void escape(std::string *out, std::string_view s);

private:
    void keyPart(std::string_view key);
    std::string *out_;
    bool first_ = true;
};

} // namespace icacam::fw
