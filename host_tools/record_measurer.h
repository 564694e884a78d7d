#pragma once
// Measuring one manifest record on the PC: the row's declared inputs (with their tolerances
// and the lab's tolerance) → SpecimenSpec (reading/specimen_spec.h), its image and
// calibration loaded, then read by the one Instrument (reading/instrument.h). `icacam
// measure` and `icacam loop` both measure through this.
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "calibration/calibration_file.h"
#include "friction/friction_model.h"
#include "host_tools/image_file.h"
#include "host_tools/manifest.h"
#include "reading/instrument.h"

namespace icacam::host {

// Manifest columns that set the tolerances (all optional; defaults in reading/specimen_spec.h):
//   mm_per_px_tol (relative, 1 σ), h_final_tol_mm, n_tol (1 σ), tolerance_mu (absolute),
//   tolerance_rel (relative to μ). CLI-wide values come in through `defaults`.
struct RecordReading {
    reading::Reading reading;
    bool measured = false; // reached the pipeline (reading holds its result)
    std::string message;   // why it did not
    LumaImage image;       // the decoded frame, for overlays
    reading::SpecimenSpec spec;
};

class RecordMeasurer {
public:
    // defaults: the tolerances applied where a row sets none.
    RecordMeasurer(const friction::FrictionModel &model, const reading::SpecimenSpec &defaults);
    // Reads an image row: its spec, image and calibration, then the instrument's reading.
    void measure(const ManifestRow &row, const Manifest &manifest, RecordReading *out, long repeat = 1);
    // The row's declared inputs: false with *why set when one is missing or malformed.
    bool readSpec(const ManifestRow &row, bool needsScale, reading::SpecimenSpec *spec, std::string *why) const;
    const friction::FrictionModel &model() const { return instrument_.model(); }
    reading::Instrument &instrument() { return instrument_; }

private:
    bool useCalibration(const ManifestRow &row, const Manifest &manifest, int width, int height, std::string *why);
    bool loadSegments(const ManifestRow &row, const Manifest &manifest, int width, int height, vision::LitInTurn *lit,
                      std::string *why);
    reading::SpecimenSpec defaults_;
    std::vector<LumaImage> segments_; // the row's segment frames, held while it is read
    reading::Instrument instrument_;
    std::map<std::string, std::pair<calibration::CalibrationFile, std::string>> calibrations_; // by path
};

// Parses "ABS" or "ABS,REL" (e.g. 0.01,0.05) into t; false if malformed.
bool parseTolerance(const std::string &text, reading::ReadingTolerance *t);

} // namespace icacam::host
