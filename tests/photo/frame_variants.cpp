// A photograph as the camera could have given it otherwise, for the repeatability study
// (repeatability_study.sh): the same frame with a fresh draw of sensor noise, mirrored, or
// turned a quarter. The scene is unchanged, so a reading that moves beyond its U, or changes
// its status, moved on the pixels alone.
//
// usage: photo_frame_variants IN OUT.png noise SEED [SIGMA]   Gaussian noise, SIGMA grey levels (default 1)
//        photo_frame_variants IN OUT.png mirror              left for right
//        photo_frame_variants IN OUT.png quarter             turned 90° clockwise
// OUT is written losslessly (PNG), so that nothing but the variant differs.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/photo/frame_variants.h"

int main(int argc, char **argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s IN OUT.png noise SEED [SIGMA] | mirror | quarter\n", argv[0]);
        return 2;
    }
    cv::Mat frame = cv::imread(argv[1], cv::IMREAD_UNCHANGED);
    if (frame.empty()) {
        std::fprintf(stderr, "%s: cannot read %s\n", argv[0], argv[1]);
        return 1;
    }
    const std::string mode = argv[3];
    cv::Mat out;
    if (mode == "noise" && argc >= 5) {
        out = icacam::test::withSensorNoise(frame, std::strtoull(argv[4], nullptr, 10),
                                            argc >= 6 ? std::atof(argv[5]) : 1.0);
    } else if (mode == "mirror") {
        cv::flip(frame, out, 1);
    } else if (mode == "quarter") {
        cv::rotate(frame, out, cv::ROTATE_90_CLOCKWISE);
    } else {
        std::fprintf(stderr, "%s: unknown variant %s\n", argv[0], mode.c_str());
        return 2;
    }
    if (!cv::imwrite(argv[2], out)) {
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[2]);
        return 1;
    }
    return 0;
}
