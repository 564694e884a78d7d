#include "host_tools/record_measurer.h"

#include <filesystem>

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::friction;
using namespace icacam::vision;

RecordMeasurer::RecordMeasurer(const FrictionModel &model, const SpecimenSpec &defaults)
        : model_(model), defaults_(defaults)
{
    analyzer_.configure(16384, 16384); // working memory does not grow with the frame
}

bool parseTolerance(const std::string &text, ReadingTolerance *t)
{
    const size_t comma = text.find(',');
    double a, r = t->relMu;
    if (!parseNumber(text.substr(0, comma), &a) || a < 0) return false;
    if (comma != std::string::npos && (!parseNumber(text.substr(comma + 1), &r) || r < 0)) return false;
    t->absMu = a;
    t->relMu = r;
    return true;
}

bool RecordMeasurer::readSpec(const ManifestRow &row, SpecimenSpec *spec, std::string *why) const
{
    auto number = [&](const char *key, bool required, double *v, double min = -1e300) {
        if (!row.has(key) || row.get(key).empty()) {
            if (required) *why = std::string("missing ") + key;
            return !required;
        }
        if (!parseNumber(row.get(key), v)) {
            *why = std::string("bad number in ") + key + ": '" + row.get(key) + "'";
            return false;
        }
        if (*v < min) {
            *why = std::string(key) + " must not be negative";
            return false;
        }
        return true;
    };
    *spec = defaults_;
    const bool calibrated = row.has("calibration") && !row.get("calibration").empty();
    DeclaredTolerances &dt = spec->tolerances;
    ReadingTolerance &rt = spec->tolerance;
    if (!(number("n", true, &spec->n) && number("mm_per_px", !calibrated, &spec->mmPerPx) &&
          number("k_mpa", false, &spec->kMpa) && number("d0_mm", false, &spec->d0Mm) &&
          number("h0_mm", false, &spec->h0Mm) && number("h_final_mm", false, &spec->hFinalMm, 0) &&
          number("mm_per_px_tol", false, &dt.scaleRel, 0) && number("h_final_tol_mm", false, &dt.hFinalMm, 0) &&
          number("n_tol", false, &dt.n, 0) && number("tolerance_mu", false, &rt.absMu, 0) &&
          number("tolerance_rel", false, &rt.relMu, 0)))
        return false;
    if (!(spec->mmPerPx > 0) && !(calibrated && spec->mmPerPx == 0)) {
        *why = "mm_per_px must be positive";
        return false;
    }
    if (!(spec->h0Mm > 0)) {
        *why = "h0_mm must be positive";
        return false;
    }
    return true;
}

void RecordMeasurer::measure(const ManifestRow &row, const Manifest &manifest, RecordReading *out, long repeat)
{
    out->measured = false;
    out->message.clear();
    out->m = Measurement{};
    if (!row.error.empty()) {
        out->message = "manifest line " + std::to_string(row.line) + ": " + row.error;
        return;
    }
    SpecimenSpec &spec = out->spec;
    if (!readSpec(row, &spec, &out->message)) return;
    if (!row.has("image") || row.get("image").empty()) {
        out->message = "missing image";
        return;
    }
    fs::path p = row.get("image");
    if (p.is_relative()) p = fs::path(manifest.baseDir) / p;
    if (std::string e = loadLuma(p.string(), &out->image); !e.empty()) {
        out->message = e;
        return;
    }
    const cv::Mat &luma = out->image.luma;
    if (row.has("calibration") && !row.get("calibration").empty()) {
        fs::path c = row.get("calibration");
        if (c.is_relative()) c = fs::path(manifest.baseDir) / c;
        auto it = calibrations_.find(c.string());
        if (it == calibrations_.end()) {
            calibration::CalibrationFile file;
            const std::string e = calibration::readCalibrationFile(c.string(), &file);
            it = calibrations_.emplace(c.string(), std::make_pair(file, e)).first;
        }
        const calibration::CalibrationFile &file = it->second.first;
        if (!it->second.second.empty())
            out->message = it->second.second;
        else if (file.imageWidth != luma.cols || file.imageHeight != luma.rows)
            out->message = "calibration is for " + std::to_string(file.imageWidth) + "x" +
                           std::to_string(file.imageHeight) + " images, this one is " + std::to_string(luma.cols) +
                           "x" + std::to_string(luma.rows);
        if (!out->message.empty()) return;
        plane_ = file.plane;
        spec.calibration = &plane_;
    }
    const LumaView view{luma.data, luma.cols, luma.rows, int(luma.step[0]), 1};
    for (long k = 0; k < repeat; ++k) out->m = analyzer_.measure(view, spec, model_);
    out->measured = true;
}

} // namespace icacam::host
