#include "tests/bench/opencv_baseline.h"

#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace icacam::bench {
double opencvBaselineRadius(const cv::Mat &grey)
{
    cv::Mat blurred, binary;
    cv::GaussianBlur(grey, blurred, {5, 5}, 0);
    cv::threshold(blurred, binary, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(binary, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    double best = 0;
    for (const auto &c : contours) best = std::max(best, std::fabs(cv::contourArea(c)));
    return std::sqrt(best / M_PI);
}
} // namespace icacam::bench
