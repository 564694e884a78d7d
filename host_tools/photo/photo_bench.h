#pragma once
// The photographic bench: sets of end-face photographs rendered with real light transport
// (POV-Ray) instead of drawn, with the truth taken from the geometry that was rendered
// (docs/photobench.md). `icacam synth --renderer povray` writes them; `icacam measure` and
// `icacam score` judge the pipeline on them as on the drawn sets.
//
// Segment frames (--segments N, PhotoBenchOptions::segments): a device with a segmented LED
// ring lights the N segments in turn and takes a frame under each, beside the full-ring
// photograph (which stays as it is, bit for bit). Segment k holds the LEDs whose direction in
// the image, seen from the end face's centre, lies within ±180/N° of the image azimuth
// k · 360/N°, measured from the image's +x (columns, rightwards) towards its +y (rows,
// downwards): s0 lights from the right, s1 of 4 from below (lightImageAzimuthDeg,
// lightSegment, photo_scene.h). The exposure is locked for the sequence: every segment
// frame is developed at N times the full frame's auto-exposure gain (about 1/N of the light,
// an N times longer exposure), with its own noise; blur, vignetting, tone curve and encoding
// as the full frame's. They are written as images/<id>-s<k>.<ext> (their scenes as
// scenes/<id>-s<k>.pov) and listed in the manifest's last column, segment_images: the N
// paths relative to the manifest's directory, ';'-separated, in segment order. Without
// segments the manifest has no such column.
#include <cstdint>
#include <string>
#include <vector>

namespace icacam::host::photo {

enum class PhotoCondition {
    Straight,     // 50 %, a pinhole straight down, the scale declared exactly at the end face
    Tilted,       // the camera tilted 5–15°, the mean scale at the end face declared
    Reduction,    // pressed to 45–55 %, no final height declared
    FixtureScale, // straight, the scale measured on the fixture (the end face h nearer)
    LowRes,       // 640 × 480 or 1280 × 720 at 19–42 px/mm
};

// The frame: 1456 × 1088 (the reference photographs' size), 640 × 480 (the CI size) or
// 2028 × 1520 (the reference photographs' larger frame). The lowres condition draws its own.
enum class PhotoFrame { Full, Small, Large };

// How bright the zones are against each other: the order of face, ring, barrel and
// background (the last three physical: the finishes are drawn so that the render has it).
enum class FaceProfile {
    Staircase,  // face much brighter than the ring, ring brighter than the barrel, background lighter than the barrel
    BrightRing, // a polished face darker than a matte grooved ring
    DarkRing,   // a burnished ring darker than the barrel's lit shoulder
    DarkBackground, // face over ring over barrel, on a black fixture
    LowContrast,    // face and ring of nearly one brightness; the grooves tell them apart
};

const char *conditionName(PhotoCondition c);
const char *profileName(FaceProfile p);
// A comma-separated list, or "all". False on an unknown name.
bool parseConditions(const std::string &list, std::vector<PhotoCondition> *out);
bool parseProfiles(const std::string &list, std::vector<FaceProfile> *out);
std::string conditionNames();
std::string profileNames();

struct PhotoBenchOptions {
    std::vector<PhotoCondition> conditions{PhotoCondition::Straight};
    std::vector<FaceProfile> profiles; // empty: every profile in turn
    int countPerCondition = 8;
    uint32_t seed = 1;
    int first = 1; // the first record's number (a record is the same at any count)
    PhotoFrame frame = PhotoFrame::Full;
    std::string profilesCsv;                // the FE barrel profiles (barrel_profile.h)
    double barrelFlatness = 1;              // the side's shape flattened about its widest section (photo_record.h)
    std::string povray = "povray";          // the renderer's binary
    std::string quality = "+A0.2 +AM2 +R1"; // POV-Ray's anti-aliasing: adaptive, one level
    bool keepRender = false;                // keep the linear 16-bit render beside the scene
    bool labels = false;                    // also DIR/labels/<id>.png: the zones as flat greys (photo_scene.h)
    int segments = 0;                       // 0, or 2, 3, 4, 6, 8: segment frames too (above)
    // The file format: as the sensor drew it (JPEG 80–95 or PNG), or every photograph PNG
    // (test images) or JPEG (committed sets: a tenth of the bytes; a PNG draw becomes quality 92).
    enum class Encoding { Sensor, Png, Jpeg } encoding = Encoding::Sensor;
    bool quiet = false;
};

// Writes DIR/images/*, DIR/scenes/<id>.pov (the scene each image was rendered from),
// DIR/manifest.csv (what a lab declares) and DIR/truth.csv (per id: the condition, μ of the
// specimen, the radii, the outline the camera sees, the camera, the zones' grey levels).
// Returns the manifest's path. Throws when POV-Ray is missing or fails, or on a segment
// count other than 0, 2, 3, 4, 6, 8.
std::string writePhotoSet(const std::string &dir, const PhotoBenchOptions &opt);

// True when the renderer's binary runs.
bool povrayAvailable(const std::string &povray = "povray");

} // namespace icacam::host::photo
