#pragma once
// A photograph with a fresh, seeded draw of Gaussian sensor noise: the same scene, other
// pixels (photo_frame_variants and the tests that replay one of its draws).
#include <cstdint>

#include <opencv2/core.hpp>

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

} // namespace icacam::test
