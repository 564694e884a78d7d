#pragma once
// One record of the photographic bench: the specimen, the scene that renders it, the sensor
// that develops it and the truth the geometry gives (host_tools/photo/photo_bench.h).
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "host_tools/photo/barrel_profile.h"
#include "host_tools/photo/photo_bench.h"
#include "host_tools/photo/photo_scene.h"
#include "host_tools/photo/photo_sensor.h"

namespace icacam::host::photo {

struct PhotoRecord {
    PhotoCondition condition = PhotoCondition::Straight;
    FaceProfile profile = FaceProfile::Staircase;
    std::string material;
    double n = 0, mu50 = 0, kMpa = 0, reduction = 0.5;
    double uMm = 0; // the ring's equivalent width as modelled (R_o − R_i,eq)
    PhotoScene scene;
    SensorModel sensor;
    double workingDistanceMm = 0; // pinhole to the end face's centre
    double tiltDeg = 0;
    double trueMmPerPx = 0;     // at the end face's centre (the mean of a tilted view's two directions)
    double declaredMmPerPx = 0; // what the manifest says
};

// The geometry as the camera sees it.
struct PhotoTruth {
    cv::Point2d centrePx; // the end face's centre
    double outlinePx = 0; // the equal-area radius of the specimen's outline about it
    double outlineMm = 0; // the same at the end face's scale
    // The equal-area radii of the original face's edge and of the contact edge as projected
    // (their polygons' areas in the image).
    double innerPx = 0, outerPx = 0;
    // Per direction about the centre (kTruthBins, from +u towards +v): the contact edge's and
    // the outline's radius in pixels.
    std::vector<double> outerBinPx, outlineBinPx;
};
constexpr int kTruthBins = 720;

// The specimen, scene, camera and sensor of one record. flatness 1 builds the side through the
// FE's shape; above 1 each of its points lies at ζ^(1/flatness) of the half height from the
// mid-plane instead of ζ: the same radii, the side nearer R_max over more of its height and
// folding more sharply onto the platen (3–4: R_max reached within 1–2 mm of the end face, as
// a parametric barrel or another FE's friction law has it; the outline a close camera sees
// then lies 1–3 % inside R_max rather than the FE's 3–6 %). The draws are the same in any frame.
PhotoRecord drawRecord(PhotoCondition cond, FaceProfile profile, std::mt19937 &rng,
                       const std::vector<BarrelProfile> &profiles, PhotoFrame frame, double flatness = 1);

PhotoTruth projectTruth(const PhotoScene &s);

// The median grey of each zone in the developed photograph (converted to grey): the
// original face, the ring (where it is over 4 px wide), the barrel between the contact edge
// and the outline, and the fixture 1.5–2.5 mm beyond the outline. NaN where a zone has no
// pixel.
struct ZoneLevels {
    double face = 0, ring = 0, barrel = 0, background = 0;
};
ZoneLevels zoneLevels(const cv::Mat &image, const PhotoScene &s, const PhotoTruth &t, double mmPerPx);

} // namespace icacam::host::photo
