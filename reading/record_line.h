#pragma once
// The record's one line format: a flat JSON object per line (the device's serial lines and
// journal, `icacam measure --format jsonl`, the loop's journal reader). Just enough JSON: a
// flat object of strings, numbers, booleans and nulls in, a builder out (nested values are
// refused: the protocol has none); the reading's fields into a line (JsonRecordSink); and the
// journal's seal, a CRC-32 of the line before its last field.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "reading/reading_record.h"

namespace icacam::reading {

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

// The reading's fields (reading/reading_record.h) into a JSON line.
class JsonRecordSink final : public RecordSink {
public:
    explicit JsonRecordSink(JsonBuilder *j) : j_(j) {}
    void text(const char *name, std::string_view v) override { j_->str(name, v); }
    void number(const char *name, double v, int decimals) override { j_->fixed(name, v, decimals); }
    void absent(const char *name) override { j_->raw(name, "null"); }

private:
    JsonBuilder *j_;
};

// CRC-32 (IEEE 802.3, reflected) of data.
uint32_t recordCrc32(std::string_view data);
// Seals a line without its closing brace: appends ,"crc32":"xxxxxxxx"} (the CRC of what
// precedes it). Allocates only if line must grow.
void sealRecordLine(std::string *line);
// A line as sealRecordLine leaves it, its CRC matching.
bool recordLineIntact(std::string_view line);

} // namespace icacam::reading
