#pragma once
// One record schema for every reading: the fields `icacam measure` and `icacam loop` write
// as CSV or JSON columns and the device journals and sends on serial, in this order and at
// these precisions (PRODUCT.md §6 first, then the budget, then diagnostics). Each output
// form is a RecordSink; the schema is written once, here.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "reading/reading.h"

namespace icacam::reading {

class RecordSink {
public:
    virtual void text(const char *name, std::string_view value) = 0;
    // decimals: fixed-point digits after the point.
    virtual void number(const char *name, double value, int decimals) = 0;
    virtual void absent(const char *name) = 0; // no value here: empty in CSV, null in JSON

protected:
    ~RecordSink() = default;
};

// The reading's fields (everything after the record's id). m == nullptr: the record never
// reached the pipeline (bad row, missing file); message says why. For a measurement
// message may be empty: the record then says what the status means (readingMessage).
void writeReading(const Reading *m, std::string_view message, std::string_view model, RecordSink &sink);

// The fields writeReading emits, in order (a CSV header is "id" and these).
int readingFieldCount();
const char *readingFieldName(int i);

// Flag names joined by ';' into buf (always terminated; cut at a whole name when full).
void flagList(uint32_t flags, char *buf, size_t size);
// What a reading's status means in words: the error, or each check's finding with what to
// supply or do ("… declare h_final_mm"); "" for ok.
void readingMessage(const Reading &m, char *buf, size_t size);
// The advice in words: "h_final_mm: U 0.0160 → 0.0060", "n_tol 0.003: U …", or "none: U … is
// mostly the model's own".
void adviceText(const Advice &a, char *buf, size_t size);
// Where segment frames lit from elsewhere than they were said to: what to set ("" when they
// did not, or were not checked). Part of adviceText; said on its own beside a warning.
void segmentsAdvice(const Advice &a, char *buf, size_t size);

} // namespace icacam::reading
