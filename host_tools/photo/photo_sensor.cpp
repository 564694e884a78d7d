#include "host_tools/photo/photo_sensor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace icacam::host::photo {

double SensorModel::noiseAtMidGrey() const
{
    // The linear level that the tone curve maps to 128, its electrons' σ, through the curve's slope.
    const double x = std::pow(128.0 / 255.0, gamma);
    const double sigma = std::sqrt(x * fullWellE + readNoiseE * readNoiseE) / fullWellE;
    const double slope = std::pow(x, 1 / gamma - 1) / gamma;
    return 255 * slope * sigma;
}

cv::Mat developPhoto(const cv::Mat &linear, const SensorModel &m, std::mt19937 &rng, double fixedGain, double *gainUsed)
{
    if (linear.channels() != 3) throw std::runtime_error("photo: a 3-channel render was expected");
    cv::Mat img;
    linear.convertTo(img, CV_32FC3, linear.depth() == CV_16U ? 1.0 / 65535 : 1.0);
    if (!m.colour) {
        cv::Mat grey;
        cv::cvtColor(img, grey, cv::COLOR_BGR2GRAY);
        img = grey;
    }
    // Auto-exposure as a camera meters: the frame's mean to a mid-grey, held back where that
    // would clip more than the brightest highlights. A locked exposure is not metered.
    double gain = fixedGain;
    if (!(fixedGain > 0)) {
        cv::Mat lum;
        if (img.channels() == 3)
            cv::cvtColor(img, lum, cv::COLOR_BGR2GRAY);
        else
            lum = img;
        const double mean = cv::mean(lum)[0];
        std::vector<float> v(lum.begin<float>(), lum.end<float>());
        const size_t at = std::min(v.size() - 1, size_t(0.999 * double(v.size())));
        std::nth_element(v.begin(), v.begin() + long(at), v.end());
        gain = mean > 0 ? m.exposureMean / mean : 1;
        if (v[at] * gain > m.highlightCap) gain = m.highlightCap / v[at];
    }
    if (gainUsed) *gainUsed = gain;
    img *= gain;
    if (m.blurSigmaPx > 0) cv::GaussianBlur(img, img, cv::Size(), m.blurSigmaPx, m.blurSigmaPx, cv::BORDER_REFLECT);
    // Vignetting, a quadratic fall-off to the corners; then the electrons, Poisson (as a
    // Gaussian of the same variance at these counts) with the read noise, and clipping.
    const double cx = 0.5 * (img.cols - 1), cy = 0.5 * (img.rows - 1), r2max = cx * cx + cy * cy;
    std::normal_distribution<float> unit(0, 1);
    const int ch = img.channels();
    for (int y = 0; y < img.rows; ++y) {
        float *row = img.ptr<float>(y);
        for (int x = 0; x < img.cols; ++x) {
            const double fall = 1 - m.vignetting * ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / r2max;
            for (int c = 0; c < ch; ++c) {
                float &p = row[x * ch + c];
                const double e = std::max(0.0, p * fall) * m.fullWellE;
                const double noisy = e + unit(rng) * std::sqrt(e + m.readNoiseE * m.readNoiseE);
                p = float(std::clamp(noisy / m.fullWellE, 0.0, 1.0));
            }
        }
    }
    cv::Mat out(img.size(), CV_8UC(ch));
    // The tone curve, fine enough that the shadows are not posterised by the table.
    constexpr int kSteps = 65535;
    std::vector<uint8_t> lut(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i)
        lut[size_t(i)] = uint8_t(std::lround(255 * std::pow(double(i) / kSteps, 1 / m.gamma)));
    for (int y = 0; y < img.rows; ++y) {
        const float *in = img.ptr<float>(y);
        uint8_t *o = out.ptr<uint8_t>(y);
        for (int i = 0; i < img.cols * ch; ++i) o[i] = lut[size_t(std::lround(in[i] * kSteps))];
    }
    return out;
}

std::vector<uint8_t> encodePhoto(const cv::Mat &image, const SensorModel &m)
{
    std::vector<uint8_t> bytes;
    const bool ok = m.jpegQuality > 0 ? cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, m.jpegQuality})
                                      : cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, 6});
    if (!ok) throw std::runtime_error("photo: could not encode the image");
    return bytes;
}

} // namespace icacam::host::photo
