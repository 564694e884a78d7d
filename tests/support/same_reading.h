#pragma once
// One instrument, two front ends: `icacam measure`'s reading of a manifest row as a result
// line's fields, and the check that a device's result line carries the same reading, field
// by field to the printed digit. Header-only for the tests that link the host tools.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "friction/friction_model.h"
#include "host_tools/manifest.h"
#include "host_tools/record_measurer.h"
#include "host_tools/result_writer.h"
#include "reading/reading_record.h"
#include "reading/record_line.h"

namespace icacam::test {

// The first row of `manifest` measured as `icacam measure --format jsonl` writes it (a row
// that is not measured gives its message).
inline reading::FlatObject hostResult(const host::Manifest &manifest, const friction::FrictionModel &model)
{
    host::RecordMeasurer measurer(model, reading::SpecimenSpec{});
    host::RecordReading reading;
    measurer.measure(manifest.rows.at(0), manifest, &reading);
    std::ostringstream out;
    host::ResultWriter writer(out, host::ResultFormat::Jsonl);
    host::ResultRow row;
    row.id = "x";
    row.model = model.name();
    if (reading.measured)
        row.m = &reading.reading;
    else
        row.message = reading.message;
    writer.write(row);
    std::string line = out.str();
    line.pop_back();
    reading::FlatObject o;
    EXPECT_EQ(reading::parseFlatObject(line, &o), "");
    return o;
}

// The same, from a manifest's text whose paths are relative to baseDir.
inline reading::FlatObject hostResult(const std::string &manifestText, const std::string &baseDir,
                                      const friction::FrictionModel &model)
{
    host::Manifest manifest;
    std::string err;
    EXPECT_TRUE(host::parseManifest(manifestText, &manifest, &err)) << err;
    manifest.baseDir = baseDir;
    return hostResult(manifest, model);
}

// Every reading field of the device's result line as the host wrote it.
inline void expectSameReading(const reading::FlatObject &device, const reading::FlatObject &host)
{
    for (int i = 0; i < reading::readingFieldCount(); ++i) {
        const char *name = reading::readingFieldName(i);
        const reading::JsonField *d = device.find(name), *h = host.find(name);
        ASSERT_TRUE(d) << "device record lacks " << name;
        ASSERT_TRUE(h) << "icacam measure record lacks " << name;
        EXPECT_EQ(int(d->type), int(h->type)) << name;
        EXPECT_EQ(d->text, h->text) << name;
    }
}

} // namespace icacam::test
