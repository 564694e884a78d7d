#pragma once
// One physically based scene of the photographic bench, written as a POV-Ray 3.7 scene:
// the upset specimen on the fixture (the end face a disc, the barrel a surface of revolution
// through the FE's free surface, host_tools/photo/barrel_profile.h), metallic finishes with
// gloss, turning grooves and stains as surface normals and textures, a ring of point lights
// around the lens, and a pinhole camera. Units are mm; POV-Ray's y is up, the fixture is the
// plane y = 0 and the specimen's axis is vertical.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "host_tools/photo/barrel_profile.h"

namespace icacam::host::photo {

// A pinhole camera as POV-Ray's perspective camera takes it: the ray through the continuous
// image point (u, v) (pixel i covers [i, i + 1]) is f·forward + (u − W/2)·right + (H/2 − v)·up.
struct PinholeCamera {
    cv::Vec3d location;
    cv::Vec3d right, up, forward; // orthonormal
    double focalPx = 1000;
    int width = 1456, height = 1088;

    // The image position of a point, in pixel-index coordinates (pixel i's centre at i), as
    // the pipeline reports positions. Points behind the camera give NaN.
    cv::Point2d project(const cv::Vec3d &p) const;
};

// A camera at distance wdMm from target along its axis, the axis tilted by tiltDeg from the
// vertical towards the azimuth azimuthDeg (0: +x), the image's right as close to +x as the
// tilt allows.
PinholeCamera cameraLookingAt(const cv::Vec3d &target, double wdMm, double tiltDeg, double azimuthDeg, double focalPx,
                              int width, int height);

// A surface's material: a metal's colour, a diffuse and a glossy (Blinn) part, a mirror part
// that reflects the (dark) surroundings, and the normal perturbations of its finish.
struct SurfaceFinish {
    cv::Vec3d colour{0.7, 0.7, 0.7};
    double diffuse = 0.5;
    double specular = 0.2, roughness = 0.05; // highlight strength and width (POV-Ray's)
    double reflection = 0;
    double grooveDepth = 0, groovePitchMm = 0.1; // turning grooves (0: none)
    double grain = 0, grainMm = 0.2;             // random roughness of the surface
    double grainStretch = 1, grainAxisDeg = 0;   // > 1: marks drawn out along one direction (grinding)
};

struct PhotoScene {
    // The specimen (mm, in its own frame: axis along y, standing on y = 0).
    double faceHeightMm = 7.5;
    double rInnerMm = 5.5; // nominal radius of the original face's edge (before its harmonics)
    double rOuterMm = 6.3; // the contact edge: where the barrel leaves the platen
    double rMaxMm = 7.3;   // the barrel's widest section, at half height
    double innerAmp[2] = {0, 0}, innerPhase[2] = {0, 0}; // R_i (1 + a2 cos(2θ + φ2) + a3 cos(3θ + φ3))
    double ovality = 0, ovalityAxisDeg = 0;              // the whole body scaled by (1 + e, 1/(1 + e)): area kept
    BarrelShape shape;
    double axisXMm = 0, axisZMm = 0; // the axis's foot on the fixture

    SurfaceFinish face, ring, barrel, fixture;
    // Stains on the end face (lubricant residue, oxide): a patchy texture over both zones.
    double stainCover = 0; // 0 … 1, the share of the face they cover (0: none)
    double stainMm = 0.6;  // their size
    SurfaceFinish stain;
    cv::Vec3d patternOffset{0, 0, 0}; // moves every random pattern: a new specimen, not a new law

    std::vector<cv::Vec3d> lights;
    double lightPower = 1; // each light's intensity at fadeMm
    double fadeMm = 60;    // inverse-square falloff: 1 at this distance
    PinholeCamera camera;

    // The equivalent (equal-area) radius of the original face's edge: R_i √(1 + (a2² + a3²)/2).
    double rInnerEqMm() const;
    // The original face's edge at an angle about the axis (the specimen's own frame).
    double innerRadiusAt(double thetaRad) const;
    // A point of the specimen (its own frame: radius, angle, height) in the scene.
    cv::Vec3d toScene(double rMm, double thetaRad, double yMm) const;
    // The barrel's radius at a height (0 … faceHeightMm).
    double barrelRadiusAt(double yMm) const;
};

// A light's direction as the image shows it, from the end face's centre on the specimen's
// axis a: degrees in [0, 360) from the image's +x (columns, rightwards) towards its +y (rows,
// downwards), atan2(−(light − a)·up, (light − a)·right) with the camera's right and up as
// POV-Ray maps them to columns and rows (PinholeCamera).
double lightImageAzimuthDeg(const PhotoScene &s, const cv::Vec3d &light);
// The segment of a ring light split into count (> 0) that a light at that image azimuth
// belongs to: segment k is centred at k · 360/count degrees and holds [−180/count, +180/count)
// about it, so every light is in exactly one.
int lightSegment(double azimuthDeg, int count);

// The scene as a POV-Ray 3.7 source. labels: the same geometry and camera with every zone
// emitting its own grey and no light (face 1, ring 2/3, barrel 1/3, fixture 0): the image
// the truth's projections are checked against.
std::string povraySceneText(const PhotoScene &s, bool labels = false);

} // namespace icacam::host::photo
