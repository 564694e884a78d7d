#pragma once
// A number printed with a printf format ("%.6g", "%.4f" …) as a std::string: the generated
// tables and decks print every number this way, so they read the same on every platform.
#include <cstdio>
#include <string>

namespace icacam::host {

inline std::string numberText(const char *format, double v)
{
    char b[64];
    std::snprintf(b, sizeof b, format, v);
    return b;
}

} // namespace icacam::host
