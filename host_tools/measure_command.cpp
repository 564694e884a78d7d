// `icacam measure`: re-measure saved images in batch (PRODUCT.md §6).
#include "measure_command.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "calibration/calibration_file.h"
#include "vision/model/friction_models.h"
#include "image_file.h"
#include "manifest.h"
#include "result_writer.h"
#include "vision/end_face_analyzer.h"

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::vision;

namespace {

const char *kUsage =
    "usage: icacam measure --manifest FILE [--out FILE] [--format csv|jsonl]\n"
    "                      [--overlay DIR] [--repeat N] [--model paper_reduction]\n"
    "Measures every record of a manifest (columns id,image,n,mm_per_px; optional k_mpa,\n"
    "d0_mm, h0_mm, h_final_mm). One bad record never stops the batch: it gets status=error.\n"
    "Models: paper_reduction (default: the paper's fit with u carried to 50 % reduction from\n"
    "h_final_mm by the FE du/dr; without h_final_mm it is the paper's fit), paper (the\n"
    "published reference, 50 % only), fe, fe_reduction (docs/loop.md, docs/fe.md).\n"
    "A 'calibration' column (a file from 'icacam calibrate', relative to the manifest) may\n"
    "stand beside or instead of mm_per_px; the end face is then taken at h_final_mm above\n"
    "the fixture, or h0_mm/2 when no final height is given (docs/calibration.md).\n";

void drawOverlay(const cv::Mat &luma, const Measurement &m, const std::string &path)
{
    cv::Mat bgr;
    cv::cvtColor(luma, bgr, cv::COLOR_GRAY2BGR);
    auto curve = [&](const BoundaryFit &f, cv::Scalar colour) {
        std::vector<cv::Point> pts;
        for (int i = 0; i < 720; ++i) {
            const double t = 2 * M_PI * i / 720;
            const double r = f.radiusAt(t);
            pts.emplace_back(int(std::lround((m.centreX + r * std::cos(t)) * 16)),
                             int(std::lround((m.centreY + r * std::sin(t)) * 16)));
        }
        cv::polylines(bgr, pts, true, colour, 1, cv::LINE_AA, 4);
    };
    auto points = [&](const EdgeSample *p, cv::Scalar colour) {
        for (int i = 0; p && i < m.rayCount; ++i)
            if (p[i].valid) cv::circle(bgr, {int(p[i].x.toDouble()), int(p[i].y.toDouble())}, 1, colour, -1);
    };
    points(m.innerPoints, {255, 200, 0});
    points(m.outerPoints, {0, 200, 255});
    curve(m.inner, {255, 0, 0});
    curve(m.outer, {0, 0, 255});
    if (m.rMaxPx > 0)
        cv::circle(bgr, {int(m.centreX), int(m.centreY)}, int(m.rMaxPx), {0, 255, 0}, 1, cv::LINE_AA);
    char text[160];
    std::snprintf(text, sizeof text, "mu=%.4f +- %.4f  u=%.4f mm  %s", m.mu, m.muSigma, m.uMm,
                  statusName(m.status));
    cv::putText(bgr, text, {20, 40}, cv::FONT_HERSHEY_SIMPLEX, 1.0, {0, 255, 255}, 2);
    cv::imwrite(path, bgr);
}

} // namespace

int measureCommand(const std::vector<std::string> &args)
{
    std::string manifestPath, outPath, format = "csv", overlayDir, modelName = kDefaultModel;
    long repeat = 1;
    for (size_t i = 0; i < args.size(); ++i) {
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) throw std::runtime_error(args[i] + " needs a value");
            return args[++i];
        };
        if (args[i] == "--manifest") manifestPath = value();
        else if (args[i] == "--out") outPath = value();
        else if (args[i] == "--format") format = value();
        else if (args[i] == "--overlay") overlayDir = value();
        else if (args[i] == "--model") modelName = value();
        else if (args[i] == "--repeat") {
            double r;
            if (!parseNumber(value(), &r) || r < 1 || r > 100000 || r != std::floor(r))
                throw std::runtime_error("--repeat needs a whole number from 1 to 100000");
            repeat = long(r);
        } else if (args[i] == "-h" || args[i] == "--help") { std::cout << kUsage; return 0; }
        else throw std::runtime_error("unknown option '" + args[i] + "'\n" + kUsage);
    }
    if (manifestPath.empty()) throw std::runtime_error(std::string("--manifest is required\n") + kUsage);
    if (format != "csv" && format != "jsonl") throw std::runtime_error("--format must be csv or jsonl");
    auto model = frictionModel(modelName);
    if (!model) throw std::runtime_error("unknown model '" + modelName + "' (known: " + kKnownModels + ")");

    Manifest manifest;
    std::string err;
    if (!readManifest(manifestPath, &manifest, &err)) throw std::runtime_error(err);
    if (!overlayDir.empty()) fs::create_directories(overlayDir);

    std::ofstream file;
    if (!outPath.empty()) {
        file.open(outPath);
        if (!file) throw std::runtime_error("cannot write '" + outPath + "'");
    }
    std::ostream &out = outPath.empty() ? std::cout : file;
    ResultWriter writer(out, format == "jsonl");
    writer.header();

    EndFaceAnalyzer analyzer;
    analyzer.configure(16384, 16384); // working memory does not grow with the frame
    std::map<std::string, std::pair<calibration::CalibrationFile, std::string>> calibrations; // by path
    int nOk = 0, nWarn = 0, nErr = 0;
    for (const ManifestRow &row : manifest.rows) {
        ResultRow r;
        r.id = row.get("id", "line" + std::to_string(row.line));
        r.model = model->name();
        Measurement m;
        LumaImage img;
        SpecimenSpec spec;
        PlaneCalibration calibration;
        const bool calibrated = row.has("calibration");
        auto number = [&](const char *key, double fallback, bool required, double *outV) {
            if (!row.has(key)) {
                if (required) { r.message = std::string("missing ") + key; return false; }
                *outV = fallback;
                return true;
            }
            if (!parseNumber(row.get(key), outV)) {
                r.message = std::string("bad number in ") + key + ": '" + row.get(key) + "'";
                return false;
            }
            return true;
        };
        bool ok = row.error.empty();
        if (!ok) r.message = "manifest line " + std::to_string(row.line) + ": " + row.error;
        ok = ok && number("n", 0, true, &spec.n) && number("mm_per_px", 0, !calibrated, &spec.mmPerPx) &&
             number("k_mpa", 0, false, &spec.kMpa) && number("d0_mm", 10, false, &spec.d0Mm) &&
             number("h0_mm", 15, false, &spec.h0Mm) && number("h_final_mm", 0, false, &spec.hFinalMm);
        if (ok && !row.has("image")) { r.message = "missing image"; ok = false; }
        if (ok && !(spec.mmPerPx > 0) && !(calibrated && spec.mmPerPx == 0)) {
            r.message = "mm_per_px must be positive";
            ok = false;
        }
        if (ok) {
            fs::path p = row.get("image");
            if (p.is_relative()) p = fs::path(manifest.baseDir) / p;
            if (std::string e = loadLuma(p.string(), &img); !e.empty()) { r.message = e; ok = false; }
        }
        if (ok && calibrated) {
            fs::path p = row.get("calibration");
            if (p.is_relative()) p = fs::path(manifest.baseDir) / p;
            auto it = calibrations.find(p.string());
            if (it == calibrations.end()) {
                calibration::CalibrationFile c;
                const std::string e = calibration::readCalibrationFile(p.string(), &c);
                it = calibrations.emplace(p.string(), std::make_pair(c, e)).first;
            }
            const calibration::CalibrationFile &c = it->second.first;
            if (!it->second.second.empty()) r.message = it->second.second;
            else if (c.imageWidth != img.luma.cols || c.imageHeight != img.luma.rows)
                r.message = "calibration is for " + std::to_string(c.imageWidth) + "x" +
                            std::to_string(c.imageHeight) + " images, this one is " +
                            std::to_string(img.luma.cols) + "x" + std::to_string(img.luma.rows);
            else if (spec.hFinalMm < 0 || !(spec.h0Mm > 0)) r.message = "h_final_mm or h0_mm not usable";
            ok = r.message.empty();
            if (ok) {
                calibration = c.plane;
                calibration.heightMm = spec.hFinalMm > 0 ? spec.hFinalMm : 0.5 * spec.h0Mm;
                spec.calibration = &calibration;
                // Without a declared scale, the search is sized from the calibrated one.
                if (spec.mmPerPx == 0)
                    spec.mmPerPx = planeScaleAt(calibration, 0.5 * (img.luma.cols - 1), 0.5 * (img.luma.rows - 1));
                if (!(spec.mmPerPx > 0)) { r.message = "calibration does not map the image centre"; ok = false; }
            }
        }
        if (ok) {
            const LumaView view{img.luma.data, img.luma.cols, img.luma.rows, int(img.luma.step[0]), 1};
            for (long k = 0; k < repeat; ++k) m = analyzer.measure(view, spec, *model);
            r.m = &m;
            r.status = statusName(m.status);
            if (m.status == Status::Error) r.message = errorMessage(m.error);
            else if (m.flags) r.message = "check flags: " + ResultWriter::flagList(m.flags);
            if (!overlayDir.empty() && m.hasValue())
                drawOverlay(img.luma, m, (fs::path(overlayDir) / (r.id + ".png")).string());
        }
        (r.status == "ok" ? nOk : r.status == "warn" ? nWarn : nErr)++;
        writer.write(r);
    }
    std::cerr << "icacam measure: " << manifest.rows.size() << " records: " << nOk << " ok, "
              << nWarn << " warn, " << nErr << " error\n";
    return 0;
}

} // namespace icacam::host
