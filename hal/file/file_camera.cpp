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

constexpr int kMinSegmentImages = 3, kMaxSegmentImages = 8;

std::string trim(std::string s)
{
    s.erase(0, s.find_first_not_of(" \t"));
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
    return s;
}

std::string fileName(const std::string &path)
{
    return fs::path(path).filename().string();
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
    std::vector<Entry> entries;
    if (fs::is_directory(opts_.source, ec)) {
        for (const auto &e : fs::directory_iterator(opts_.source, ec))
            if (e.is_regular_file(ec) && isImageName(e.path())) entries.push_back({e.path().string(), {}});
        std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) { return a.image < b.image; });
    } else if (fs::is_regular_file(opts_.source, ec)) {
        if (Error e = readList(&entries); !e.ok()) return e;
    } else {
        return Error::make(Errc::NotFound, "camera source '" + opts_.source + "' is neither a folder nor a list file");
    }
    if (entries.empty()) return Error::make(Errc::NotFound, "camera source '" + opts_.source + "' holds no images");
    const size_t row = size_t(fmt.maxWidth) * size_t(channelsOf(fmt.format));
    const size_t a = size_t(opts_.strideAlign);
    capacity_ = (row + a - 1) / a * a * size_t(fmt.maxHeight);
    buffer_ = std::make_unique<uint8_t[]>(capacity_);
    fmt_ = fmt;
    // Configured again over the same frames (a device re-acquiring a camera that timed out):
    // carry on where it was, as a sensor would, rather than start the sequence over.
    if (entries != entries_) next_ = 0;
    entries_ = std::move(entries);
    return {};
}

Error FileCamera::readList(std::vector<Entry> *entries) const
{
    std::ifstream in(opts_.source);
    const fs::path base = fs::path(opts_.source).parent_path();
    auto where = [&](const std::string &p) { return fs::path(p).is_absolute() ? p : (base / p).string(); };
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        line = trim(line);
        if (line.empty() || line[0] == '#') continue;
        // "IMAGE | S0 | … | S(N−1)": the parts between the bars, each trimmed.
        std::vector<std::string> parts;
        for (size_t from = 0;;) {
            const size_t bar = line.find('|', from);
            parts.push_back(trim(line.substr(from, bar == std::string::npos ? bar : bar - from)));
            if (parts.back().empty())
                return Error::make(Errc::Invalid, "camera list '" + opts_.source + "' line " + std::to_string(lineNo) +
                                                      ": an empty path beside a '|'");
            if (bar == std::string::npos) break;
            from = bar + 1;
        }
        Entry entry{parts[0] == "!timeout" ? parts[0] : where(parts[0]), {}};
        for (size_t k = 1; k < parts.size(); ++k) entry.segments.push_back(where(parts[k]));
        const int n = int(entry.segments.size());
        const std::string at = "camera list '" + opts_.source + "' line " + std::to_string(lineNo);
        if (n > 0 && entry.image == "!timeout")
            return Error::make(Errc::Invalid, at + ": '!timeout' has no segment images");
        if (n > 0 && (n < kMinSegmentImages || n > kMaxSegmentImages))
            return Error::make(Errc::Invalid, at + ": " + std::to_string(n) + " segment images (" +
                                                  std::to_string(kMinSegmentImages) + " to " +
                                                  std::to_string(kMaxSegmentImages) + ")");
        entries->push_back(std::move(entry));
    }
    return {};
}

std::string FileCamera::describe() const
{
    return "file camera: " + opts_.source + " (" + std::to_string(entries_.size()) + " frames)";
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
    if (next_ >= entries_.size() && opts_.loop) next_ = 0;
    if (next_ >= entries_.size() || entries_[next_].image == "!timeout") {
        if (next_ < entries_.size()) ++next_;
        clock_.sleepMs(timeoutMs); // a sensor that delivers nothing: the caller's deadline passes
        return Error::make(Errc::Timeout, "no frame within " + std::to_string(timeoutMs) + " ms");
    }
    const size_t index = next_++; // a scene that cannot be delivered is used up too
    const Entry &entry = entries_[index];
    const std::string *path = &entry.image;
    const int ch = channelsOf(fmt_.format);
    const int a = opts_.strideAlign;
    DecodedImage img;
    if (Error e = decode(entry.image, &img); !e.ok()) return e;
    const int by = litBy(start, img.height);
    double share = 1;
    if (by != kWholeRing) {
        next_ = index; // a segment's frame leaves the scene for the whole ring's
        if (entry.segments.empty()) {
            share = 1.0 / opts_.light->segments();
        } else {
            if (int(entry.segments.size()) != opts_.light->segments())
                return Error::make(Errc::Invalid, "'" + fileName(entry.image) + "' has " +
                                                      std::to_string(entry.segments.size()) +
                                                      " segment images, the LED ring " +
                                                      std::to_string(opts_.light->segments()) + " segments");
            path = &entry.segments[size_t(by)];
            DecodedImage seg;
            if (Error e = decode(*path, &seg); !e.ok()) return e;
            if (seg.width != img.width || seg.height != img.height)
                return Error::make(Errc::BadFormat, "segment image '" + fileName(*path) + "' is " +
                                                        std::to_string(seg.width) + "x" + std::to_string(seg.height) +
                                                        ", its scene '" + fileName(entry.image) + "' " +
                                                        std::to_string(img.width) + "x" + std::to_string(img.height));
            img = seg;
        }
    }
    // The stride the sensor would use for the widest frame of this row length.
    const int stride = (img.width * ch + a - 1) / a * a;
    if (stride != img.stride) {
        // Re-lay rows from the bottom up so the padded rows never overwrite unread ones.
        for (int y = img.height - 1; y > 0; --y)
            std::memmove(buffer_.get() + size_t(y) * size_t(stride), buffer_.get() + size_t(y) * size_t(img.stride),
                         size_t(img.width * ch));
    }
    if (stride < img.width * ch) return Error::make(Errc::BadStride, "stride shorter than a row");
    // The scene stays until a frame has seen it lit by the whole ring (a file camera without a
    // light: every frame).
    if (!light(buffer_.get(), img.width, img.height, stride, ch, start, by, share)) next_ = index;
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
    out->source = fileName(*path);
    return {};
}

Error FileCamera::decode(const std::string &path, DecodedImage *img)
{
    Error e = decodeImage(path, buffer_.get(), capacity_, fmt_.maxWidth, fmt_.maxHeight, 0, img);
    if (!e.ok()) return e;
    const int ch = channelsOf(fmt_.format);
    if (img->channels != ch)
        return Error::make(Errc::BadFormat, "'" + fileName(path) + "' has " + std::to_string(img->channels) +
                                                " channel(s), the camera is configured for " + std::to_string(ch));
    return {};
}

int FileCamera::litBy(int64_t startMs, int height) const
{
    if (!opts_.light) return kWholeRing;
    const double from = double(startMs) + double(opts_.readoutMs) * (height / 2) / height;
    const double to = from + opts_.exposureMs;
    int by = kWholeRing;
    double most = opts_.light->litFraction(from, to);
    for (int k = 0; k < opts_.light->segments(); ++k)
        if (const double lit = opts_.light->litFraction(from, to, k); lit > most) {
            most = lit;
            by = k;
        }
    return by;
}

bool FileCamera::light(uint8_t *rows, int width, int height, int stride, int channels, int64_t startMs, int by,
                       double share) const
{
    if (!opts_.light) return true;
    bool allLit = true;
    const double ambient = std::clamp(opts_.ambient, 0.0, 1.0);
    for (int y = 0; y < height; ++y) {
        const double from = double(startMs) + double(opts_.readoutMs) * y / height;
        const double to = from + opts_.exposureMs;
        const double lit =
            by == kWholeRing ? opts_.light->litFraction(from, to) : opts_.light->litFraction(from, to, by);
        allLit &= lit >= 1.0;
        const auto gain = unsigned(std::lround((ambient + (1 - ambient) * lit * share) * 256));
        if (gain >= 256) continue;
        uint8_t *row = rows + size_t(y) * size_t(stride);
        for (int x = 0; x < width * channels; ++x) row[x] = uint8_t((row[x] * gain + 128) >> 8);
    }
    return allLit;
}

} // namespace icacam::hal
