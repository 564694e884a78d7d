#pragma once
// A photograph with a fresh, seeded draw of Gaussian sensor noise, or through JPEG: the same
// scene, other pixels (photo_frame_variants and the tests that replay one of its variants).
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace icacam::test {

inline cv::Mat withSensorNoise(const cv::Mat &frame, uint64_t seed, double sigma)
{
    cv::RNG rng(seed);
    cv::Mat noise(frame.size(), CV_32FC(frame.channels())), levels, out;
    rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma);
    frame.convertTo(levels, CV_32F);
    levels += noise;
    levels.convertTo(out, frame.type()); // rounded and saturated to the frame's depth
    return out;
}

// The frame encoded as JPEG at quality (1–100) and decoded again; empty where it cannot be.
inline cv::Mat throughJpeg(const cv::Mat &frame, int quality)
{
    std::vector<uchar> bytes;
    if (!cv::imencode(".jpg", frame, bytes, {cv::IMWRITE_JPEG_QUALITY, quality})) return {};
    return cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
}

} // namespace icacam::test
