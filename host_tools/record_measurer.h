#pragma once
// Measuring one manifest record on the PC: the row's declared inputs (with their tolerances
// and the lab's tolerance) → SpecimenSpec, its image and calibration loaded, then the
// pipeline and the interpretation every reading goes through (vision/reading_interpreter.h).
// `icacam measure` and `icacam loop` both measure through this.
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "calibration/calibration_file.h"
#include "friction/friction_model.h"
#include "host_tools/image_file.h"
#include "host_tools/manifest.h"
#include "vision/end_face_analyzer.h"

namespace icacam::host {

// Manifest columns that set the tolerances (all optional; defaults in vision/specimen_spec.h):
//   mm_per_px_tol (relative, 1 σ), h_final_tol_mm, n_tol (1 σ), tolerance_mu (absolute),
//   tolerance_rel (relative to μ). CLI-wide values come in through `defaults`.
struct RecordReading {
    vision::Measurement m;
    bool measured = false; // reached the pipeline (m holds its result)
    std::string message;   // why it did not
    LumaImage image;       // the decoded frame, for overlays
    vision::SpecimenSpec spec;
};

class RecordMeasurer {
public:
    // defaults: the tolerances applied where a row sets none.
    RecordMeasurer(const friction::FrictionModel &model, const vision::SpecimenSpec &defaults);
    void measure(const ManifestRow &row, const Manifest &manifest, RecordReading *out, long repeat = 1);
    const friction::FrictionModel &model() const { return model_; }

private:
    bool readSpec(const ManifestRow &row, vision::SpecimenSpec *spec, std::string *why) const;
    const friction::FrictionModel &model_;
    vision::SpecimenSpec defaults_;
    vision::EndFaceAnalyzer analyzer_;
    std::map<std::string, std::pair<calibration::CalibrationFile, std::string>> calibrations_; // by path
    vision::PlaneCalibration plane_;
};

// Parses "ABS" or "ABS,REL" (e.g. 0.01,0.05) into t; false if malformed.
bool parseTolerance(const std::string &text, vision::ReadingTolerance *t);

} // namespace icacam::host
