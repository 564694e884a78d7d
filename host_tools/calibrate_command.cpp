#include "host_tools/calibrate_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "calibration/calibration_file.h"
#include "host_tools/cli_options.h"
#include "host_tools/image_file.h"
#include "host_tools/manifest.h"

namespace icacam::host {

namespace fs = std::filesystem;

namespace {

const char *kUsage = "usage: icacam calibrate --images DIR --board chessboard:COLSxROWS:SQUARE_MM\n"
                     "                        --flat PHOTO --out FILE [--board-thickness MM]\n"
                     "                        [--max-rms PX] [--max-blur PX] [--free-k3]\n"
                     "  --images DIR   photos of the board in different poses (png/jpg/tif/bmp/pgm)\n"
                     "  --board        chessboard:COLSxROWS:SQUARE_MM (inner corners, square side) or\n"
                     "                 circles:COLSxROWS:SPACING_MM (symmetric grid of dark dots)\n"
                     "  --flat PHOTO   the photo with the board lying flat on the fixture (path, or a name\n"
                     "                 in DIR): gives the fixture plane's pose\n"
                     "  --board-thickness MM  the board's surface above the fixture (default 0)\n"
                     "  --max-rms PX   refuse a calibration whose RMS reprojection error is above this\n"
                     "                 (default 0.5: the corners are not found to the accuracy a scale needs)\n"
                     "  --max-blur PX  also refuse views whose board edges (squares or dots) are wider than\n"
                     "                 this (default: no limit; views are judged by their reprojection error)\n"
                     "  --free-k3      also fit k3 (default: fixed at 0, ill-determined in a narrow field)\n"
                     "Needs at least 5 usable views. A view whose corners do not fit the calibration (its\n"
                     "reprojection error 4 times the median view's and above 0.3 px: the board moved, bent\n"
                     "or was misdetected) is dropped with a message. See docs/calibration.md.\n";

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

Board parseBoard(const std::string &spec)
{
    Board b;
    const size_t c1 = spec.find(':'), c2 = spec.rfind(':'), x = spec.find('x', c1 + 1);
    auto fail = [&]() -> Board {
        throw std::runtime_error("bad --board '" + spec +
                                 "': expected chessboard:COLSxROWS:SQUARE_MM or circles:COLSxROWS:SPACING_MM");
    };
    if (c1 == std::string::npos || c2 == c1 || x == std::string::npos || x > c2) return fail();
    const std::string kind = spec.substr(0, c1);
    if (kind != "chessboard" && kind != "circles") return fail();
    b.circles = kind == "circles";
    double cols, rows;
    if (!parseNumber(spec.substr(c1 + 1, x - c1 - 1), &cols) || !parseNumber(spec.substr(x + 1, c2 - x - 1), &rows) ||
        !parseNumber(spec.substr(c2 + 1), &b.pitchMm))
        return fail();
    if (cols < 3 || rows < 3 || cols > 100 || rows > 100 || cols != std::floor(cols) || rows != std::floor(rows) ||
        !(b.pitchMm > 0))
        throw std::runtime_error("bad --board '" + spec + "': at least 3×3 points and a positive pitch");
    b.size = {int(cols), int(rows)};
    return b;
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

} // namespace

int calibrateCommand(const std::vector<std::string> &args)
{
    std::string dir, boardSpec, flat, outPath;
    double thickness = 0, maxBlur = 0, maxRms = 0.5;
    bool freeK3 = false;
    cli::OptionReader opts(args, kUsage);
    auto number = [&](double *v) {
        *v = opts.number();
        if (*v < 0) opts.fail("a non-negative number");
    };
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << kUsage;
            return 0;
        } else if (opts.is("--images"))
            dir = opts.value();
        else if (opts.is("--board"))
            boardSpec = opts.value();
        else if (opts.is("--flat"))
            flat = opts.value();
        else if (opts.is("--out"))
            outPath = opts.value();
        else if (opts.is("--board-thickness"))
            number(&thickness);
        else if (opts.is("--max-blur"))
            number(&maxBlur);
        else if (opts.is("--max-rms"))
            number(&maxRms);
        else if (opts.is("--free-k3"))
            freeK3 = opts.flag();
        else
            opts.unknown();
    }
    if (dir.empty() || boardSpec.empty() || flat.empty() || outPath.empty())
        opts.missing("--images, --board, --flat and --out (all are needed)");
    const Board board = parseBoard(boardSpec);
    if (!fs::is_directory(dir)) throw std::runtime_error("--images: '" + dir + "' is not a folder");
    fs::path flatPath = flat;
    if (!fs::exists(flatPath) && fs::exists(fs::path(dir) / flat)) flatPath = fs::path(dir) / flat;

    std::vector<fs::path> files;
    for (const auto &e : fs::directory_iterator(dir))
        if (e.is_regular_file() && isImage(e.path())) files.push_back(e.path());
    std::sort(files.begin(), files.end());

    std::vector<std::vector<cv::Point3f>> objectPts;
    std::vector<std::vector<cv::Point2f>> imagePts;
    std::vector<std::string> used;
    std::ostringstream rejected;
    cv::Size imageSize;
    for (const fs::path &p : files) {
        LumaImage img;
        std::string why = loadLuma(p.string(), &img);
        if (why.empty() && imageSize.width && img.luma.size() != imageSize) why = "size differs from the first view";
        std::vector<cv::Point2f> pts;
        double blur = 0;
        if (why.empty()) why = detect(img.luma, board, maxBlur, &pts, &blur);
        if (!why.empty()) {
            rejected << "  " << p.filename().string() << ": " << why << "\n";
            continue;
        }
        if (!imageSize.width) imageSize = img.luma.size();
        objectPts.push_back(board.object());
        imagePts.push_back(pts);
        used.push_back(p.filename().string());
    }
    if (int(used.size()) < kMinViews) {
        if (!rejected.str().empty()) std::cerr << "icacam calibrate: views not used:\n" << rejected.str();
        throw std::runtime_error("only " + std::to_string(used.size()) + " usable view" +
                                 (used.size() == 1 ? "" : "s") + " of " + std::to_string(files.size()) + " in '" + dir +
                                 "': a calibration needs at least " + std::to_string(kMinViews) +
                                 " views of the whole board in different tilts");
    }

    // Calibrate, then drop the view that stands out (if any) and calibrate again: a view is
    // judged by what it does to the calibration, not by how sharp it looks.
    cv::Mat K, D;
    std::vector<cv::Mat> rvecs, tvecs;
    std::vector<double> perView;
    const int flags = freeK3 ? 0 : cv::CALIB_FIX_K3;
    double rms = 0, medianView = 0;
    for (;;) {
        cv::Mat stdIntr, stdExtr, errs;
        rms = cv::calibrateCamera(objectPts, imagePts, imageSize, K, D, rvecs, tvecs, stdIntr, stdExtr, errs, flags,
                                  cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
        perView.assign(errs.begin<double>(), errs.end<double>());
        std::vector<double> sorted = perView;
        std::sort(sorted.begin(), sorted.end());
        medianView = sorted[sorted.size() / 2];
        const size_t worst = size_t(std::max_element(perView.begin(), perView.end()) - perView.begin());
        const bool standsOut = perView[worst] > std::max(kDropFloorPx, kDropFactor * medianView);
        if (!standsOut) break;
        char msg[200];
        if (int(used.size()) <= kMinViews) {
            std::snprintf(msg, sizeof msg,
                          "  %s: reprojection error %.2f px against the views' median %.2f px, kept: only %d views\n",
                          used[worst].c_str(), perView[worst], medianView, kMinViews);
            rejected << msg;
            break;
        }
        std::snprintf(msg, sizeof msg,
                      "  %s: dropped: reprojection error %.2f px against the views' median %.2f px (the board "
                      "moved, bent or was misdetected)\n",
                      used[worst].c_str(), perView[worst], medianView);
        rejected << msg;
        objectPts.erase(objectPts.begin() + long(worst));
        imagePts.erase(imagePts.begin() + long(worst));
        used.erase(used.begin() + long(worst));
    }
    if (!rejected.str().empty()) std::cerr << "icacam calibrate: views not used:\n" << rejected.str();
    // Every view alike but none fitting well (very soft or noisy boards): nothing stands out,
    // and the calibration is still not good enough to write.
    if (rms > maxRms) {
        char msg[240];
        std::snprintf(
            msg, sizeof msg,
            "the %zu views calibrate to an RMS reprojection error of %.2f px (median view %.2f px), above "
            "%.2f px: the corners are not found well enough (blurred, noisy or moving boards?); no file written",
            used.size(), rms, medianView, maxRms);
        throw std::runtime_error(msg);
    }
    // Coverage of the field: distortion is fitted where corners are and extrapolated elsewhere.
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
    const double coverage = double(covered) / (kCellsX * kCellsY);

    // The flat view: the fixture plane's pose with the intrinsics just found.
    LumaImage flatImg;
    if (std::string e = loadLuma(flatPath.string(), &flatImg); !e.empty()) throw std::runtime_error("--flat: " + e);
    if (flatImg.luma.size() != imageSize) throw std::runtime_error("--flat: photo size differs from the views");
    std::vector<cv::Point2f> flatPts;
    double flatBlur = 0;
    if (std::string e = detect(flatImg.luma, board, maxBlur, &flatPts, &flatBlur); !e.empty())
        throw std::runtime_error("--flat '" + flatPath.string() + "': " + e);
    cv::Mat rvec, tvec;
    const std::vector<cv::Point3f> obj = board.object();
    if (!cv::solvePnP(obj, flatPts, K, D, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE))
        throw std::runtime_error("--flat: the board's pose could not be solved");
    std::vector<cv::Point2f> reproj;
    cv::projectPoints(obj, rvec, tvec, K, D, reproj);
    double flatErr = 0;
    for (size_t i = 0; i < obj.size(); ++i) flatErr += std::pow(cv::norm(reproj[i] - flatPts[i]), 2);
    flatErr = std::sqrt(flatErr / double(obj.size()));
    // The flat view gives the plane every measurement uses: it must fit like a good view.
    if (flatErr > std::max(kDropFloorPx, kDropFactor * medianView)) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "--flat '%s': its corners do not fit the calibration (reprojection error %.2f px against the "
                      "views' median %.2f px): retake it",
                      flatPath.string().c_str(), flatErr, medianView);
        throw std::runtime_error(msg);
    }

    calibration::CalibrationFile c;
    vision::PlaneCalibration &p = c.plane;
    p.fx = K.at<double>(0, 0), p.fy = K.at<double>(1, 1), p.cx = K.at<double>(0, 2), p.cy = K.at<double>(1, 2);
    p.k1 = D.at<double>(0), p.k2 = D.at<double>(1), p.p1 = D.at<double>(2), p.p2 = D.at<double>(3);
    p.k3 = D.total() > 4 ? D.at<double>(4) : 0;
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    cv::Vec3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
    // The fixture lies the board's thickness below the board's surface, away from the camera.
    const cv::Vec3d normal(R(0, 2), R(1, 2), R(2, 2));
    const double up = -(R.t() * t)[2] >= 0 ? 1.0 : -1.0;
    t -= up * thickness * normal;
    for (int i = 0; i < 9; ++i) p.r[i] = R.val[i];
    for (int i = 0; i < 3; ++i) p.t[i] = t[i];
    c.imageWidth = imageSize.width, c.imageHeight = imageSize.height;
    c.rmsPx = rms;
    c.views = int(used.size());
    c.board = boardSpec;
    c.boardThicknessMm = thickness;
    if (!p.valid()) throw std::runtime_error("the calibration came out not physical; check the board geometry");
    if (std::string e = calibration::writeCalibrationFile(outPath, c); !e.empty()) throw std::runtime_error(e);

    const double tiltDeg = std::acos(std::min(1.0, std::fabs(normal[2]))) * 180 / M_PI;
    std::printf("icacam calibrate: %d views of %zu, RMS reprojection error %.3f px\n", c.views, files.size(), rms);
    std::printf(
        "  per-view reprojection error: median %.3f px, largest %.3f px; corners cover %.0f %% of the frame%s\n",
        medianView, *std::max_element(perView.begin(), perView.end()), 100 * coverage,
        coverage < 0.3 ? " (low: distortion is extrapolated beyond them; add views near the frame's edges)" : "");
    std::printf("  fx %.2f  fy %.2f  cx %.2f  cy %.2f\n", p.fx, p.fy, p.cx, p.cy);
    std::printf("  distortion k1 %.5f  k2 %.5f  p1 %.6f  p2 %.6f  k3 %.5f\n", p.k1, p.k2, p.p1, p.p2, p.k3);
    std::printf("  fixture: %.2f mm from the camera along the axis, tilted %.2f deg; flat view RMS %.3f px\n",
                std::fabs(t[2]), tiltDeg, flatErr);
    std::printf("  scale at the image centre (mm/px) by height above the fixture:");
    for (double h : {0.0, 2.5, 5.0, 7.5, 10.0}) {
        vision::PlaneCalibration at = p;
        at.heightMm = h;
        std::printf(" %.1f mm: %.6f%s", h,
                    vision::planeScaleAt(at, 0.5 * (imageSize.width - 1), 0.5 * (imageSize.height - 1)),
                    h < 10 ? "," : "\n");
    }
    std::printf("  written to %s\n", outPath.c_str());
    return 0;
}

} // namespace icacam::host
