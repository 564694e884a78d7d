#include "host_tools/camera_calibrator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "host_tools/image_file.h"
#include "host_tools/manifest.h"
#include "vision/plane_calibration.h"

namespace icacam::host {

namespace fs = std::filesystem;

namespace {

constexpr int kMinViews = 5;
// A view stands out when its RMS reprojection error exceeds both of these: the factor over
// the median view's keeps a uniformly soft set (every view a little worse, all consistent),
// the floor keeps sharp sets' ordinary spread (0.02–0.1 px) from dropping good views.
constexpr double kDropFactor = 4.0;
constexpr double kDropFloorPx = 0.3;

struct Board {
    bool circles = false;
    cv::Size size;
    double pitchMm = 0;
    std::vector<cv::Point3f> object() const
    {
        std::vector<cv::Point3f> pts;
        for (int j = 0; j < size.height; ++j)
            for (int i = 0; i < size.width; ++i) pts.emplace_back(float(i * pitchMm), float(j * pitchMm), 0.f);
        return pts;
    }
};

// Reads --board's spec; returns an empty string or why it is not one.
std::string parseBoard(const std::string &spec, Board *b)
{
    const size_t c1 = spec.find(':'), c2 = spec.rfind(':'), x = spec.find('x', c1 + 1);
    const std::string expected =
        "bad --board '" + spec + "': expected chessboard:COLSxROWS:SQUARE_MM or circles:COLSxROWS:SPACING_MM";
    if (c1 == std::string::npos || c2 == c1 || x == std::string::npos || x > c2) return expected;
    const std::string kind = spec.substr(0, c1);
    if (kind != "chessboard" && kind != "circles") return expected;
    b->circles = kind == "circles";
    double cols, rows;
    if (!parseNumber(spec.substr(c1 + 1, x - c1 - 1), &cols) || !parseNumber(spec.substr(x + 1, c2 - x - 1), &rows) ||
        !parseNumber(spec.substr(c2 + 1), &b->pitchMm))
        return expected;
    if (cols < 3 || rows < 3 || cols > 100 || rows > 100 || cols != std::floor(cols) || rows != std::floor(rows) ||
        !(b->pitchMm > 0))
        return "bad --board '" + spec + "': at least 3×3 points and a positive pitch";
    b->size = {int(cols), int(rows)};
    return "";
}

// Edge width of a circle grid's dots (pixels, about the 10–90 % rise like OpenCV's
// chessboard sharpness): per dot, the step from the dot's centre to the paper around it
// divided by the steepest slope on its edge; the median over the dots. A blurred dot
// keeps its centroid but shifts it under perspective, so soft views are refused alike.
double circleGridEdgeWidth(const cv::Mat &gray, const cv::Size &size, const std::vector<cv::Point2f> &pts)
{
    std::vector<double> pitches;
    for (int j = 0; j < size.height; ++j)
        for (int i = 0; i + 1 < size.width; ++i)
            pitches.push_back(cv::norm(pts[size_t(j * size.width + i + 1)] - pts[size_t(j * size.width + i)]));
    std::nth_element(pitches.begin(), pitches.begin() + long(pitches.size() / 2), pitches.end());
    const double pitch = pitches[pitches.size() / 2];
    const int half = std::max(3, int(0.48 * pitch));
    std::vector<double> widths;
    for (const cv::Point2f &p : pts) {
        const cv::Rect box(int(std::lround(p.x)) - half, int(std::lround(p.y)) - half, 2 * half + 1, 2 * half + 1);
        if ((box & cv::Rect(0, 0, gray.cols, gray.rows)) != box) continue;
        cv::Mat win, gx, gy, mag;
        gray(box).convertTo(win, CV_32F);
        cv::Sobel(win, gx, CV_32F, 1, 0, 3);
        cv::Sobel(win, gy, CV_32F, 0, 1, 3);
        cv::magnitude(gx, gy, mag);
        double maxGrad = 0;
        cv::minMaxLoc(mag(cv::Rect(1, 1, win.cols - 2, win.rows - 2)), nullptr, &maxGrad);
        // Dot level at the centre, paper level on the window's rim.
        const float dot = win.at<float>(half, half);
        std::vector<float> rim;
        for (int k = 0; k < win.cols; ++k)
            rim.insert(rim.end(), {win.at<float>(0, k), win.at<float>(win.rows - 1, k), win.at<float>(k, 0),
                                   win.at<float>(k, win.cols - 1)});
        std::nth_element(rim.begin(), rim.begin() + long(rim.size() / 2), rim.end());
        const double contrast = double(rim[rim.size() / 2]) - double(dot);
        if (maxGrad > 0 && contrast > 0) widths.push_back(contrast / (maxGrad / 8)); // Sobel gain 8
    }
    if (widths.empty()) return 1e9;
    std::nth_element(widths.begin(), widths.begin() + long(widths.size() / 2), widths.end());
    return widths[widths.size() / 2];
}

// Finds the board; returns an empty string or why the view is unusable.
std::string detect(const cv::Mat &gray, const Board &b, double maxBlur, std::vector<cv::Point2f> *pts, double *blur)
{
    *blur = 0;
    if (b.circles) {
        if (!cv::findCirclesGrid(gray, b.size, *pts, cv::CALIB_CB_SYMMETRIC_GRID))
            return "circle grid not found (blurred, cut off, or not " + std::to_string(b.size.width) + "x" +
                   std::to_string(b.size.height) + " dots?)";
        *blur = circleGridEdgeWidth(gray, b.size, *pts);
        if (maxBlur > 0 && !(*blur <= maxBlur)) {
            char msg[120];
            std::snprintf(msg, sizeof msg, "blurred (dot edge width %.1f px > %.1f px)", *blur, maxBlur);
            return msg;
        }
        return "";
    }
    if (!cv::findChessboardCorners(gray, b.size, *pts, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
        return "chessboard not found (blurred, cut off, or not " + std::to_string(b.size.width) + "x" +
               std::to_string(b.size.height) + " inner corners?)";
    // Edge rise width across the board's edges (OpenCV's estimate, pixels): a soft view
    // moves corners by more than its scatter shows.
    const cv::Scalar sharp = cv::estimateChessboardSharpness(gray, b.size, *pts);
    *blur = sharp[0];
    if (maxBlur > 0 && !(sharp[0] <= maxBlur)) {
        char msg[120];
        std::snprintf(msg, sizeof msg, "blurred (edge width %.1f px > %.1f px)", sharp[0], maxBlur);
        return msg;
    }
    cv::cornerSubPix(gray, *pts, {5, 5}, {-1, -1},
                     cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 50, 1e-4));
    return "";
}

bool isImage(const fs::path &p)
{
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const char *x : {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".bmp", ".pgm", ".pnm"})
        if (e == x) return true;
    return false;
}

// The board in every usable photo, in file-name order.
struct BoardViews {
    std::vector<std::vector<cv::Point3f>> objectPts;
    std::vector<std::vector<cv::Point2f>> imagePts;
    std::vector<std::string> used; // file names
    cv::Size imageSize;
};

// Finds the board in every image file of the folder; the photos left out go to *rejected.
BoardViews findBoardViews(const std::vector<fs::path> &files, const Board &board, double maxBlur,
                          std::ostringstream *rejected)
{
    BoardViews v;
    for (const fs::path &p : files) {
        LumaImage img;
        std::string why = loadLuma(p.string(), &img);
        if (why.empty() && v.imageSize.width && img.luma.size() != v.imageSize)
            why = "size differs from the first view";
        std::vector<cv::Point2f> pts;
        double blur = 0;
        if (why.empty()) why = detect(img.luma, board, maxBlur, &pts, &blur);
        if (!why.empty()) {
            *rejected << "  " << p.filename().string() << ": " << why << "\n";
            continue;
        }
        if (!v.imageSize.width) v.imageSize = img.luma.size();
        v.objectPts.push_back(board.object());
        v.imagePts.push_back(pts);
        v.used.push_back(p.filename().string());
    }
    return v;
}

struct Intrinsics {
    cv::Mat K, D;
    std::vector<double> perView; // RMS reprojection error per view
    double rms = 0, medianView = 0;
};

// Calibrates, then drops the view that stands out (if any) and calibrates again: a view is
// judged by what it does to the calibration, not by how sharp it looks. Never below
// kMinViews views; the dropped ones go to *rejected.
Intrinsics calibrateDroppingOutliers(BoardViews *v, bool freeK3, std::ostringstream *rejected)
{
    Intrinsics in;
    std::vector<cv::Mat> rvecs, tvecs;
    const int flags = freeK3 ? 0 : cv::CALIB_FIX_K3;
    for (;;) {
        cv::Mat stdIntr, stdExtr, errs;
        in.rms = cv::calibrateCamera(v->objectPts, v->imagePts, v->imageSize, in.K, in.D, rvecs, tvecs, stdIntr,
                                     stdExtr, errs, flags,
                                     cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
        in.perView.assign(errs.begin<double>(), errs.end<double>());
        std::vector<double> sorted = in.perView;
        std::sort(sorted.begin(), sorted.end());
        in.medianView = sorted[sorted.size() / 2];
        const size_t worst = size_t(std::max_element(in.perView.begin(), in.perView.end()) - in.perView.begin());
        const bool standsOut = in.perView[worst] > std::max(kDropFloorPx, kDropFactor * in.medianView);
        if (!standsOut) break;
        char msg[200];
        if (int(v->used.size()) <= kMinViews) {
            std::snprintf(msg, sizeof msg,
                          "  %s: reprojection error %.2f px against the views' median %.2f px, kept: only %d views\n",
                          v->used[worst].c_str(), in.perView[worst], in.medianView, kMinViews);
            *rejected << msg;
            break;
        }
        std::snprintf(msg, sizeof msg,
                      "  %s: dropped: reprojection error %.2f px against the views' median %.2f px (the board "
                      "moved, bent or was misdetected)\n",
                      v->used[worst].c_str(), in.perView[worst], in.medianView);
        *rejected << msg;
        v->objectPts.erase(v->objectPts.begin() + long(worst));
        v->imagePts.erase(v->imagePts.begin() + long(worst));
        v->used.erase(v->used.begin() + long(worst));
    }
    return in;
}

// Coverage of the field: distortion is fitted where corners are and extrapolated elsewhere.
double fieldCoverage(const std::vector<std::vector<cv::Point2f>> &imagePts, const cv::Size &imageSize)
{
    constexpr int kCellsX = 8, kCellsY = 6;
    bool cell[kCellsY][kCellsX] = {};
    for (const auto &view : imagePts)
        for (const cv::Point2f &q : view) {
            const int cx = std::clamp(int(q.x * kCellsX / float(imageSize.width)), 0, kCellsX - 1);
            const int cy = std::clamp(int(q.y * kCellsY / float(imageSize.height)), 0, kCellsY - 1);
            cell[cy][cx] = true;
        }
    int covered = 0;
    for (const auto &row : cell)
        for (bool c : row) covered += c;
    return double(covered) / (kCellsX * kCellsY);
}

// The flat view: the fixture plane's pose with the intrinsics just found. Returns an empty
// string or why the flat photo cannot give it.
std::string fixturePose(const fs::path &flatPath, const Board &board, double maxBlur, const cv::Size &imageSize,
                        const Intrinsics &in, cv::Mat *rvec, cv::Mat *tvec, double *flatErr)
{
    LumaImage flatImg;
    if (std::string e = loadLuma(flatPath.string(), &flatImg); !e.empty()) return "--flat: " + e;
    if (flatImg.luma.size() != imageSize) return "--flat: photo size differs from the views";
    std::vector<cv::Point2f> flatPts;
    double flatBlur = 0;
    if (std::string e = detect(flatImg.luma, board, maxBlur, &flatPts, &flatBlur); !e.empty())
        return "--flat '" + flatPath.string() + "': " + e;
    const std::vector<cv::Point3f> obj = board.object();
    if (!cv::solvePnP(obj, flatPts, in.K, in.D, *rvec, *tvec, false, cv::SOLVEPNP_ITERATIVE))
        return "--flat: the board's pose could not be solved";
    std::vector<cv::Point2f> reproj;
    cv::projectPoints(obj, *rvec, *tvec, in.K, in.D, reproj);
    double err = 0;
    for (size_t i = 0; i < obj.size(); ++i) err += std::pow(cv::norm(reproj[i] - flatPts[i]), 2);
    *flatErr = std::sqrt(err / double(obj.size()));
    // The flat view gives the plane every measurement uses: it must fit like a good view.
    if (*flatErr > std::max(kDropFloorPx, kDropFactor * in.medianView)) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "--flat '%s': its corners do not fit the calibration (reprojection error %.2f px against the "
                      "views' median %.2f px): retake it",
                      flatPath.string().c_str(), *flatErr, in.medianView);
        return msg;
    }
    return "";
}

// The file's camera: the intrinsics and the fixture's pose, moved the board's thickness down.
void describeCamera(const Intrinsics &in, const cv::Mat &rvec, const cv::Mat &tvec, double thicknessMm,
                    CameraCalibration *out)
{
    vision::PlaneCalibration &p = out->file.plane;
    p.fx = in.K.at<double>(0, 0), p.fy = in.K.at<double>(1, 1), p.cx = in.K.at<double>(0, 2),
    p.cy = in.K.at<double>(1, 2);
    p.k1 = in.D.at<double>(0), p.k2 = in.D.at<double>(1), p.p1 = in.D.at<double>(2), p.p2 = in.D.at<double>(3);
    p.k3 = in.D.total() > 4 ? in.D.at<double>(4) : 0;
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    cv::Vec3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
    // The fixture lies the board's thickness below the board's surface, away from the camera.
    const cv::Vec3d normal(R(0, 2), R(1, 2), R(2, 2));
    const double up = -(R.t() * t)[2] >= 0 ? 1.0 : -1.0;
    t -= up * thicknessMm * normal;
    for (int i = 0; i < 9; ++i) p.r[i] = R.val[i];
    for (int i = 0; i < 3; ++i) p.t[i] = t[i];
    out->fixtureDistanceMm = std::fabs(t[2]);
    out->tiltDeg = std::acos(std::min(1.0, std::fabs(normal[2]))) * 180 / M_PI;
}

// What `icacam calibrate` prints about the camera it wrote.
void printCalibration(const CameraCalibration &c, const std::string &outPath)
{
    const vision::PlaneCalibration &p = c.file.plane;
    std::printf("icacam calibrate: %d views of %zu, RMS reprojection error %.3f px\n", c.file.views, c.photos,
                c.file.rmsPx);
    std::printf(
        "  per-view reprojection error: median %.3f px, largest %.3f px; corners cover %.0f %% of the frame%s\n",
        c.medianViewPx, c.largestViewPx, 100 * c.coverage,
        c.coverage < 0.3 ? " (low: distortion is extrapolated beyond them; add views near the frame's edges)" : "");
    std::printf("  fx %.2f  fy %.2f  cx %.2f  cy %.2f\n", p.fx, p.fy, p.cx, p.cy);
    std::printf("  distortion k1 %.5f  k2 %.5f  p1 %.6f  p2 %.6f  k3 %.5f\n", p.k1, p.k2, p.p1, p.p2, p.k3);
    std::printf("  fixture: %.2f mm from the camera along the axis, tilted %.2f deg; flat view RMS %.3f px\n",
                c.fixtureDistanceMm, c.tiltDeg, c.flatRmsPx);
    std::printf("  scale at the image centre (mm/px) by height above the fixture:");
    for (double h : {0.0, 2.5, 5.0, 7.5, 10.0}) {
        vision::PlaneCalibration at = p;
        at.heightMm = h;
        std::printf(" %.1f mm: %.6f%s", h,
                    vision::planeScaleAt(at, 0.5 * (c.file.imageWidth - 1), 0.5 * (c.file.imageHeight - 1)),
                    h < 10 ? "," : "\n");
    }
    std::printf("  written to %s\n", outPath.c_str());
}

} // namespace

std::string calibrateCamera(const CameraCalibrationInputs &in, CameraCalibration *out)
{
    *out = CameraCalibration();
    Board board;
    if (std::string e = parseBoard(in.board, &board); !e.empty()) return e;
    if (!fs::is_directory(in.imagesDir)) return "--images: '" + in.imagesDir + "' is not a folder";
    fs::path flatPath = in.flatPhoto;
    if (!fs::exists(flatPath) && fs::exists(fs::path(in.imagesDir) / in.flatPhoto))
        flatPath = fs::path(in.imagesDir) / in.flatPhoto;

    std::vector<fs::path> files;
    for (const auto &e : fs::directory_iterator(in.imagesDir))
        if (e.is_regular_file() && isImage(e.path())) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    out->photos = files.size();

    std::ostringstream rejected;
    BoardViews views = findBoardViews(files, board, in.maxBlurPx, &rejected);
    if (int(views.used.size()) < kMinViews) {
        out->viewsNotUsed = rejected.str();
        return "only " + std::to_string(views.used.size()) + " usable view" + (views.used.size() == 1 ? "" : "s") +
               " of " + std::to_string(files.size()) + " in '" + in.imagesDir + "': a calibration needs at least " +
               std::to_string(kMinViews) + " views of the whole board in different tilts";
    }
    const Intrinsics intr = calibrateDroppingOutliers(&views, in.freeK3, &rejected);
    out->viewsNotUsed = rejected.str();
    // Every view alike but none fitting well (very soft or noisy boards): nothing stands out,
    // and the calibration is still not good enough to write.
    if (intr.rms > in.maxRmsPx) {
        char msg[240];
        std::snprintf(
            msg, sizeof msg,
            "the %zu views calibrate to an RMS reprojection error of %.2f px (median view %.2f px), above "
            "%.2f px: the corners are not found well enough (blurred, noisy or moving boards?); no file written",
            views.used.size(), intr.rms, intr.medianView, in.maxRmsPx);
        return msg;
    }
    out->coverage = fieldCoverage(views.imagePts, views.imageSize);
    cv::Mat rvec, tvec;
    if (std::string e =
            fixturePose(flatPath, board, in.maxBlurPx, views.imageSize, intr, &rvec, &tvec, &out->flatRmsPx);
        !e.empty())
        return e;

    describeCamera(intr, rvec, tvec, in.boardThicknessMm, out);
    calibration::CalibrationFile &c = out->file;
    c.imageWidth = views.imageSize.width, c.imageHeight = views.imageSize.height;
    c.rmsPx = intr.rms;
    c.views = int(views.used.size());
    c.board = in.board;
    c.boardThicknessMm = in.boardThicknessMm;
    out->medianViewPx = intr.medianView;
    out->largestViewPx = *std::max_element(intr.perView.begin(), intr.perView.end());
    if (!c.plane.valid()) return "the calibration came out not physical; check the board geometry";
    return "";
}

void writeCameraCalibration(const CameraCalibrationInputs &in, const std::string &outPath)
{
    CameraCalibration c;
    const std::string error = calibrateCamera(in, &c);
    if (!c.viewsNotUsed.empty()) std::cerr << "icacam calibrate: views not used:\n" << c.viewsNotUsed;
    if (!error.empty()) throw std::runtime_error(error);
    if (std::string e = calibration::writeCalibrationFile(outPath, c.file); !e.empty()) throw std::runtime_error(e);
    printCalibration(c, outPath);
}

} // namespace icacam::host
