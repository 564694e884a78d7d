#pragma once
// Storage in a folder (the SD card on the device, a temporary folder in tests). An optional
// quota makes the folder behave like a small card: a write that would exceed it is refused
// with Errc::Full before any byte is written, as ENOSPC would refuse it.
#include <cstdint>
#include <string>

#include "hal/storage.h"

namespace icacam::hal {

class FolderStorage final : public Storage {
public:
    Error open(const std::string &folder, uint64_t quotaBytes = 0);

    Error append(std::string_view name, std::string_view data) override;
    Error writeAtomic(std::string_view name, std::string_view data) override;
    Result<std::string> read(std::string_view name) override;
    Error truncate(std::string_view name, uint64_t size) override;
    Error remove(std::string_view name) override;
    Result<std::vector<std::string>> list() override;
    Result<uint64_t> freeBytes() override;

private:
    Error checkName(std::string_view name) const;
    Error reserve(uint64_t bytes);
    std::string path(std::string_view name) const { return folder_ + "/" + std::string(name); }

    std::string folder_;
    uint64_t quota_ = 0;
};

} // namespace icacam::hal
