#include "host_tools/record_measurer.h"

#include <filesystem>

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::reading;

RecordMeasurer::RecordMeasurer(const friction::FrictionModel &model, const SpecimenSpec &defaults) : defaults_(defaults)
{
    instrument_.configure(16384, 16384, model); // working memory does not grow with the frame
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

bool RecordMeasurer::readSpec(const ManifestRow &row, bool needsScale, SpecimenSpec *spec, std::string *why) const
{
    *spec = defaults_;
    std::string text; // the looked-up value, held until the next lookup
    auto lookup = [&row, &text](std::string_view key) -> const char * {
        const std::string k(key);
        if (!row.has(k)) return nullptr;
        text = row.get(k);
        return text.c_str();
    };
    return specimenFromFields(lookup, needsScale, spec, why);
}

// The row's calibration file (read once per path), set on the instrument; false with *why
// set when it cannot be read or is for another image size.
bool RecordMeasurer::useCalibration(const ManifestRow &row, const Manifest &manifest, int width, int height,
                                    std::string *why)
{
    if (!row.has("calibration") || row.get("calibration").empty()) {
        instrument_.setCalibration(nullptr, 0, 0);
        return true;
    }
    fs::path c = row.get("calibration");
    if (c.is_relative()) c = fs::path(manifest.baseDir) / c;
    auto it = calibrations_.find(c.string());
    if (it == calibrations_.end()) {
        calibration::CalibrationFile file;
        const std::string e = calibration::readCalibrationFile(c.string(), &file);
        it = calibrations_.emplace(c.string(), std::make_pair(file, e)).first;
    }
    const calibration::CalibrationFile &file = it->second.first;
    if (!it->second.second.empty()) {
        *why = it->second.second;
        return false;
    }
    instrument_.setCalibration(&file.plane, file.imageWidth, file.imageHeight);
    *why = instrument_.frameSizeIssue(width, height);
    return why->empty();
}

void RecordMeasurer::measure(const ManifestRow &row, const Manifest &manifest, RecordReading *out, long repeat)
{
    out->measured = false;
    out->message.clear();
    out->reading = Reading{};
    if (!row.error.empty()) {
        out->message = "manifest line " + std::to_string(row.line) + ": " + row.error;
        return;
    }
    SpecimenSpec &spec = out->spec;
    const bool calibrated = row.has("calibration") && !row.get("calibration").empty();
    if (!readSpec(row, !calibrated, &spec, &out->message)) return;
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
    if (!useCalibration(row, manifest, luma.cols, luma.rows, &out->message)) return;
    vision::LitInTurn lit;
    if (!loadSegments(row, manifest, luma.cols, luma.rows, &lit, &out->message)) return;
    const vision::LumaView view{luma.data, luma.cols, luma.rows, int(luma.step[0]), 1};
    for (long k = 0; k < repeat; ++k) out->reading = instrument_.read(view, spec, lit.count ? &lit : nullptr);
    out->measured = true;
}

// The row's segment frames (`segment_images`: paths separated by ';', segment k centred at
// image azimuth segment0_deg + k·360/N° from +x towards +y; segment0_deg 0 where the column
// is absent), each the main frame's size; false with *why.
bool RecordMeasurer::loadSegments(const ManifestRow &row, const Manifest &manifest, int width, int height,
                                  vision::LitInTurn *lit, std::string *why)
{
    lit->count = 0;
    if (!row.has("segment_images") || row.get("segment_images").empty()) return true;
    const std::vector<std::string> paths = splitList(row.get("segment_images"));
    if (paths.size() < size_t(vision::kMinTiltSegments) || paths.size() > size_t(vision::LitInTurn::kMaxSegments)) {
        *why = "segment_images: " + std::to_string(paths.size()) + " frames; the tilt needs " +
               std::to_string(vision::kMinTiltSegments) + "-" + std::to_string(vision::LitInTurn::kMaxSegments);
        return false;
    }
    segments_.resize(paths.size());
    for (size_t k = 0; k < paths.size(); ++k) {
        if (paths[k].empty()) {
            *why = "segment_images: segment " + std::to_string(k) + " has no path";
            return false;
        }
        fs::path p = paths[k];
        if (p.is_relative()) p = fs::path(manifest.baseDir) / p;
        if (std::string e = loadLuma(p.string(), &segments_[k]); !e.empty()) {
            *why = "segment " + std::to_string(k) + ": " + e;
            return false;
        }
        const cv::Mat &m = segments_[k].luma;
        if (m.cols != width || m.rows != height) {
            *why = "segment " + std::to_string(k) + " is " + std::to_string(m.cols) + "x" + std::to_string(m.rows) +
                   ", the frame " + std::to_string(width) + "x" + std::to_string(height);
            return false;
        }
        lit->segment[k] = vision::LumaView{m.data, m.cols, m.rows, int(m.step[0]), 1};
    }
    lit->azimuth0Deg = 0;
    if (row.has("segment0_deg") && !row.get("segment0_deg").empty() &&
        !parseNumber(row.get("segment0_deg"), &lit->azimuth0Deg)) {
        *why = "segment0_deg: not a number";
        return false;
    }
    lit->count = int(paths.size());
    return true;
}

} // namespace icacam::host
