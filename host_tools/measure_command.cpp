// `icacam measure`: re-measure saved images in batch (PRODUCT.md §6).
#include "measure_command.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/model/friction_models.h"
#include "manifest.h"
#include "record_measurer.h"
#include "result_writer.h"

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::vision;

namespace {

const char *kUsage =
    "usage: icacam measure --manifest FILE [--out FILE] [--format csv|jsonl]\n"
    "                      [--overlay DIR] [--repeat N] [--model paper_reduction]\n"
    "                      [--tolerance ABS[,REL]]\n"
    "Measures every record of a manifest (columns id,image,n,mm_per_px; optional k_mpa,\n"
    "d0_mm, h0_mm, h_final_mm). One bad record never stops the batch: it gets status=error.\n"
    "Models: paper_reduction (default: the paper's fit with u carried to 50 % reduction by the\n"
    "FE du/dr, from h_final_mm or from the reduction the silhouette implies), paper (the\n"
    "published reference, 50 % only), fe, fe_reduction (docs/loop.md, docs/fe.md).\n"
    "A 'calibration' column (a file from 'icacam calibrate', relative to the manifest) may\n"
    "stand beside or instead of mm_per_px; the end face is then taken at h_final_mm above\n"
    "the fixture, or at the reduction the reading assumes when none is given (docs/calibration.md).\n"
    "Every row carries mu_sigma and its budget (sigma_edges, sigma_scale, sigma_reduction, sigma_n,\n"
    "sigma_model); status ok only when 2 mu_sigma is within the tolerance, by default\n"
    "max(0.01, 5 % of mu) (--tolerance, or the columns tolerance_mu and tolerance_rel). Declared\n"
    "inputs' tolerances (1 sigma): mm_per_px_tol (relative, default 0.005), h_final_tol_mm\n"
    "(0.05), n_tol (0.01); without h_final_mm the reduction is inferred from the silhouette\n"
    "(docs/uncertainty.md).\n";

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
    SpecimenSpec defaults;
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
        else if (args[i] == "--tolerance") {
            if (!parseTolerance(value(), &defaults.tolerance))
                throw std::runtime_error("--tolerance needs ABS or ABS,REL (e.g. 0.01,0.05)");
        } else if (args[i] == "--repeat") {
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

    RecordMeasurer measurer(*model, defaults);
    int nOk = 0, nWarn = 0, nErr = 0;
    RecordReading reading;
    for (const ManifestRow &row : manifest.rows) {
        ResultRow r;
        r.id = row.get("id", "line" + std::to_string(row.line));
        r.model = model->name();
        measurer.measure(row, manifest, &reading, repeat);
        const Measurement &m = reading.m;
        if (reading.measured) {
            r.m = &m;
            if (!overlayDir.empty() && m.hasValue())
                drawOverlay(reading.image.luma, m, (fs::path(overlayDir) / (r.id + ".png")).string());
        } else {
            r.message = reading.message;
        }
        const Status st = reading.measured ? m.status : Status::Error;
        (st == Status::Ok ? nOk : st == Status::Warn ? nWarn : nErr)++;
        writer.write(r);
    }
    std::cerr << "icacam measure: " << manifest.rows.size() << " records: " << nOk << " ok, "
              << nWarn << " warn, " << nErr << " error\n";
    return 0;
}

} // namespace icacam::host
