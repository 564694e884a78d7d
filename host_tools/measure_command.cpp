// `icacam measure`: re-measure saved images in batch (PRODUCT.md §6).
#include "host_tools/measure_command.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "friction/friction_models.h"
#include "host_tools/cli_options.h"
#include "host_tools/manifest.h"
#include "host_tools/number_text.h"
#include "host_tools/record_measurer.h"
#include "host_tools/result_writer.h"

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::friction;
using namespace icacam::reading;
using namespace icacam::vision;

namespace {

std::string usage()
{
    const ReadingTolerance t;
    const DeclaredTolerances d;
    return std::string("usage: icacam measure --manifest FILE [--out FILE] [--format table|csv|jsonl]\n"
                       "                      [--overlay DIR] [--repeat N] [--model NAME] [--tolerance ABS[,REL]]\n"
                       "  --manifest FILE  the records: columns id,image,n,mm_per_px; optional k_mpa, d0_mm,\n"
                       "                   h0_mm, h_final_mm\n"
                       "  --out FILE       the records (default: standard output)\n"
                       "  --format         table (a line per record and a summary: the default without --out),\n"
                       "                   csv (the full record: the default with --out) or jsonl\n"
                       "  --overlay DIR    also draw each measured image's boundaries into DIR/<id>.png\n"
                       "  --repeat N       measure each image N times (default 1: timing and profiling)\n"
                       "  --model NAME     the friction model (default ") +
           friction::kDefaultModel + "; known: " + cli::modelNames() +
           ")\n"
           "  --tolerance ABS[,REL]  the lab's tolerance on mu: the column decision says whether\n"
           "                   U = 2 mu_sigma lies within max(ABS, REL * mu) (default " +
           numberText("%g", t.absMu) + "," + numberText("%g", t.relMu) +
           ";\n                   the columns tolerance_mu, tolerance_rel per record)\n"
           "status: ok (every check passed: U covers the error), warn (a check found a condition U\n"
           "may not cover; message names it and what to supply) or error (no value). advice: the\n"
           "declared input that would shrink U the most, and to what (docs/measuring.md).\n"
           "One bad record never stops the batch: it gets status=error.\n"
           "Models: paper_reduction, the paper's fit with u carried to 50 % reduction by the FE du/dr\n"
           "(from h_final_mm or from the reduction the silhouette implies); paper, the published\n"
           "reference (50 % only); fe, fe_reduction: the project's CalculiX tables (docs/loop.md, docs/fe.md).\n"
           "A 'calibration' column (a file from 'icacam calibrate', relative to the manifest) may\n"
           "stand beside or instead of mm_per_px; the end face is then taken at h_final_mm above\n"
           "the fixture, or at the reduction the reading assumes when none is given (docs/calibration.md).\n"
           "Every row carries mu_sigma and its budget (sigma_edges, sigma_scale, sigma_reduction, sigma_n,\n"
           "sigma_model). Declared inputs' tolerances (1 sigma, columns): mm_per_px_tol (relative, default " +
           numberText("%g", d.scaleRel) + "),\nh_final_tol_mm (" + numberText("%g", d.hFinalMm) + "), n_tol (" +
           numberText("%g", d.n) +
           "); without h_final_mm the reduction is inferred from the silhouette\n"
           "(docs/uncertainty.md). working_distance_mm: the camera's distance to the end face; a close\n"
           "camera sees the barrel's outline inside R_max, and the silhouette is held against that outline.\n"
           "tone_gamma: the camera's tone curve, encoded = linear^(1/tone_gamma) (1, the default: levels\n"
           "proportional to light; about 2.2: a camera's sRGB-like output); the ring's edges are located\n"
           "in linear light (docs/photographs.md).\n";
}

void drawOverlay(const cv::Mat &luma, const reading::Reading &reading, const std::string &path)
{
    const vision::EndFaceGeometry &m = reading.geometry;
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
    if (m.rMaxPx > 0) cv::circle(bgr, {int(m.centreX), int(m.centreY)}, int(m.rMaxPx), {0, 255, 0}, 1, cv::LINE_AA);
    char text[160];
    std::snprintf(text, sizeof text, "mu=%.4f +- %.4f (U)  u=%.4f mm  %s", reading.mu, reading.expanded(), reading.uMm,
                  statusName(reading.status));
    cv::putText(bgr, text, {20, 40}, cv::FONT_HERSHEY_SIMPLEX, 1.0, {0, 255, 255}, 2);
    cv::imwrite(path, bgr);
}

} // namespace

int measureCommand(const std::vector<std::string> &args)
{
    std::string manifestPath, outPath, format, overlayDir, modelName = kDefaultModel;
    long repeat = 1;
    SpecimenSpec defaults;
    cli::OptionReader opts(args, usage());
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << usage();
            return 0;
        } else if (opts.is("--manifest"))
            manifestPath = opts.value();
        else if (opts.is("--out"))
            outPath = opts.value();
        else if (opts.is("--format")) {
            format = opts.value();
            if (format != "table" && format != "csv" && format != "jsonl")
                opts.fail("table, csv or jsonl, not '" + format + "'");
        } else if (opts.is("--overlay"))
            overlayDir = opts.value();
        else if (opts.is("--model")) {
            modelName = opts.value();
            if (!frictionModel(modelName))
                opts.fail("unknown model '" + modelName + "' (known: " + cli::modelNames() + ")");
        } else if (opts.is("--tolerance")) {
            if (!parseTolerance(opts.value(), &defaults.tolerance)) opts.fail("ABS or ABS,REL (e.g. 0.01,0.05)");
        } else if (opts.is("--repeat"))
            repeat = opts.wholeNumber(1, 100000);
        else
            opts.unknown();
    }
    if (manifestPath.empty()) opts.missing("--manifest");
    const FrictionModel *model = frictionModel(modelName);

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
    if (format.empty()) format = outPath.empty() ? "table" : "csv";
    ResultWriter writer(out, format == "table"   ? ResultFormat::Table
                             : format == "jsonl" ? ResultFormat::Jsonl
                                                 : ResultFormat::Csv);
    writer.header();

    RecordMeasurer measurer(*model, defaults);
    int nOk = 0, nWarn = 0, nErr = 0;
    RecordReading reading;
    for (const ManifestRow &row : manifest.rows) {
        ResultRow r;
        r.id = row.get("id", "line" + std::to_string(row.line));
        r.model = model->name();
        measurer.measure(row, manifest, &reading, repeat);
        const reading::Reading &m = reading.reading;
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
    writer.summary();
    if (format != "table")
        std::cerr << "icacam measure: " << manifest.rows.size() << " records: " << nOk << " ok, " << nWarn << " warn, "
                  << nErr << " error\n";
    return 0;
}

} // namespace icacam::host
