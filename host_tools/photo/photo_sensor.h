#pragma once
// From the renderer's linear radiance to the file a camera writes: auto-exposure, lens blur,
// vignetting, shot and read noise in electrons, the tone curve, 8 bits, a grey or colour
// sensor, JPEG or PNG.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace icacam::host::photo {

struct SensorModel {
    double exposureMean = 0.18; // the frame's mean luminance after exposure (linear, of full scale)…
    double highlightCap = 1.2;  // …unless its 99.9th percentile would pass this (then that is held)
    double blurSigmaPx = 0.8;   // lens and focus, a Gaussian
    double vignetting = 0.2;    // relative fall-off at the frame's corners
    double fullWellE = 10000;   // electrons at full scale (shot noise)
    double readNoiseE = 4;      // electrons, Gaussian
    double gamma = 2.2;         // the tone curve: out = in^(1/gamma)
    bool colour = false;        // a colour camera (else mono)
    int jpegQuality = 0;        // 0: PNG

    // The noise's standard deviation in 8-bit grey levels at a mid-grey (128) output.
    double noiseAtMidGrey() const;
};

// linear: CV_16UC3 or CV_32FC3 in linear radiance (BGR, as cv::imread gives). Returns the
// 8-bit image (CV_8UC1 or CV_8UC3) before encoding. fixedGain > 0: the exposure locked at
// that gain (a sequence's later frames), else metered from the frame (exposureMean,
// highlightCap); gainUsed, when given, receives the gain applied to the linear radiance.
cv::Mat developPhoto(const cv::Mat &linear, const SensorModel &m, std::mt19937 &rng, double fixedGain = 0,
                     double *gainUsed = nullptr);

// The bytes of the file (JPEG at the model's quality, or PNG).
std::vector<uint8_t> encodePhoto(const cv::Mat &image, const SensorModel &m);

} // namespace icacam::host::photo
