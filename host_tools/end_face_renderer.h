#pragma once
// Synthetic photographs of an upset specimen's end face, with ground truth: the project's
// own renderer for accuracy tests over many random cases (and for calibration photos
// later). Nuisances follow the issue: either face/ICA polarity, low and fading contrast,
// turning marks, stains, scratches, illumination gradient and vignetting, a highlight ring
// on the barrel, a distractor circle, defocus blur, sensor noise, JPEG compression.
#include <cstdint>
#include <random>
#include <string>

#include <opencv2/core.hpp>

namespace icacam::host {

struct EndFaceScene {
    int width = 1456, height = 1088;
    double mmPerPx = 0.0135;
    double cxPx = 728, cyPx = 544;
    double rInnerMm = 5.5, rOuterMm = 6.2, rMaxMm = 7.25; // nominal radii (before wobble)
    // Boundary wobble: relative amplitudes of harmonics 2..4 and their phases.
    double wobble[2][3] = {}, wobblePhase[2][3] = {};
    double background = 40, barrel = 30, ica = 170, face = 150; // grey levels
    // Where the visible edges lie relative to the boundaries' truth (mm, inner and outer):
    // a soft transition whose middle is not the boundary itself. The truth radii below
    // exclude it.
    double edgeOffsetMm[2] = {0, 0};
    double fade = 0;         // ICA contrast fades by this fraction around the ring
    double turningMarks = 0; // amplitude of concentric marks in the ICA (grey levels)
    int stains = 0, scratches = 0;
    double gradient = 0;     // illumination gradient across the frame (fraction)
    double vignetting = 0;   // fall-off at the corners (fraction)
    double highlight = 0;    // highlight ring on the barrel (grey levels)
    bool distractor = false; // a circle in the fixture
    double blurSigmaPx = 0;
    double noiseSigma = 0;
    int jpegQuality = 0; // 0: PNG
    uint32_t seed = 1;

    // Equivalent radii sqrt(area/π) of the drawn boundaries (the truth).
    double rInnerEqMm() const;
    double rOuterEqMm() const;
};

// Where boundary b (0 inner, 1 outer) is drawn at angle theta about the centre (mm): its
// nominal radius with the wobble, moved by the visible edge's offset.
double drawnBoundaryMm(const EndFaceScene &s, int b, double theta);

// A clean scene of the paper's geometry at 50 % reduction (D0 10 mm): contact edge 6.2 mm,
// ICA width u, silhouette from volume constancy, mild blur and noise. Tests and benchmarks
// start from it and add what they exercise.
EndFaceScene nominalScene(double uMm = 0.6);

// Random scene for the given (u, geometry); nuisances drawn from the ranges the vision
// library must handle. `hard` widens them to the limits.
EndFaceScene randomScene(std::mt19937 &rng, double uMm, double rOuterMm, double rMaxMm, bool hard);

// Illumination on a CV_32F frame: a linear gradient (fraction across the half-diagonal, in
// the direction `angle`) and radial vignetting about the frame centre.
void applyIllumination(cv::Mat &f, double gradient, double vignetting, double angle);

// Renders the scene to an 8-bit grey image (blur, noise and JPEG applied).
cv::Mat renderEndFace(const EndFaceScene &s);

// Encodes per the scene (PNG or JPEG at its quality).
std::vector<uint8_t> encodeEndFace(const EndFaceScene &s, const cv::Mat &img);

} // namespace icacam::host
