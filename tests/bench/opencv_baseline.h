#pragma once
// The plain OpenCV pipeline PRODUCT.md §7 compares against: 5×5 Gaussian blur, Otsu
// threshold, findContours, contour areas. It finds the barrel's silhouette, not the ICA.
#include <opencv2/core.hpp>

namespace icacam::bench {
// Returns the equivalent radius of the largest contour (pixels). Single-threaded.
double opencvBaselineRadius(const cv::Mat &grey);
} // namespace icacam::bench
