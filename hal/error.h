#pragma once
// Errors as values for the HAL (STYLE.md §5): a named code and a human message. No
// exceptions cross a HAL interface; backends that wrap throwing libraries catch at the seam.
#include <cstdint>
#include <string>
#include <utility>

namespace icacam::hal {

enum class Errc : uint8_t {
    None = 0,
    NotFound,  // a device, file or path does not exist
    Io,        // an OS call failed (message carries strerror)
    BadFormat, // pixel format, file format or encoding refused
    BadStride, // a row stride the frame cannot have
    TooLarge,  // exceeds the configured maximum
    Timeout,   // nothing arrived within the deadline
    Full,      // storage or a buffer is full
    Closed,    // the other end went away
    Invalid,   // an argument out of range or an unconfigured device
};

inline const char *errcName(Errc c)
{
    switch (c) {
    case Errc::None: return "none";
    case Errc::NotFound: return "not_found";
    case Errc::Io: return "io";
    case Errc::BadFormat: return "bad_format";
    case Errc::BadStride: return "bad_stride";
    case Errc::TooLarge: return "too_large";
    case Errc::Timeout: return "timeout";
    case Errc::Full: return "full";
    case Errc::Closed: return "closed";
    case Errc::Invalid: return "invalid";
    }
    return "unknown";
}

struct Error {
    Errc code = Errc::None;
    std::string message;

    bool ok() const { return code == Errc::None; }
    static Error make(Errc c, std::string msg) { return Error{c, std::move(msg)}; }
};

// A value or an error. T must be default-constructible (the HAL's types are).
template <typename T> struct Result {
    T value{};
    Error error;

    bool ok() const { return error.ok(); }
    static Result fail(Errc c, std::string msg) { return Result{T{}, Error::make(c, std::move(msg))}; }
};

} // namespace icacam::hal
