// A photograph as the camera could have given it otherwise, for the repeatability study
// (repeatability_study.sh): the same frame with a fresh draw of sensor noise, mirrored,
// turned a quarter, taken by a sensor of fewer pixels, or compressed. The scene is unchanged,
// so a reading that moves beyond its U, or changes its status, moved on the pixels alone.
//
// usage: photo_frame_variants IN OUT.png noise SEED [SIGMA]   Gaussian noise, SIGMA grey levels (default 1)
//        photo_frame_variants IN OUT.png mirror              left for right
//        photo_frame_variants IN OUT.png quarter             turned 90° clockwise
//        photo_frame_variants IN OUT.png area S              S times the pixels a side (0 < S < 1),
//                                                            each the mean of the ones it covers
//        photo_frame_variants IN OUT.png jpeg Q              through JPEG at quality Q (1–100)
// OUT is written losslessly (PNG), so that nothing but the variant differs.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/photo/frame_variants.h"

int main(int argc, char **argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s IN OUT.png noise SEED [SIGMA] | mirror | quarter | area S | jpeg Q\n", argv[0]);
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
    } else if (mode == "area" && argc >= 5 && std::atof(argv[4]) > 0 && std::atof(argv[4]) < 1) {
        const double s = std::atof(argv[4]);
        cv::resize(frame, out, cv::Size(), s, s, cv::INTER_AREA);
    } else if (mode == "jpeg" && argc >= 5 && std::atoi(argv[4]) >= 1 && std::atoi(argv[4]) <= 100) {
        out = icacam::test::throughJpeg(frame, std::atoi(argv[4]));
        if (out.empty()) {
            std::fprintf(stderr, "%s: cannot encode %s as JPEG\n", argv[0], argv[1]);
            return 1;
        }
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
