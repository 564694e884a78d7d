#include "host_tools/result_writer.h"

#include <cmath>
#include <cstdio>

#include "reading/reading_record.h"

namespace icacam::host {

namespace {

std::string csvQuote(std::string_view s)
{
    if (s.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(s);
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
    return q + "\"";
}

std::string jsonQuote(std::string_view s)
{
    std::string q = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            q += '\\';
            q += char(c);
        } else if (c < 0x20) {
            char b[8];
            std::snprintf(b, sizeof b, "\\u%04x", c);
            q += b;
        } else
            q += char(c);
    }
    return q + "\"";
}

std::string fixed(double v, int decimals)
{
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
    return b;
}

class CsvSink final : public reading::RecordSink {
public:
    explicit CsvSink(std::string *line) : line_(line) {}
    void text(const char *, std::string_view v) override { *line_ += "," + csvQuote(v); }
    void number(const char *, double v, int d) override { *line_ += "," + fixed(v, d); }
    void absent(const char *) override { *line_ += ","; }

private:
    std::string *line_;
};

class JsonSink final : public reading::RecordSink {
public:
    explicit JsonSink(std::string *line) : line_(line) {}
    void text(const char *k, std::string_view v) override { *line_ += "," + jsonQuote(k) + ":" + jsonQuote(v); }
    void number(const char *k, double v, int d) override { *line_ += "," + jsonQuote(k) + ":" + fixed(v, d); }
    void absent(const char *k) override { *line_ += "," + jsonQuote(k) + ":null"; }

private:
    std::string *line_;
};

} // namespace

std::vector<std::string> ResultWriter::columns()
{
    std::vector<std::string> c{"id"};
    for (int i = 0; i < reading::readingFieldCount(); ++i) c.emplace_back(reading::readingFieldName(i));
    return c;
}

std::string ResultWriter::flagList(uint32_t flags)
{
    char b[512];
    reading::flagList(flags, b, sizeof b);
    return b;
}

void ResultWriter::header()
{
    if (jsonl_) return;
    const auto cols = columns();
    for (size_t i = 0; i < cols.size(); ++i) out_ << (i ? "," : "") << cols[i];
    out_ << "\n";
}

void ResultWriter::write(const ResultRow &r)
{
    std::string line;
    if (jsonl_) {
        line = "{\"id\":" + jsonQuote(r.id);
        JsonSink sink(&line);
        reading::writeReading(r.m, r.message, r.model, sink);
        line += "}\n";
    } else {
        line = csvQuote(r.id);
        CsvSink sink(&line);
        reading::writeReading(r.m, r.message, r.model, sink);
        line += "\n";
    }
    out_ << line;
    out_.flush();
}

} // namespace icacam::host
