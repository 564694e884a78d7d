#include "host_tools/image_file.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include <opencv2/imgcodecs.hpp>

#include "vision/luma_view.h"

namespace icacam::host {

std::string checkContainer(const std::vector<uint8_t> &b, std::string *format)
{
    static const uint8_t png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (b.size() >= 8 && std::equal(png, png + 8, b.begin())) {
        *format = "png";
        // The last chunk must be IEND (12 bytes: length 0, "IEND", CRC).
        static const uint8_t iend[4] = {'I', 'E', 'N', 'D'};
        if (b.size() < 8 + 12 || !std::equal(iend, iend + 4, b.end() - 8))
            return "PNG file is truncated (no IEND chunk)";
        return "";
    }
    if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) {
        *format = "jpeg";
        // End-of-image marker, allowing padding after it.
        size_t end = b.size();
        while (end > 2 && (b[end - 1] == 0x00 || b[end - 1] == 0xFF)) --end;
        const bool eoiAtEnd = end >= 4 && b[end - 2] == 0xFF && b[end - 1] == 0xD9;
        const bool eoiBeforePad = end >= 3 && end < b.size() && b[end - 1] == 0xFF && b[end] == 0xD9;
        if (!eoiAtEnd && !eoiBeforePad) return "JPEG file is truncated (no end-of-image marker)";
        return "";
    }
    *format = "other";
    return "";
}

std::string loadLuma(const std::string &path, LumaImage *out)
{
    // A directory opens as a stream on Linux and throws on the first read: it is no image.
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) return "not a file: " + path;
    std::ifstream f(path, std::ios::binary);
    if (!f) return "image file not found or unreadable: " + path;
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return "image file is empty: " + path;
    if (std::string err = checkContainer(bytes, &out->format); !err.empty()) return err;
    cv::Mat img;
    try {
        img = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception &e) {
        return std::string("image could not be decoded: ") + e.what();
    }
    if (img.empty()) return "not an image OpenCV can decode (corrupt or unknown format)";
    if (img.depth() == CV_16U) img.convertTo(img, CV_8U, 1.0 / 257.0);
    if (img.depth() != CV_8U) return "unsupported pixel depth (need 8 or 16 bit)";
    if (!img.isContinuous()) img = img.clone();
    out->channels = img.channels();

    using namespace icacam::vision;
    FrameView fv;
    fv.data = img.data;
    fv.width = img.cols;
    fv.height = img.rows;
    fv.stride = int(img.step[0]);
    fv.bytes = img.total() * img.elemSize();
    switch (img.channels()) {
    case 1: fv.format = PixelFormat::Grey8; break;
    case 3: fv.format = PixelFormat::BGR24; break;
    case 4: fv.format = PixelFormat::XRGB32; break; // OpenCV's BGRA: B G R A in memory
    default: return "unsupported channel count " + std::to_string(img.channels());
    }
    out->luma.create(img.rows, img.cols, CV_8UC1);
    LumaView lv;
    const ErrorCode e = lumaOf(fv, out->luma.data, out->luma.total(), &lv);
    if (e != ErrorCode::None) return errorMessage(e);
    if (lv.data == img.data) out->luma = img; // viewed in place: keep the decoded plane
    return "";
}

} // namespace icacam::host
