#include "host_tools/photo/photo_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "friction/paper_model.h"
#include "friction/reduction_corrected_model.h"
#include "host_tools/photo/photo_record.h"

namespace icacam::host::photo {

namespace fs = std::filesystem;

namespace {

constexpr PhotoCondition kConditions[] = {PhotoCondition::Straight, PhotoCondition::Tilted, PhotoCondition::Reduction,
                                          PhotoCondition::FixtureScale, PhotoCondition::LowRes};
constexpr FaceProfile kProfiles[] = {FaceProfile::Staircase, FaceProfile::BrightRing, FaceProfile::DarkRing,
                                     FaceProfile::DarkBackground, FaceProfile::LowContrast};

template <typename T, size_t N>
bool parseList(const std::string &list, const T (&all)[N], const char *(*name)(T), std::vector<T> *out)
{
    out->clear();
    if (list == "all") {
        out->assign(std::begin(all), std::end(all));
        return true;
    }
    std::stringstream in(list);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto it = std::find_if(std::begin(all), std::end(all), [&](T v) { return item == name(v); });
        if (it == std::end(all)) return false;
        if (std::find(out->begin(), out->end(), *it) == out->end()) out->push_back(*it);
    }
    return !out->empty();
}

template <typename T, size_t N> std::string names(const T (&all)[N], const char *(*name)(T))
{
    std::string s;
    for (T v : all) s += (s.empty() ? "" : ",") + std::string(name(v));
    return s;
}

std::string shellQuote(const std::string &s)
{
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

std::string tail(const fs::path &p, size_t chars)
{
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    const std::string t = s.str();
    return t.size() > chars ? t.substr(t.size() - chars) : t;
}

constexpr int kPovrayStartAttempts = 5;

// Added to a record's seed parts for its segment frames' noise: a stream apart from the one
// the record and its full frame draw from.
constexpr uint32_t kSegmentNoiseSeed = 0x5e6f7a01;

bool validSegmentCount(int n)
{
    return n == 0 || n == 2 || n == 3 || n == 4 || n == 6 || n == 8;
}

// Renders scenes/<id>.pov into scenes/<id>.png (16-bit, linear): POV-Ray writes only below
// its working directory (Debian's povray.conf), so it runs in scenes/.
cv::Mat render(const fs::path &scenes, const std::string &id, const PinholeCamera &cam, const PhotoBenchOptions &opt,
               const std::string &quality)
{
    const std::string cmd = "cd " + shellQuote(scenes.string()) + " && " + opt.povray + " +I" + id + ".pov +O" + id +
                            ".png +W" + std::to_string(cam.width) + " +H" + std::to_string(cam.height) +
                            " +FN16 File_Gamma=1.0 +WT1 -D -V " + quality + " > " + id + ".log 2>&1";
    const fs::path png = scenes / (id + ".png");
    // POV-Ray gives its render thread a fixed time to start and gives up on a busy machine
    // ("Timed out waiting for worker thread startup", vfeInitializeTimedOut): nothing was
    // rendered, so it is run again, a few times.
    int rc = 0;
    for (int attempt = 0; attempt < kPovrayStartAttempts; ++attempt) {
        rc = std::system(cmd.c_str());
        if (rc == 0 ||
            tail(scenes / (id + ".log"), 800).find("Timed out waiting for worker thread startup") == std::string::npos)
            break;
    }
    cv::Mat img = cv::imread(png.string(), cv::IMREAD_UNCHANGED);
    if (rc != 0 || img.empty())
        throw std::runtime_error("povray failed on " + (scenes / (id + ".pov")).string() + ":\n" +
                                 tail(scenes / (id + ".log"), 800));
    fs::remove(scenes / (id + ".log"));
    if (!opt.keepRender) fs::remove(png);
    return img;
}

void writeText(const fs::path &p, const std::string &text)
{
    std::ofstream f(p);
    f << text;
    if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

void writeBytes(const fs::path &p, const std::vector<uint8_t> &bytes)
{
    std::ofstream f(p, std::ios::binary);
    f.write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
    if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

// μ of the specimen from the modelled ring width at its reduction: the paper's model at the
// width carried back to 50 % (as the drawn benches' truth).
double trueMu(double uMm, double n, double reduction)
{
    static const friction::PaperModel paper;
    static const friction::ReductionCorrectedModel carry(paper, "paper_reduction");
    const double u50 = reduction == 0.5 ? uMm : carry.uAtBaseReduction({uMm, n, 0, 10, 15, 0}, reduction);
    return paper.estimate({u50, n, 0, 10, 15, 0}).mu;
}

} // namespace

const char *conditionName(PhotoCondition c)
{
    switch (c) {
    case PhotoCondition::Straight: return "straight";
    case PhotoCondition::Tilted: return "tilted";
    case PhotoCondition::Reduction: return "reduction";
    case PhotoCondition::FixtureScale: return "fixture_scale";
    case PhotoCondition::LowRes: return "lowres";
    }
    return "?";
}

const char *profileName(FaceProfile p)
{
    switch (p) {
    case FaceProfile::Staircase: return "staircase";
    case FaceProfile::BrightRing: return "bright_ring";
    case FaceProfile::DarkRing: return "dark_ring";
    case FaceProfile::DarkBackground: return "dark_background";
    case FaceProfile::LowContrast: return "low_contrast";
    }
    return "?";
}

bool parseConditions(const std::string &list, std::vector<PhotoCondition> *out)
{
    return parseList(list, kConditions, conditionName, out);
}

bool parseProfiles(const std::string &list, std::vector<FaceProfile> *out)
{
    return parseList(list, kProfiles, profileName, out);
}

std::string conditionNames()
{
    return names(kConditions, conditionName);
}

std::string profileNames()
{
    return names(kProfiles, profileName);
}

bool povrayAvailable(const std::string &povray)
{
    return std::system((povray + " --version > /dev/null 2>&1").c_str()) == 0;
}

std::string writePhotoSet(const std::string &dir, const PhotoBenchOptions &opt)
{
    if (opt.conditions.empty()) throw std::runtime_error("photo: no condition given");
    if (!validSegmentCount(opt.segments))
        throw std::runtime_error("photo: " + std::to_string(opt.segments) + " segments (0, 2, 3, 4, 6 or 8)");
    if (!povrayAvailable(opt.povray))
        throw std::runtime_error("'" + opt.povray + "' does not run: install POV-Ray (apt-get install povray)");
    const std::vector<BarrelProfile> table = readBarrelProfiles(opt.profilesCsv);
    const std::vector<FaceProfile> profiles =
        opt.profiles.empty() ? std::vector<FaceProfile>(std::begin(kProfiles), std::end(kProfiles)) : opt.profiles;
    const fs::path root(dir);
    fs::create_directories(root / "images");
    fs::create_directories(root / "scenes");
    const std::string manifestPath = (root / "manifest.csv").string();
    std::ofstream man(manifestPath), truth(root / "truth.csv");
    if (!man || !truth) throw std::runtime_error("cannot write to '" + dir + "'");
    man << "id,image,n,k_mpa,d0_mm,h0_mm,mm_per_px" << (opt.segments > 0 ? ",segment_images" : "") << "\n";
    truth << "id,condition,mu,u_mm,r_inner_mm,r_outer_mm,r_bulge_mm,reduction,u_px,tilt_deg,k1,scale_error,"
             "working_distance_mm,focal_px,width,height,n,blur_px,noise,contrast,camera_truth,"
             "profile,material,outline_mm,outline_px,cx_px,cy_px,mm_per_px_true,face_level,ring_level,barrel_level,"
             "background_level,lights,jpeg_quality,colour,r_inner_px,r_outer_px\n";
    for (int i = opt.first; i < opt.first + opt.countPerCondition; ++i)
        for (PhotoCondition cond : opt.conditions) {
            // Each record from its own seed: the same record whatever the count or the first.
            std::seed_seq seq{opt.seed, uint32_t(cond), uint32_t(i)};
            std::mt19937 rng(seq);
            const FaceProfile profile = profiles[size_t(i - 1) % profiles.size()];
            PhotoRecord rec = drawRecord(cond, profile, rng, table, opt.frame, opt.barrelFlatness);
            if (opt.encoding == PhotoBenchOptions::Encoding::Png) rec.sensor.jpegQuality = 0;
            if (opt.encoding == PhotoBenchOptions::Encoding::Jpeg && rec.sensor.jpegQuality == 0)
                rec.sensor.jpegQuality = 92;
            char id[48];
            std::snprintf(id, sizeof id, "%s-%04d", conditionName(cond), i);
            writeText(root / "scenes" / (std::string(id) + ".pov"), povraySceneText(rec.scene));
            const cv::Mat linear = render(root / "scenes", id, rec.scene.camera, opt, opt.quality);
            if (opt.labels) {
                // Fine anti-aliasing: the zones' areas are what the label image is for.
                const std::string stem = std::string(id) + "-labels";
                writeText(root / "scenes" / (stem + ".pov"), povraySceneText(rec.scene, true));
                cv::Mat grey, lab = render(root / "scenes", stem, rec.scene.camera, opt, "+A0.01 +AM2 +R3");
                cv::extractChannel(lab, grey, 1);
                grey.convertTo(grey, CV_8U, 255.0 / 65535);
                fs::create_directories(root / "labels");
                cv::imwrite((root / "labels" / (std::string(id) + ".png")).string(), grey);
            }
            std::mt19937 noise(rng());
            double gain = 0;
            const cv::Mat photo = developPhoto(linear, rec.sensor, noise, 0, &gain);
            const char *ext = rec.sensor.jpegQuality ? ".jpg" : ".png";
            const std::string name = std::string(id) + ext;
            const auto bytes = encodePhoto(photo, rec.sensor);
            std::ofstream(root / "images" / name, std::ios::binary)
                .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));

            // The segment frames (photo_bench.h): the same scene with one segment's LEDs, the
            // exposure locked at N times the full frame's.
            std::string segmentImages;
            if (opt.segments > 0) {
                std::vector<std::vector<cv::Vec3d>> lit(size_t(opt.segments));
                for (const cv::Vec3d &l : rec.scene.lights)
                    lit[size_t(lightSegment(lightImageAzimuthDeg(rec.scene, l), opt.segments))].push_back(l);
                for (int k = 0; k < opt.segments; ++k) {
                    const std::string stem = std::string(id) + "-s" + std::to_string(k);
                    PhotoScene segment = rec.scene;
                    segment.lights = lit[size_t(k)];
                    writeText(root / "scenes" / (stem + ".pov"), povraySceneText(segment));
                    const cv::Mat segLinear = render(root / "scenes", stem, segment.camera, opt, opt.quality);
                    std::seed_seq segSeq{opt.seed, uint32_t(cond), uint32_t(i), kSegmentNoiseSeed, uint32_t(k)};
                    std::mt19937 segNoise(segSeq);
                    const cv::Mat segPhoto = developPhoto(segLinear, rec.sensor, segNoise, gain * opt.segments);
                    writeBytes(root / "images" / (stem + ext), encodePhoto(segPhoto, rec.sensor));
                    segmentImages += (k ? ";images/" : ",images/") + stem + ext;
                }
            }

            const PhotoScene &s = rec.scene;
            const PhotoTruth t = projectTruth(s);
            const ZoneLevels z = zoneLevels(photo, s, t, rec.trueMmPerPx);
            const double riEq = s.rInnerEqMm(), u = s.rOuterMm - riEq;
            char line[1024];
            std::snprintf(line, sizeof line, "%s,images/%s,%.4f,%d,10,15,%.7f", id, name.c_str(), rec.n, int(rec.kMpa),
                          rec.declaredMmPerPx);
            man << line << segmentImages << "\n";
            std::snprintf(line, sizeof line,
                          "%s,%s,%.5f,%.5f,%.5f,%.5f,%.5f,%.4f,%.2f,%.2f,0,%.4f,%.2f,%.1f,%d,%d,%.4f,%.2f,%.2f,%.1f,,"
                          "%s,%s,%.5f,%.2f,%.2f,%.2f,%.7f,%.1f,%.1f,%.1f,%.1f,%zu,%d,%d,%.3f,%.3f\n",
                          id, conditionName(cond), trueMu(u, rec.n, rec.reduction), u, riEq, s.rOuterMm, s.rMaxMm,
                          rec.reduction, u / rec.trueMmPerPx, rec.tiltDeg, rec.declaredMmPerPx / rec.trueMmPerPx - 1,
                          rec.workingDistanceMm, s.camera.focalPx, s.camera.width, s.camera.height, rec.n,
                          rec.sensor.blurSigmaPx, rec.sensor.noiseAtMidGrey(), z.face - z.ring, profileName(profile),
                          rec.material.c_str(), t.outlinePx * rec.trueMmPerPx, t.outlinePx, t.centrePx.x, t.centrePx.y,
                          rec.trueMmPerPx, z.face, z.ring, z.barrel, z.background, s.lights.size(),
                          rec.sensor.jpegQuality, rec.sensor.colour ? 1 : 0, t.innerPx, t.outerPx);
            truth << line;
            if (!opt.quiet) std::cerr << "icacam synth: " << id << " (" << profileName(profile) << ")\n";
        }
    if (!man || !truth) throw std::runtime_error("cannot write to '" + dir + "'");
    return manifestPath;
}

} // namespace icacam::host::photo
