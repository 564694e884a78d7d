// Drawing one record of the photographic bench: the specimen from the paper's model and the
// FE, the finishes of its zones for the brightness profile asked for, the ring light, the
// camera and the sensor.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "friction/paper_model.h"
#include "friction/radii_consistency.h"
#include "friction/reduction_corrected_model.h"
#include "host_tools/model_inverse.h"
#include "host_tools/photo/photo_record.h"
#include "host_tools/synth_command.h"

namespace icacam::host::photo {

namespace {

constexpr double kH0Mm = 15;

double uniform(std::mt19937 &rng, double a, double b)
{
    return std::uniform_real_distribution<double>(a, b)(rng);
}

struct Metal {
    const char *name;
    cv::Vec3d rgb; // reflectance, in POV-Ray's order
};
const Metal kMetals[] = {
    {"steel", {0.60, 0.61, 0.63}},
    {"aluminium", {0.82, 0.83, 0.85}},
    {"copper", {0.82, 0.52, 0.38}},
    {"brass", {0.80, 0.68, 0.42}},
};

// A light or dark fixture: bead-blasted aluminium, ground steel, or black anodised.
SurfaceFinish fixtureFinish(std::mt19937 &rng, bool light)
{
    SurfaceFinish f;
    const double grey = light ? uniform(rng, 0.45, 0.8) : uniform(rng, 0.02, 0.07);
    f.colour = {grey, grey, grey * uniform(rng, 0.97, 1.03)};
    f.diffuse = uniform(rng, 0.6, 0.9);
    f.specular = uniform(rng, 0.02, 0.15), f.roughness = uniform(rng, 0.05, 0.2);
    f.grain = uniform(rng, 0.1, 0.4), f.grainMm = uniform(rng, 0.05, 0.3);
    return f;
}

// The finishes of face, ring and barrel for a profile. Under a ring light close to the
// lens a flat face returns its diffuse part and the glossy lobe around the mirror direction;
// a polished one mirrors the dark room; the steep barrel returns little except on its
// shoulder near the contact edge.
void drawFinishes(PhotoScene &s, FaceProfile p, const cv::Vec3d &metal, std::mt19937 &rng)
{
    auto metallic = [&](double diffuse, double specular, double roughness, double reflection) {
        SurfaceFinish f;
        f.colour = metal;
        f.diffuse = diffuse, f.specular = specular, f.roughness = roughness, f.reflection = reflection;
        return f;
    };
    bool lightFixture = uniform(rng, 0, 1) < 0.5;
    switch (p) {
    case FaceProfile::Staircase:
        s.face =
            metallic(uniform(rng, 0.75, 0.95), uniform(rng, 0.2, 0.5), uniform(rng, 0.03, 0.08), uniform(rng, 0, 0.1));
        s.ring = metallic(uniform(rng, 0.28, 0.42), uniform(rng, 0.05, 0.2), uniform(rng, 0.05, 0.1), 0);
        s.barrel = metallic(uniform(rng, 0.25, 0.45), uniform(rng, 0.05, 0.2), uniform(rng, 0.05, 0.1), 0);
        lightFixture = true;
        break;
    case FaceProfile::BrightRing:
        s.face = metallic(uniform(rng, 0.08, 0.2), uniform(rng, 0.3, 0.8), uniform(rng, 0.005, 0.02),
                          uniform(rng, 0.3, 0.6));
        s.ring = metallic(uniform(rng, 0.55, 0.85), uniform(rng, 0.1, 0.3), uniform(rng, 0.04, 0.1), 0);
        s.barrel = metallic(uniform(rng, 0.3, 0.6), uniform(rng, 0.05, 0.3), uniform(rng, 0.04, 0.1), 0);
        break;
    case FaceProfile::DarkRing:
        s.face =
            metallic(uniform(rng, 0.35, 0.6), uniform(rng, 0.1, 0.4), uniform(rng, 0.03, 0.08), uniform(rng, 0, 0.1));
        s.ring = metallic(uniform(rng, 0.04, 0.1), uniform(rng, 0.4, 0.8), uniform(rng, 0.005, 0.015),
                          uniform(rng, 0.3, 0.5));
        s.barrel = metallic(uniform(rng, 0.6, 0.9), uniform(rng, 0.1, 0.3), uniform(rng, 0.05, 0.12), 0);
        break;
    case FaceProfile::DarkBackground:
        s.face =
            metallic(uniform(rng, 0.6, 0.9), uniform(rng, 0.2, 0.5), uniform(rng, 0.03, 0.08), uniform(rng, 0, 0.1));
        s.ring = metallic(uniform(rng, 0.25, 0.45), uniform(rng, 0.05, 0.2), uniform(rng, 0.05, 0.1), 0);
        s.barrel = metallic(uniform(rng, 0.25, 0.5), uniform(rng, 0.05, 0.2), uniform(rng, 0.05, 0.1), 0);
        lightFixture = false;
        break;
    case FaceProfile::LowContrast: {
        const double d = uniform(rng, 0.35, 0.7);
        s.face = metallic(d, uniform(rng, 0.1, 0.3), uniform(rng, 0.04, 0.08), 0);
        s.ring = metallic(d * uniform(rng, 0.8, 1.2), uniform(rng, 0.1, 0.3), uniform(rng, 0.04, 0.08), 0);
        s.barrel = metallic(uniform(rng, 0.3, 0.6), uniform(rng, 0.05, 0.2), uniform(rng, 0.05, 0.1), 0);
        break;
    }
    }
    // The platen's grinding marks imprinted in the face, fine and drawn out along one direction
    // (shallower on a polished face, whose gloss shows every slope); the turning marks (feed
    // 0.05–0.2 mm) on the former lateral surface: rolled onto the platen about as wide, on the
    // barrel pressed together axially.
    s.face.grain = s.face.roughness < 0.03 ? uniform(rng, 0.01, 0.04) : uniform(rng, 0.03, 0.12);
    s.face.grainMm = uniform(rng, 0.01, 0.04), s.face.grainStretch = uniform(rng, 5, 20);
    s.face.grainAxisDeg = uniform(rng, 0, 180);
    const double feed = uniform(rng, 0.05, 0.2);
    s.ring.grooveDepth = uniform(rng, 0.3, 1.3), s.ring.groovePitchMm = feed * uniform(rng, 0.8, 1.2);
    // Seen from above the barrel's grooves crowd below a pixel, where a point-sampling renderer
    // shows moiré a sensor's pixel area would average away: kept shallow there.
    s.barrel.grooveDepth = uniform(rng, 0.1, 0.4), s.barrel.groovePitchMm = feed * uniform(rng, 0.5, 0.7);
    s.fixture = fixtureFinish(rng, lightFixture);
    // Lubricant residue or oxide in patches, on most specimens.
    if (uniform(rng, 0, 1) < 0.6) {
        s.stainCover = uniform(rng, 0.03, 0.15);
        s.stainMm = uniform(rng, 0.3, 1.2);
        s.stain.colour = {uniform(rng, 0.25, 0.4), uniform(rng, 0.22, 0.32), uniform(rng, 0.15, 0.25)};
        s.stain.diffuse = uniform(rng, 0.3, 0.7), s.stain.specular = 0.05, s.stain.roughness = 0.1;
    }
    s.patternOffset = {uniform(rng, -50, 50), uniform(rng, -50, 50), uniform(rng, -50, 50)};
}

// The ring light: N point LEDs on a circle about the lens, in the plane a few mm in front of it.
void drawRingLight(PhotoScene &s, std::mt19937 &rng)
{
    const PinholeCamera &c = s.camera;
    const int count = std::uniform_int_distribution<int>(12, 32)(rng);
    const double radius = uniform(rng, 15, 35), ahead = uniform(rng, 0, 8), phase = uniform(rng, 0, 2 * M_PI);
    s.lights.clear();
    for (int k = 0; k < count; ++k) {
        const double a = phase + 2 * M_PI * k / count;
        s.lights.push_back(c.location + c.forward * ahead + (c.right * std::cos(a) + c.up * std::sin(a)) * radius);
    }
    // Each LED's share; the developed image is exposed automatically, so only the ratio to
    // the inverse-square falloff (1 at the working distance) matters.
    s.fadeMm = cv::norm(c.location - s.toScene(0, 0, s.faceHeightMm));
    s.lightPower = 2.0 / count;
}

SensorModel drawSensor(std::mt19937 &rng)
{
    SensorModel m;
    m.exposureMean = uniform(rng, 0.12, 0.3);
    m.highlightCap = uniform(rng, 0.95, 1.3);
    m.blurSigmaPx = uniform(rng, 0.5, 1.4);
    m.vignetting = uniform(rng, 0.05, 0.35);
    m.fullWellE = uniform(rng, 4000, 15000);
    m.readNoiseE = uniform(rng, 2, 8);
    m.colour = uniform(rng, 0, 1) < 0.5;
    m.jpegQuality = uniform(rng, 0, 1) < 0.7 ? int(uniform(rng, 80, 96)) : 0;
    return m;
}

// The end face's mean scale (mm per px) at its centre: √ of the projection's area ratio.
double scaleAtCentre(const PhotoScene &s)
{
    const double d = 0.5, h = s.faceHeightMm;
    const cv::Vec3d c = s.toScene(0, 0, h);
    const cv::Point2d p0 = s.camera.project(c), px = s.camera.project(c + cv::Vec3d(d, 0, 0)),
                      pz = s.camera.project(c + cv::Vec3d(0, 0, d));
    const double det = std::fabs((px.x - p0.x) * (pz.y - p0.y) - (px.y - p0.y) * (pz.x - p0.x));
    return d / std::sqrt(det);
}

// True when the specimen's outline with a margin for its shadow lies inside the frame.
bool fitsFrame(const PhotoScene &s, double marginMm)
{
    const PinholeCamera &c = s.camera;
    for (int k = 0; k < 72; ++k)
        for (double y : {0.0, s.faceHeightMm / 2, s.faceHeightMm}) {
            const cv::Point2d p = c.project(s.toScene(s.rMaxMm + marginMm, 2 * M_PI * k / 72, y));
            if (!(p.x > 6 && p.y > 6 && p.x < c.width - 7 && p.y < c.height - 7)) return false;
        }
    return true;
}

} // namespace

PhotoRecord drawRecord(PhotoCondition cond, FaceProfile profile, std::mt19937 &rng,
                       const std::vector<BarrelProfile> &profiles, PhotoFrame frame, double flatness)
{
    PhotoRecord rec;
    rec.condition = cond, rec.profile = profile;
    // The specimen: n, μ and K as the other benches draw them; the ring's width from the
    // paper's model (carried to another reduction by the FE du/dr, as the reduction-aware
    // models invert it); the contact edge and the widest section from the FE base.
    PhotoScene &s = rec.scene;
    for (;;) {
        rec.n = uniform(rng, 0.05, 0.5), rec.mu50 = uniform(rng, 0.06, 0.29), rec.kMpa = uniform(rng, 250, 1250);
        rec.reduction = cond == PhotoCondition::Reduction ? uniform(rng, 0.45, 0.55) : 0.5;
        const double u50 = uForMu(friction::PaperModel(), rec.mu50, rec.n);
        rec.uMm = u50 + friction::ReductionCorrectedModel::slopeAt(rec.n, rec.mu50) * (rec.reduction - 0.5);
        if (!friction::feRadiusAt(friction::FeRadius::Outer, rec.n, rec.mu50, rec.reduction, &s.rOuterMm) ||
            !friction::feRMaxAt(rec.n, rec.mu50, rec.reduction, &s.rMaxMm) || rec.uMm < 0.02)
            continue;
        break;
    }
    s.faceHeightMm = kH0Mm * (1 - rec.reduction);
    s.shape = barrelShapeAt(profiles, rec.n, rec.mu50, rec.reduction);
    if (flatness != 1)
        for (double &z : s.shape.zeta) z = std::pow(z, 1 / flatness);
    // The original face's edge is not a circle (the 2nd and 3rd harmonics), the body slightly
    // oval (the bar's anisotropy); the equivalent radii are what the truth gives.
    s.innerAmp[0] = uniform(rng, 0, 0.012), s.innerAmp[1] = uniform(rng, 0, 0.006);
    s.innerPhase[0] = uniform(rng, 0, 2 * M_PI), s.innerPhase[1] = uniform(rng, 0, 2 * M_PI);
    const double riEq = s.rOuterMm - rec.uMm;
    s.rInnerMm = riEq / std::sqrt(1 + 0.5 * (s.innerAmp[0] * s.innerAmp[0] + s.innerAmp[1] * s.innerAmp[1]));
    s.ovality = uniform(rng, 0, 0.008), s.ovalityAxisDeg = uniform(rng, 0, 180);

    const Metal &metal = kMetals[std::uniform_int_distribution<int>(0, 3)(rng)];
    rec.material = metal.name;
    drawFinishes(s, profile, metal.rgb, rng);

    // The camera: a pinhole 45–95 mm above the end face, at a scale that keeps the specimen
    // and its shadow in the frame.
    const bool small = frame == PhotoFrame::Small;
    int width = small ? 640 : frame == PhotoFrame::Large ? 2028 : 1456;
    int height = small ? 480 : frame == PhotoFrame::Large ? 1520 : 1088;
    double pxMmLo = 0.75, pxMmHi = 1.0;
    if (cond == PhotoCondition::LowRes) {
        const bool vga = small || uniform(rng, 0, 1) < 0.5;
        width = vga ? 640 : 1280, height = vga ? 480 : 720;
    }
    const double marginMm = 0.9;
    const double pxMmMax = (std::min(width, height) / 2.0 - 10) / (s.rMaxMm + marginMm);
    double pxMm = pxMmMax * uniform(rng, pxMmLo, pxMmHi);
    rec.workingDistanceMm = uniform(rng, 45, 95);
    const double h = s.faceHeightMm;
    if (cond == PhotoCondition::Tilted) {
        rec.tiltDeg = uniform(rng, 5, 15);
        const double az = uniform(rng, 0, 360);
        for (int tries = 0;; ++tries) {
            const cv::Vec3d target(uniform(rng, -1.2, 1.2), h, uniform(rng, -1.2, 1.2));
            s.camera = cameraLookingAt(target, rec.workingDistanceMm, rec.tiltDeg, az, pxMm * rec.workingDistanceMm,
                                       width, height);
            if (fitsFrame(s, marginMm)) break;
            if (tries > 40) throw std::runtime_error("photo: the specimen does not fit the tilted camera's frame");
            pxMm *= 0.97;
        }
    } else {
        // Straight down over a point beside the specimen: the specimen anywhere in the frame.
        const double rPx = (s.rMaxMm + marginMm) * pxMm;
        const double u = uniform(rng, rPx + 8, std::max(rPx + 9, width - rPx - 8));
        const double v = uniform(rng, rPx + 8, std::max(rPx + 9, height - rPx - 8));
        s.camera = cameraLookingAt({0, h, 0}, rec.workingDistanceMm, 0, 0, pxMm * rec.workingDistanceMm, width, height);
        s.axisXMm = (u + 0.5 - width / 2.0) / pxMm;
        s.axisZMm = -(v + 0.5 - height / 2.0) / pxMm;
        if (!fitsFrame(s, 0.3)) throw std::runtime_error("photo: the specimen left the frame");
    }
    rec.workingDistanceMm = cv::norm(s.camera.location - s.toScene(0, 0, h));
    rec.trueMmPerPx = scaleAtCentre(s);
    rec.declaredMmPerPx = rec.trueMmPerPx;
    // The fixture's scale: a target on the fixture, h farther than the end face.
    if (cond == PhotoCondition::FixtureScale)
        rec.declaredMmPerPx = rec.trueMmPerPx * (rec.workingDistanceMm + h) / rec.workingDistanceMm;
    drawRingLight(s, rng);
    rec.sensor = drawSensor(rng);
    return rec;
}

} // namespace icacam::host::photo
