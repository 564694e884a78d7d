#include "hal/file/file_camera.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "hal/file/image_decoder.h"

namespace icacam::hal {

namespace fs = std::filesystem;

namespace {

bool isImageName(const fs::path &p)
{
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".pgm";
}

int channelsOf(PixelFormat f)
{
    switch (f) {
    case PixelFormat::Grey8: return 1;
    case PixelFormat::RGB24: return 3;
    default: return 0;
    }
}

} // namespace

Error FileCamera::configure(const CameraFormat &fmt)
{
    if (fmt.maxWidth <= 0 || fmt.maxHeight <= 0 || fmt.maxWidth > 16384 || fmt.maxHeight > 16384)
        return Error::make(Errc::Invalid, "camera size must be 1..16384 pixels each way");
    if (channelsOf(fmt.format) == 0)
        return Error::make(Errc::BadFormat, "the file camera delivers grey8 or rgb24 only");
    if (opts_.strideAlign < 1 || opts_.strideAlign > 4096)
        return Error::make(Errc::Invalid, "stride alignment must be 1..4096");
    std::error_code ec;
    const std::vector<std::string> before = std::move(files_);
    files_.clear();
    if (fs::is_directory(opts_.source, ec)) {
        for (const auto &e : fs::directory_iterator(opts_.source, ec))
            if (e.is_regular_file(ec) && isImageName(e.path())) files_.push_back(e.path().string());
        std::sort(files_.begin(), files_.end());
    } else if (fs::is_regular_file(opts_.source, ec)) {
        std::ifstream in(opts_.source);
        const fs::path base = fs::path(opts_.source).parent_path();
        for (std::string line; std::getline(in, line);) {
            line.erase(0, line.find_first_not_of(" \t"));
            while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
            if (line.empty() || line[0] == '#') continue;
            if (line == "!timeout" || fs::path(line).is_absolute())
                files_.push_back(line);
            else
                files_.push_back((base / line).string());
        }
    } else {
        return Error::make(Errc::NotFound, "camera source '" + opts_.source + "' is neither a folder nor a list file");
    }
    if (files_.empty()) return Error::make(Errc::NotFound, "camera source '" + opts_.source + "' holds no images");
    const size_t row = size_t(fmt.maxWidth) * size_t(channelsOf(fmt.format));
    const size_t a = size_t(opts_.strideAlign);
    capacity_ = (row + a - 1) / a * a * size_t(fmt.maxHeight);
    buffer_ = std::make_unique<uint8_t[]>(capacity_);
    fmt_ = fmt;
    // Configured again over the same frames (a device re-acquiring a camera that timed out):
    // carry on where it was, as a sensor would, rather than start the sequence over.
    if (files_ != before) next_ = 0;
    return {};
}

std::string FileCamera::describe() const
{
    return "file camera: " + opts_.source + " (" + std::to_string(files_.size()) + " frames)";
}

Result<CameraControls> FileCamera::setControls(const CameraControls &asked)
{
    if (asked.lensPosition >= 0 && opts_.fixedFocus)
        return Result<CameraControls>::fail(Errc::Invalid, "this camera has no lens control (fixed focus)");
    mergeControls(&opts_.controls, asked);
    CameraControls took;
    mergeControls(&took, asked);
    return {took, {}};
}

Error FileCamera::capture(const CaptureRequest &req, CapturedFrame *out)
{
    if (!buffer_) return Error::make(Errc::Invalid, "camera not configured");
    const int timeoutMs = req.timeoutMs;
    int64_t start = clock_.monotonicMs();
    if (req.notBeforeMs != CaptureRequest::kAtCall && req.notBeforeMs > start) {
        clock_.sleepMs(req.notBeforeMs - start);
        start = clock_.monotonicMs();
    }
    const int64_t notBefore = req.notBeforeMs == CaptureRequest::kAtCall ? start : req.notBeforeMs;
    if (next_ >= files_.size() && opts_.loop) next_ = 0;
    if (next_ >= files_.size() || files_[next_] == "!timeout") {
        if (next_ < files_.size()) ++next_;
        clock_.sleepMs(timeoutMs); // a sensor that delivers nothing: the caller's deadline passes
        return Error::make(Errc::Timeout, "no frame within " + std::to_string(timeoutMs) + " ms");
    }
    const size_t index = next_++; // a file that cannot be delivered is used up too
    const std::string &path = files_[index];
    const int ch = channelsOf(fmt_.format);
    const int a = opts_.strideAlign;
    // The stride the sensor would use for the widest frame of this row length.
    DecodedImage img;
    Error e = decodeImage(path, buffer_.get(), capacity_, fmt_.maxWidth, fmt_.maxHeight, 0, &img);
    if (!e.ok()) return e;
    if (img.channels != ch)
        return Error::make(Errc::BadFormat, "'" + fs::path(path).filename().string() + "' has " +
                                                std::to_string(img.channels) +
                                                " channel(s), the camera is configured for " + std::to_string(ch));
    const int stride = (img.width * ch + a - 1) / a * a;
    if (stride != img.stride) {
        // Re-lay rows from the bottom up so the padded rows never overwrite unread ones.
        for (int y = img.height - 1; y > 0; --y)
            std::memmove(buffer_.get() + size_t(y) * size_t(stride), buffer_.get() + size_t(y) * size_t(img.stride),
                         size_t(img.width * ch));
    }
    if (stride < img.width * ch) return Error::make(Errc::BadStride, "stride shorter than a row");
    // The scene stays until a frame has seen it lit (a file camera without a light: every frame).
    if (!light(buffer_.get(), img.width, img.height, stride, ch, start)) next_ = index;
    if (opts_.exposureMs + opts_.readoutMs > 0) clock_.sleepMs(opts_.exposureMs + opts_.readoutMs);
    if (clock_.monotonicMs() - start > timeoutMs)
        return Error::make(Errc::Timeout, "frame arrived after the " + std::to_string(timeoutMs) + " ms deadline");
    out->view.format = fmt_.format;
    out->view.data = buffer_.get();
    out->view.width = img.width;
    out->view.height = img.height;
    out->view.stride = stride;
    out->view.bytes = size_t(stride) * size_t(img.height);
    out->timestampMs = start;
    out->latencyUs = (start - notBefore) * 1000;
    out->exposureUs = opts_.controls.exposureUs >= 0 ? opts_.controls.exposureUs : int64_t(opts_.exposureMs) * 1000;
    out->sequence = uint32_t(next_);
    out->staleFrames = 0;
    out->controls = opts_.controls;
    out->source = fs::path(path).filename().string();
    return {};
}

bool FileCamera::light(uint8_t *rows, int width, int height, int stride, int channels, int64_t startMs) const
{
    if (!opts_.light) return true;
    bool allLit = true;
    const double ambient = std::clamp(opts_.ambient, 0.0, 1.0);
    for (int y = 0; y < height; ++y) {
        const double from = double(startMs) + double(opts_.readoutMs) * y / height;
        const double lit = opts_.light->litFraction(from, from + opts_.exposureMs);
        allLit &= lit >= 1.0;
        const auto gain = unsigned(std::lround((ambient + (1 - ambient) * lit) * 256));
        if (gain >= 256) continue;
        uint8_t *row = rows + size_t(y) * size_t(stride);
        for (int x = 0; x < width * channels; ++x) row[x] = uint8_t((row[x] * gain + 128) >> 8);
    }
    return allLit;
}

} // namespace icacam::hal
