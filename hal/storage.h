#pragma once
// Persistent storage (the SD card): named files in one folder, with the two write
// disciplines a crash-safe journal needs. Names are plain file names (no '/', no "..").
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hal/error.h"

namespace icacam::hal {

class Storage {
public:
    virtual ~Storage() = default;
    // Appends and fsyncs; when it returns ok the bytes survive a power loss. Errors: Full, Io.
    virtual Error append(std::string_view name, std::string_view data) = 0;
    // Writes a temporary file, fsyncs it, renames it over name and fsyncs the folder: the
    // file is either the old or the whole new content after a crash. Errors: Full, Io.
    virtual Error writeAtomic(std::string_view name, std::string_view data) = 0;
    virtual Result<std::string> read(std::string_view name) = 0; // NotFound if absent
    virtual Error truncate(std::string_view name, uint64_t size) = 0;
    virtual Error remove(std::string_view name) = 0;
    virtual Result<std::vector<std::string>> list() = 0;
    virtual Result<uint64_t> freeBytes() = 0;
};

} // namespace icacam::hal
