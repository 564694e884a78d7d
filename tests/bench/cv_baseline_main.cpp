// cv_baseline IMAGE [--repeat N]: runs the OpenCV baseline N times on one decoded frame,
// single-threaded, for callgrind's per-frame instruction count.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <opencv2/core.hpp>

#include "host_tools/image_file.h"
#include "tests/bench/opencv_baseline.h"

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: cv_baseline IMAGE [--repeat N]\n");
        return 2;
    }
    int repeat = 1;
    if (argc >= 4 && std::string(argv[2]) == "--repeat") repeat = std::max(1, std::atoi(argv[3]));
    cv::setNumThreads(1);
    icacam::host::LumaImage img;
    if (std::string e = icacam::host::loadLuma(argv[1], &img); !e.empty()) {
        std::fprintf(stderr, "cv_baseline: %s\n", e.c_str());
        return 1;
    }
    double r = 0;
    for (int i = 0; i < repeat; ++i) r = icacam::bench::opencvBaselineRadius(img.luma);
    std::printf("silhouette radius %.2f px\n", r);
    return 0;
}
