#include "host_tools/photo/photo_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace icacam::host::photo {

namespace {

std::string vec(const cv::Vec3d &v)
{
    char b[96];
    std::snprintf(b, sizeof b, "<%.6f, %.6f, %.6f>", v[0], v[1], v[2]);
    return b;
}

std::string num(double v)
{
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

cv::Vec3d rotateAbout(const cv::Vec3d &v, const cv::Vec3d &axis, double angleRad)
{
    // Rodrigues' rotation formula.
    const double c = std::cos(angleRad), s = std::sin(angleRad);
    return v * c + axis.cross(v) * s + axis * (axis.dot(v) * (1 - c));
}

// The ovality's linear map in the fixture plane, (x, z) → (x', z').
void ovalityMatrix(const PhotoScene &s, double m[2][2])
{
    const double a = s.ovalityAxisDeg * M_PI / 180, c = std::cos(a), sn = std::sin(a);
    const double k1 = 1 + s.ovality, k2 = 1 / (1 + s.ovality);
    // R(a) · diag(k1, k2) · R(−a)
    m[0][0] = c * c * k1 + sn * sn * k2;
    m[0][1] = c * sn * (k1 - k2);
    m[1][0] = m[0][1];
    m[1][1] = sn * sn * k1 + c * c * k2;
}

// A texture of one finish; normalText adds the surface's own normal perturbation.
std::string texture(const std::string &name, const SurfaceFinish &f, const std::string &normalText)
{
    std::ostringstream o;
    o << "#declare " << name << " = texture {\n"
      << "  pigment { rgb " << vec(f.colour) << " }\n";
    if (!normalText.empty()) o << "  " << normalText << "\n";
    o << "  finish { ambient 0 emission 0 diffuse " << num(f.diffuse) << " specular " << num(f.specular)
      << " roughness " << num(f.roughness) << " metallic";
    if (f.reflection > 0) o << " reflection { " << num(f.reflection) << " metallic }";
    o << " }\n}\n";
    return o.str();
}

// A zone of the label image: its own grey, emitted, lit by nothing.
std::string labelTexture(const std::string &name, double grey)
{
    return "#declare " + name + " = texture { pigment { rgb " + num(grey) +
           " } finish { ambient 0 emission 1 diffuse 0 specular 0 } }\n";
}

std::string grainNormal(const SurfaceFinish &f, const cv::Vec3d &offset)
{
    if (f.grain <= 0) return "";
    const std::string scale = f.grainStretch > 1 ? "<" + num(f.grainMm * f.grainStretch) + ", " + num(f.grainMm) +
                                                       ", " + num(f.grainMm) + "> rotate y * " + num(f.grainAxisDeg)
                                                 : num(f.grainMm);
    return "normal { bumps " + num(f.grain) + " scale " + scale + " translate " + vec(offset) + " }";
}

// The zones' textures. The immigrated ring is former lateral surface: its turning grooves,
// rolled onto the platen, are concentric rings; on the barrel they run round it.
std::string materials(const PhotoScene &s)
{
    std::ostringstream o;
    const double h = s.faceHeightMm;
    const cv::Vec3d off = s.patternOffset;
    o << texture("FaceClean", s.face, grainNormal(s.face, off));
    std::string ringNormal = grainNormal(s.ring, off);
    if (s.ring.grooveDepth > 0)
        ringNormal = "normal { onion " + num(s.ring.grooveDepth) + " scallop_wave scale " + num(s.ring.groovePitchMm) +
                     " translate <0, " + num(h) + ", 0> }";
    o << texture("RingClean", s.ring, ringNormal);
    std::string barrelNormal = grainNormal(s.barrel, off);
    if (s.barrel.grooveDepth > 0)
        barrelNormal = "normal { gradient y " + num(s.barrel.grooveDepth) + " sine_wave scale " +
                       num(s.barrel.groovePitchMm) + " translate " + vec(off) + " }";
    o << texture("Barrel", s.barrel, barrelNormal);
    o << texture("Stain", s.stain, grainNormal(s.stain, off));
    const char *zones[] = {"Face", "Ring"};
    for (const char *z : zones) {
        if (s.stainCover > 0) {
            // bozo is roughly uniform on 0 … 1: the patches above 1 − cover.
            const double from = 1 - s.stainCover;
            o << "#declare " << z << " = texture { bozo turbulence 0.6 texture_map { [0 " << z << "Clean] ["
              << num(from) << " " << z << "Clean] [" << num(std::min(1.0, from + 0.02)) << " Stain] [1 Stain] }\n"
              << "  scale " << num(s.stainMm) << " translate " << vec(off * 1.7) << " }\n";
        } else
            o << "#declare " << z << " = texture { " << z << "Clean }\n";
    }
    o << texture("Fixture", s.fixture, grainNormal(s.fixture, off));

    return o.str();
}

} // namespace

cv::Point2d PinholeCamera::project(const cv::Vec3d &p) const
{
    const cv::Vec3d d = p - location;
    const double depth = d.dot(forward);
    if (!(depth > 1e-9)) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    const double u = width / 2.0 + focalPx * d.dot(right) / depth;
    const double v = height / 2.0 - focalPx * d.dot(up) / depth;
    return {u - 0.5, v - 0.5};
}

PinholeCamera cameraLookingAt(const cv::Vec3d &target, double wdMm, double tiltDeg, double azimuthDeg, double focalPx,
                              int width, int height)
{
    // Straight down, the image's right is +x and its up +z (POV-Ray's left-handed frame seen
    // from above, not mirrored); the tilt turns all three about a horizontal axis.
    PinholeCamera c;
    c.focalPx = focalPx, c.width = width, c.height = height;
    c.right = {1, 0, 0}, c.up = {0, 0, 1}, c.forward = {0, -1, 0};
    const double az = azimuthDeg * M_PI / 180;
    const cv::Vec3d axis(-std::sin(az), 0, std::cos(az));
    const double t = tiltDeg * M_PI / 180;
    c.right = rotateAbout(c.right, axis, t);
    c.up = rotateAbout(c.up, axis, t);
    c.forward = rotateAbout(c.forward, axis, t);
    c.location = target - c.forward * wdMm;
    return c;
}

double PhotoScene::innerRadiusAt(double thetaRad) const
{
    return rInnerMm * (1 + innerAmp[0] * std::cos(2 * thetaRad + innerPhase[0]) +
                       innerAmp[1] * std::cos(3 * thetaRad + innerPhase[1]));
}

double PhotoScene::rInnerEqMm() const
{
    return rInnerMm * std::sqrt(1 + 0.5 * (innerAmp[0] * innerAmp[0] + innerAmp[1] * innerAmp[1]));
}

cv::Vec3d PhotoScene::toScene(double rMm, double thetaRad, double yMm) const
{
    double m[2][2];
    ovalityMatrix(*this, m);
    const double x = rMm * std::cos(thetaRad), z = rMm * std::sin(thetaRad);
    return {m[0][0] * x + m[0][1] * z + axisXMm, yMm, m[1][0] * x + m[1][1] * z + axisZMm};
}

double PhotoScene::barrelRadiusAt(double yMm) const
{
    const double half = faceHeightMm / 2;
    const double zeta = std::fabs(yMm - half) / half;
    const size_t k = shape.zeta.size();
    double s = shape.s.back();
    for (size_t i = 1; i < k; ++i)
        if (zeta <= shape.zeta[i]) {
            const double span = shape.zeta[i] - shape.zeta[i - 1];
            const double t = span > 0 ? (zeta - shape.zeta[i - 1]) / span : 0;
            s = shape.s[i - 1] + t * (shape.s[i] - shape.s[i - 1]);
            break;
        }
    return rOuterMm + s * (rMaxMm - rOuterMm);
}

double lightImageAzimuthDeg(const PhotoScene &s, const cv::Vec3d &light)
{
    const cv::Vec3d d = light - s.toScene(0, 0, s.faceHeightMm);
    const double deg = std::atan2(-d.dot(s.camera.up), d.dot(s.camera.right)) * 180 / M_PI;
    return deg < 0 ? deg + 360 : deg;
}

int lightSegment(double azimuthDeg, int count)
{
    const double width = 360.0 / count;
    const int k = int(std::floor((azimuthDeg + width / 2) / width)) % count;
    return k < 0 ? k + count : k;
}

std::string povraySceneText(const PhotoScene &s, bool labels)
{
    std::ostringstream o;
    const PinholeCamera &c = s.camera;
    const double h = s.faceHeightMm;
    o << "// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).\n"
      << "#version 3.7;\n"
      << "global_settings { assumed_gamma 1.0 max_trace_level 4 }\n"
      << "background { rgb 0 }\n"
      << "camera { perspective location " << vec(c.location) << "\n"
      << "  direction " << vec(c.forward * c.focalPx) << "\n"
      << "  right " << vec(c.right * double(c.width)) << "\n"
      << "  up " << vec(c.up * double(c.height)) << " }\n";
    for (const cv::Vec3d &l : labels ? std::vector<cv::Vec3d>{} : s.lights)
        o << "light_source { " << vec(l) << " rgb " << num(s.lightPower) << " fade_distance " << num(s.fadeMm)
          << " fade_power 2 }\n";

    if (labels)
        o << labelTexture("Face", 1) << labelTexture("Ring", 2.0 / 3) << labelTexture("Barrel", 1.0 / 3)
          << labelTexture("Fixture", 0);
    else
        o << materials(s);
    // The original face's edge: R_i(θ) with its 2nd and 3rd harmonics, in the specimen's frame.
    const std::string theta = "atan2(z, x)";
    o << "#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - " << num(s.rInnerMm) << " * (1 + "
      << num(s.innerAmp[0]) << " * cos(2 * " << theta << " + " << num(s.innerPhase[0]) << ") + " << num(s.innerAmp[1])
      << " * cos(3 * " << theta << " + " << num(s.innerPhase[1]) << ")), 0, 1) }\n";

    // The body: the end face (a disc at the final height) and the barrel through the FE's free
    // surface, mirrored about the mid-plane, from the contact edge at the top to the one on the
    // fixture.
    o << "union {\n"
      << "  disc { <0, " << num(h) << ", 0>, y, " << num(s.rOuterMm)
      << "\n    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } "
         "}\n";
    const size_t k = s.shape.zeta.size();
    o << "  lathe { linear_spline " << 2 * k - 1 << "\n";
    auto point = [&](size_t i, int side) {
        const double r = s.rOuterMm + s.shape.s[i] * (s.rMaxMm - s.rOuterMm);
        const double y = h / 2 + side * s.shape.zeta[i] * h / 2;
        o << "    <" << num(r) << ", " << num(y) << ">\n";
    };
    for (size_t i = k; i-- > 0;) point(i, +1);
    for (size_t i = 1; i < k; ++i) point(i, -1);
    o << "    texture { Barrel } }\n";
    double m[2][2];
    ovalityMatrix(s, m);
    o << "  matrix <" << num(m[0][0]) << ", 0, " << num(m[1][0]) << ", 0, 1, 0, " << num(m[0][1]) << ", 0, "
      << num(m[1][1]) << ", " << num(s.axisXMm) << ", 0, " << num(s.axisZMm) << ">\n}\n";
    o << "plane { y, 0 texture { Fixture } }\n";
    return o.str();
}

} // namespace icacam::host::photo
