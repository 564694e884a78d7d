#pragma once
// Reading a saved end-face photograph into an 8-bit luma plane, with the checks a lab
// expects: a missing, empty, truncated or non-image file is a clear error, not a crash.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace icacam::host {

struct LumaImage {
    cv::Mat luma;       // CV_8UC1, continuous
    std::string format; // "png", "jpeg", ...
    int channels = 0;   // channels in the file
};

// Returns an empty string on success, else the reason in words.
std::string loadLuma(const std::string &path, LumaImage *out);

// Checks the container of PNG and JPEG files for truncation (missing IEND / EOI).
std::string checkContainer(const std::vector<uint8_t> &bytes, std::string *format);

} // namespace icacam::host
