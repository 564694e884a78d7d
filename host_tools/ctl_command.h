#pragma once
#include <string>
#include <vector>

namespace icacam::host {
// `icacam ctl --port DEV [--baud N] [--timeout-ms T] COMMAND...`: one request to the device's
// serial protocol (docs/firmware.md), its answer lines printed.
int ctlCommand(const std::vector<std::string> &args);
} // namespace icacam::host
