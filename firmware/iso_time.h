#pragma once
// A record's time: UTC, ISO 8601 with milliseconds.
#include <cstdint>

namespace icacam::fw {

// Writes into a caller buffer: the report path allocates nothing once out_ has grown.
void isoTime(int64_t wallMs, char (&b)[96]);

} // namespace icacam::fw
