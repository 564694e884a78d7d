#include "host_tools/result_writer.h"

#include <cmath>
#include <cstdio>
#include <cstring>

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
    if (format_ == ResultFormat::Jsonl) return;
    if (format_ == ResultFormat::Table) {
        char line[160];
        std::snprintf(line, sizeof line, "%-16s %-18s %-6s %s\n", "id", "mu \xC2\xB1 U", "status",
                      "finding, or advice");
        out_ << line;
        return;
    }
    const auto cols = columns();
    for (size_t i = 0; i < cols.size(); ++i) out_ << (i ? "," : "") << cols[i];
    out_ << "\n";
}

std::string ResultWriter::tableLine(const ResultRow &r)
{
    char value[48] = "-", words[800];
    const reading::Reading *m = r.m;
    const bool hasValue = m && m->hasValue();
    if (hasValue) std::snprintf(value, sizeof value, "%.4f \xC2\xB1 %.4f", m->mu, m->expanded());
    if (!m)
        std::snprintf(words, sizeof words, "%s", r.message.c_str());
    else if (m->status == reading::Status::Ok)
        reading::adviceText(m->advice, words, sizeof words);
    else
        reading::readingMessage(*m, words, sizeof words);
    // Segment frames said to lie elsewhere than they lit from: the advice says so on an ok
    // reading; beside a warning's findings too.
    if (m && m->status != reading::Status::Ok && m->advice.segmentWay != 0) {
        const size_t used = std::strlen(words);
        std::snprintf(words + used, sizeof words - used, "%s", used ? "; " : "");
        const size_t now = std::strlen(words);
        reading::segmentsAdvice(m->advice, words + now, sizeof words - now);
    }
    const char *status = m ? reading::statusName(m->status) : "error";
    char line[1000];
    // 18 bytes wide: "±" takes two, in the header and in each value alike.
    std::snprintf(line, sizeof line, "%-16s %-18s %-6s %s", r.id.c_str(), value, status, words);
    return line;
}

void ResultWriter::write(const ResultRow &r)
{
    const reading::Reading *m = r.m;
    const reading::Status st = m ? m->status : reading::Status::Error;
    (st == reading::Status::Ok ? ok_ : st == reading::Status::Warn ? warn_ : error_)++;
    if (m && m->hasValue()) {
        (m->decision == reading::Decision::Within ? within_ : beyond_)++;
        ++advised_[reading::adviceInputName(m->advice.input)];
    }
    std::string line;
    if (format_ == ResultFormat::Table) {
        line = tableLine(r) + "\n";
    } else if (format_ == ResultFormat::Jsonl) {
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

void ResultWriter::summary()
{
    if (format_ != ResultFormat::Table) return;
    const int total = ok_ + warn_ + error_;
    out_ << "\n" << total << " records: " << ok_ << " ok, " << warn_ << " warn, " << error_ << " error";
    if (within_ + beyond_ > 0) out_ << "; U within the tolerance on " << within_ << ", beyond it on " << beyond_;
    out_ << "\n";
    // The advice most readings share, where there is one.
    std::string best;
    int bestCount = 0;
    for (const auto &[name, count] : advised_)
        if (name != "none" && count > bestCount) best = name, bestCount = count;
    if (bestCount > 0) out_ << "declaring " << best << " would shrink U on " << bestCount << " of them\n";
    out_ << "ok: every check passed and U covers the error; warn: a check found a condition U may not cover "
            "(what to supply is named); the full record: --out FILE or --format csv\n";
    out_.flush();
}

} // namespace icacam::host
