#include "host_tools/synth_conditions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "calibration/calibration_file.h"
#include "friction/paper_model.h"
#include "friction/radii_consistency.h"
#include "friction/reduction_corrected_model.h"
#include "host_tools/calibration_renderer.h"
#include "host_tools/camera_calibrator.h"
#include "host_tools/end_face_renderer.h"
#include "host_tools/model_inverse.h"
#include "host_tools/specimen_body_renderer.h"
#include "vision/plane_calibration.h"

namespace icacam::host {

namespace fs = std::filesystem;

namespace {

constexpr double kH0Mm = 15, kD0Mm = 10;
constexpr double kInnerEdgeSigmaMm = 0.005, kOuterEdgeSigmaMm = 0.001;
constexpr SynthCondition kAll[] = {SynthCondition::Declared,       SynthCondition::Reduction,
                                   SynthCondition::FixtureScale,   SynthCondition::Tilt,
                                   SynthCondition::CalibratedTilt, SynthCondition::LowRes};

using Rng = std::mt19937;
double uniform(Rng &rng, double a, double b)
{
    return std::uniform_real_distribution<double>(a, b)(rng);
}

// The specimen: n, μ at 50 % (the paper's model: the truth), its true reduction, and the
// nominal radii at that reduction. The ring's width at 50 % comes from the paper's model,
// carried to the true reduction by the FE du/dr (the same carry the reduction-aware models
// invert); the contact edge and the silhouette at 50 % as the development set draws them,
// moved to the true reduction by the FE snapshots' change of R_o and R_max.
struct Specimen {
    double n = 0, mu = 0, kMpa = 0, reduction = 0.5;
    double uMm = 0, rOuterMm = 0, rMaxMm = 0;
};

Specimen drawSpecimen(Rng &rng, double reductionLo, double reductionHi)
{
    const friction::PaperModel paper;
    for (;;) {
        Specimen s;
        s.n = uniform(rng, 0.05, 0.5), s.mu = uniform(rng, 0.06, 0.29);
        s.kMpa = uniform(rng, 250, 1250);
        s.reduction = reductionLo == reductionHi ? reductionLo : uniform(rng, reductionLo, reductionHi);
        const double u50 = uForMu(paper, s.mu, s.n);
        const double rOuter50 = 6.85 - 0.95 * u50 + uniform(rng, -0.05, 0.05);
        const double rMax50 = 5.0 * std::sqrt(2.0) * (1.008 + 0.034 * u50);
        if (s.reduction == 0.5) {
            s.uMm = u50, s.rOuterMm = rOuter50, s.rMaxMm = rMax50;
            return s;
        }
        double ro50, ro, rm50, rm;
        using friction::FeRadius;
        if (!friction::feRadiusAt(FeRadius::Outer, s.n, s.mu, 0.5, &ro50) ||
            !friction::feRadiusAt(FeRadius::Outer, s.n, s.mu, s.reduction, &ro) ||
            !friction::feRMaxAt(s.n, s.mu, 0.5, &rm50) || !friction::feRMaxAt(s.n, s.mu, s.reduction, &rm))
            continue; // no FE snapshot data there: draw again
        s.uMm = u50 + friction::ReductionCorrectedModel::slopeAt(s.n, s.mu) * (s.reduction - 0.5);
        s.rOuterMm = rOuter50 + (ro - ro50);
        s.rMaxMm = rMax50 * rm / rm50;
        if (s.uMm > 0.02) return s;
    }
}

// μ of the specimen from the drawn (equivalent) ring width at its reduction: the paper's
// model at the width carried back to 50 %.
double trueMu(double uEqMm, double n, double reduction)
{
    static const friction::PaperModel paper;
    static const friction::ReductionCorrectedModel carry(paper, "paper_reduction");
    const double u50 = reduction == 0.5 ? uEqMm : carry.uAtBaseReduction({uEqMm, n, 0, kD0Mm, kH0Mm, 0}, reduction);
    return paper.estimate({u50, n, 0, kD0Mm, kH0Mm, 0}).mu;
}

// Re-places the scene in a frame of the given size and scale (the specimen kept inside).
void reframe(EndFaceScene &s, Rng &rng, int width, int height, double mmPerPx, double rMaxRenderMm)
{
    s.width = width, s.height = height, s.mmPerPx = mmPerPx;
    const double rPx = rMaxRenderMm / mmPerPx, margin = 6;
    s.cxPx = uniform(rng, rPx + margin, std::max(rPx + margin + 1, width - rPx - margin));
    s.cyPx = uniform(rng, rPx + margin, std::max(rPx + margin + 1, height - rPx - margin));
}

// One rendered record: the specimen, what the lab declares, what was true, the image.
struct Record {
    Specimen spec;
    double declaredMmPerPx = 0; // 0: not declared (the calibration gives it)
    bool calibrated = false;
    double trueMmPerPx = 0; // at the end face, where the specimen lies
    double tiltDeg = 0, k1 = 0, workingDistanceMm = 0, focalPx = 0;
    double riEq = 0, roEq = 0, rMax = 0;
    EndFaceScene scene;
    cv::Mat pixels;
    cv::Point2d centrePx; // the specimen's axis at the end face, in the image
    CameraModel camera;   // the true camera, for the tilted conditions
};

// A camera of the tilted kind: f 1.0–1.2 × the width, 6–15° or the given tilt, barrel k1.
CameraModel drawTiltedCamera(Rng &rng, int width, int height, double mmPerPxAtFace, double tiltDeg, double k1)
{
    const double f = uniform(rng, 1.0, 1.2) * width;
    const double cx = 0.5 * width + uniform(rng, -15, 15), cy = 0.5 * height + uniform(rng, -15, 15);
    const double az = uniform(rng, 0, 360);
    // The end face at f · scale along the axis; the fixture 7.5 mm farther.
    return tiltedCamera(width, height, f, cx, cy, k1, tiltDeg, az, f * mmPerPxAtFace + 0.5 * kH0Mm);
}

// True when the silhouette's circle (at half height) lies in the frame with a margin.
bool specimenInFrame(const CameraModel &cam, double x, double y, double heightMm, double rMaxMm)
{
    for (int k = 0; k < 36; ++k) {
        const double t = 2 * M_PI * k / 36;
        for (double h : {heightMm, heightMm / 2}) {
            const cv::Point2d p =
                projectFromPlane(cam, x + (rMaxMm + 0.3) * std::cos(t), y + (rMaxMm + 0.3) * std::sin(t), h);
            if (!(p.x > 8 && p.y > 8 && p.x < cam.width - 8 && p.y < cam.height - 8)) return false;
        }
    }
    return true;
}

// The calibrated camera of a set: 12 views of a chessboard and the flat one rendered through
// it, calibrated by `icacam calibrate` into DIR/camera.cal.
struct CalibratedCamera {
    CameraModel cam;
    vision::PlaneCalibration plane; // as calibrated
};

CalibratedCamera makeCalibratedCamera(Rng &rng, const fs::path &dir)
{
    CalibratedCamera c;
    const int w = 1456, h = 1088;
    const double k1 = uniform(rng, -0.35, -0.1);
    c.cam = drawTiltedCamera(rng, w, h, uniform(rng, 0.0150, 0.0190), 12.0, k1);
    const BoardPhotoRenderer r(c.cam);
    // Squares sized so that the board with its margin spans about half the field.
    ChessboardSpec board;
    const double fieldMm = w * std::fabs(c.cam.fixtureTvec[2]) / c.cam.fx;
    board.squareMm = std::round(100 * 0.5 * fieldMm / (board.cols + 3)) / 100;
    const fs::path views = dir / "calibration";
    fs::create_directories(views);
    const auto poses = calibrationPoses(c.cam, board, 12, uint32_t(rng()));
    if (poses.size() < 12) throw std::runtime_error("synth: could not place 12 board views in the frame");
    for (size_t i = 0; i < poses.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "view%02zu.png", i + 1);
        cv::imwrite((views / name).string(),
                    r.chessboard(board, poses[i].first, poses[i].second, uniform(rng, 0.6, 1.0), 2.0, uint32_t(rng())));
    }
    // The flat view: the board on the fixture, centred where the camera's axis meets it.
    cv::Matx33d R;
    cv::Rodrigues(c.cam.fixtureRvec, R);
    const cv::Point2d a = axisOnPlane(c.cam, 0);
    const cv::Vec3d offset(a.x - (board.cols - 1) * board.squareMm / 2, a.y - (board.rows - 1) * board.squareMm / 2, 0);
    cv::imwrite((views / "flat.png").string(),
                r.chessboard(board, c.cam.fixtureRvec, c.cam.fixtureTvec + R * offset, 0.8, 2.0, uint32_t(rng())));
    char spec[64];
    std::snprintf(spec, sizeof spec, "chessboard:%dx%d:%.2f", board.cols, board.rows, board.squareMm);
    const std::string out = (dir / "camera.cal").string();
    // What `icacam calibrate` prints (views used, RMS, the camera) is the set's record of it.
    CameraCalibrationInputs in;
    in.imagesDir = views.string();
    in.board = spec;
    in.flatPhoto = (views / "flat.png").string();
    writeCameraCalibration(in, out);
    calibration::CalibrationFile file;
    if (std::string e = calibration::readCalibrationFile(out, &file); !e.empty()) throw std::runtime_error(e);
    c.plane = file.plane;
    return c;
}

Record renderRecord(SynthCondition cond, Rng &rng, bool hard, const CalibratedCamera *calib)
{
    Record rec;
    const bool reduced = cond == SynthCondition::Reduction;
    rec.spec = drawSpecimen(rng, reduced ? 0.45 : 0.5, reduced ? 0.55 : 0.5);
    const Specimen &sp = rec.spec;
    EndFaceScene s = randomScene(rng, sp.uMm, sp.rOuterMm, sp.rMaxMm, hard);
    // The edge model: on the development set's photographs the pipeline's R_i scatters by
    // 0.005 mm (1 σ) about the truth and R_o by 0.001 mm, about 10 times what this renderer's
    // ideal edges give; drawn per scene, so that "declared" sets read like that set.
    s.edgeOffsetMm[0] = std::normal_distribution<double>(0, kInnerEdgeSigmaMm)(rng);
    s.edgeOffsetMm[1] = std::normal_distribution<double>(0, kOuterEdgeSigmaMm)(rng);
    // A fine scale in the small frame would cut the silhouette off: the larger camera then.
    if (2 * (sp.rMaxMm + 0.8) > s.height * s.mmPerPx) reframe(s, rng, 2028, 1520, s.mmPerPx, sp.rMaxMm);
    const double faceHeight = kH0Mm * (1 - sp.reduction);
    rec.trueMmPerPx = s.mmPerPx;
    rec.declaredMmPerPx = s.mmPerPx;
    cv::Mat img;
    switch (cond) {
    case SynthCondition::Declared:
    case SynthCondition::Reduction: img = renderEndFace(s); break;
    case SynthCondition::FixtureScale: {
        // A pinhole straight down from WD above the fixture: the scale measured on the fixture
        // is WD / (WD − h) times the end face's; the silhouette, at half height, lies between.
        const double wd = uniform(rng, 70, 150);
        rec.workingDistanceMm = wd;
        rec.declaredMmPerPx = s.mmPerPx * wd / (wd - faceHeight);
        const double rMaxRender = sp.rMaxMm * (wd - faceHeight) / (wd - faceHeight / 2);
        EndFaceScene drawn = s;
        drawn.rMaxMm = rMaxRender;
        reframe(drawn, rng, s.width, s.height, s.mmPerPx, sp.rMaxMm);
        s.cxPx = drawn.cxPx, s.cyPx = drawn.cyPx;
        img = renderEndFace(drawn);
        break;
    }
    case SynthCondition::LowRes: {
        const bool vga = uniform(rng, 0, 1) < 0.5;
        const double pxPerMm = vga ? uniform(rng, 19, 30) : uniform(rng, 19, 42);
        reframe(s, rng, vga ? 640 : 1280, vga ? 480 : 720, 1 / pxPerMm, sp.rMaxMm);
        rec.trueMmPerPx = rec.declaredMmPerPx = s.mmPerPx;
        img = renderEndFace(s);
        break;
    }
    case SynthCondition::Tilt:
    case SynthCondition::CalibratedTilt: {
        CameraModel cam;
        cv::Point2d at;
        for (int tries = 0;; ++tries) {
            cam = calib ? calib->cam
                        : drawTiltedCamera(rng, s.width, s.height, s.mmPerPx, uniform(rng, 6, 15),
                                           uniform(rng, -0.35, -0.1));
            const cv::Point2d axis = axisOnPlane(cam, faceHeight);
            at = axis + cv::Point2d(uniform(rng, -1.2, 1.2), uniform(rng, -1.2, 1.2));
            if (specimenInFrame(cam, at.x, at.y, faceHeight, sp.rMaxMm)) break;
            if (tries > 50) throw std::runtime_error("synth: the specimen does not fit the tilted camera's frame");
        }
        rec.tiltDeg = cv::norm(cam.fixtureRvec) * 180 / M_PI; // the rotation's axis lies in the fixture plane
        rec.k1 = cam.k1;
        rec.focalPx = cam.fx;
        rec.workingDistanceMm = std::fabs(cam.fixtureTvec[2]);
        rec.trueMmPerPx = planeScaleAtPoint(cam, at.x, at.y, faceHeight);
        // Uncalibrated, the lab declares the best single number: the true mean scale where the
        // end face lies. Calibrated, the calibration's scale takes its place.
        rec.declaredMmPerPx = calib ? 0 : rec.trueMmPerPx;
        rec.calibrated = calib != nullptr;
        s.width = cam.width, s.height = cam.height;
        s.mmPerPx = rec.trueMmPerPx;
        rec.centrePx = projectFromPlane(cam, at.x, at.y, faceHeight);
        rec.camera = cam;
        img = renderSpecimenBody(cam, s, at.x, at.y, faceHeight);
        break;
    }
    }
    rec.scene = s;
    rec.pixels = img;
    rec.riEq = s.rInnerEqMm(), rec.roEq = s.rOuterEqMm(), rec.rMax = sp.rMaxMm;
    return rec;
}

} // namespace

std::string writeConditionSet(const std::string &dir, const ConditionSetOptions &opt)
{
    if (opt.conditions.empty()) throw std::runtime_error("synth: no condition given");
    const fs::path root(dir);
    fs::create_directories(root / "images");
    const std::string manifestPath = (root / "manifest.csv").string();
    std::ofstream man(manifestPath), truth(root / "truth.csv");
    if (!man || !truth) throw std::runtime_error("cannot write to '" + dir + "'");
    const bool anyCalibrated =
        std::find(opt.conditions.begin(), opt.conditions.end(), SynthCondition::CalibratedTilt) != opt.conditions.end();
    man << "id,image,n,k_mpa,d0_mm,h0_mm,mm_per_px" << (anyCalibrated ? ",calibration" : "") << "\n";
    truth << "id,condition,mu,u_mm,r_inner_mm,r_outer_mm,r_bulge_mm,reduction,u_px,tilt_deg,k1,scale_error,"
             "working_distance_mm,focal_px,width,height,n,blur_px,noise,contrast,camera_truth\n";
    Rng rng(opt.seed);
    CalibratedCamera calib;
    if (anyCalibrated) calib = makeCalibratedCamera(rng, root);
    int written = 0;
    // Round robin over the conditions, so that a mixed set stays mixed when cut short.
    for (int i = 0; i < opt.countPerCondition; ++i)
        for (SynthCondition cond : opt.conditions) {
            Record rec = renderRecord(cond, rng, opt.hard, cond == SynthCondition::CalibratedTilt ? &calib : nullptr);
            char id[48];
            std::snprintf(id, sizeof id, "%s-%04d", conditionName(cond), i + 1);
            const std::string name = std::string(id) + (rec.scene.jpegQuality ? ".jpg" : ".png");
            const auto bytes = encodeEndFace(rec.scene, rec.pixels);
            std::ofstream(root / "images" / name, std::ios::binary)
                .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
            char line[640];
            if (rec.declaredMmPerPx > 0)
                std::snprintf(line, sizeof line, "%s,images/%s,%.4f,%d,10,15,%.7f%s\n", id, name.c_str(), rec.spec.n,
                              int(rec.spec.kMpa), rec.declaredMmPerPx, anyCalibrated ? "," : "");
            else
                std::snprintf(line, sizeof line, "%s,images/%s,%.4f,%d,10,15,,camera.cal\n", id, name.c_str(),
                              rec.spec.n, int(rec.spec.kMpa));
            man << line;
            // The scale error: declared over true, or the calibration's at the end face.
            double scaleError = rec.declaredMmPerPx / rec.trueMmPerPx - 1;
            if (rec.calibrated) {
                vision::PlaneCalibration got = calib.plane, want = toPlaneCalibration(calib.cam);
                got.heightMm = want.heightMm = kH0Mm * (1 - rec.spec.reduction);
                scaleError = vision::planeScaleAt(got, rec.centrePx.x, rec.centrePx.y) /
                                 vision::planeScaleAt(want, rec.centrePx.x, rec.centrePx.y) -
                             1;
            }
            // The true camera as a calibration file: measuring with it declares the condition.
            std::string cameraTruth;
            if (cond == SynthCondition::Tilt || cond == SynthCondition::CalibratedTilt) {
                fs::create_directories(root / "truth");
                cameraTruth = "truth/" + std::string(id) + ".cal";
                calibration::CalibrationFile file;
                file.plane = toPlaneCalibration(rec.camera);
                file.imageWidth = rec.camera.width, file.imageHeight = rec.camera.height;
                file.board = "rendered";
                if (std::string e = calibration::writeCalibrationFile((root / cameraTruth).string(), file); !e.empty())
                    throw std::runtime_error(e);
            }
            const double u = rec.roEq - rec.riEq;
            std::snprintf(
                line, sizeof line,
                "%s,%s,%.5f,%.5f,%.5f,%.5f,%.5f,%.4f,%.2f,%.2f,%.3f,%.4f,%.1f,%.0f,%d,%d,%.4f,%.2f,%.2f,%.1f,%s\n", id,
                conditionName(cond), trueMu(u, rec.spec.n, rec.spec.reduction), u, rec.riEq, rec.roEq, rec.rMax,
                rec.spec.reduction, u / rec.trueMmPerPx, rec.tiltDeg, rec.k1, scaleError, rec.workingDistanceMm,
                rec.focalPx, rec.scene.width, rec.scene.height, rec.spec.n, rec.scene.blurSigmaPx, rec.scene.noiseSigma,
                rec.scene.face - rec.scene.ica, cameraTruth.c_str());
            truth << line;
            ++written;
            if (!opt.quiet && written % 50 == 0) std::cerr << "icacam synth: " << written << " images\n";
        }
    if (!man || !truth) throw std::runtime_error("cannot write to '" + dir + "'");
    return manifestPath;
}

const char *conditionName(SynthCondition c)
{
    switch (c) {
    case SynthCondition::Declared: return "declared";
    case SynthCondition::Reduction: return "reduction";
    case SynthCondition::FixtureScale: return "fixture_scale";
    case SynthCondition::Tilt: return "tilt";
    case SynthCondition::CalibratedTilt: return "calibrated_tilt";
    case SynthCondition::LowRes: return "lowres";
    }
    return "?";
}

std::string conditionNames()
{
    std::string s;
    for (SynthCondition c : kAll) s += (s.empty() ? "" : ",") + std::string(conditionName(c));
    return s;
}

bool parseConditions(const std::string &list, std::vector<SynthCondition> *out)
{
    out->clear();
    if (list == "all") {
        out->assign(std::begin(kAll), std::end(kAll));
        return true;
    }
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        bool found = false;
        for (SynthCondition c : kAll)
            if (name == conditionName(c)) {
                if (std::find(out->begin(), out->end(), c) == out->end()) out->push_back(c);
                found = true;
            }
        if (!found) return false;
        start = comma + 1;
    }
    return !out->empty();
}

} // namespace icacam::host
