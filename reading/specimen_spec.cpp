#include "reading/specimen_spec.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace icacam::reading {

namespace {

struct SpecimenField {
    const char *key;
    double SpecimenSpec::*value;
    double DeclaredTolerances::*tolerance;
    double ReadingTolerance::*decision;
    bool nonNegative;
};

// In the order a manifest row's fields are checked (the first problem is the one named).
constexpr SpecimenField kFields[] = {
    {"n", &SpecimenSpec::n, nullptr, nullptr, false},
    {"mm_per_px", &SpecimenSpec::mmPerPx, nullptr, nullptr, false},
    {"k_mpa", &SpecimenSpec::kMpa, nullptr, nullptr, false},
    {"d0_mm", &SpecimenSpec::d0Mm, nullptr, nullptr, false},
    {"h0_mm", &SpecimenSpec::h0Mm, nullptr, nullptr, false},
    {"h_final_mm", &SpecimenSpec::hFinalMm, nullptr, nullptr, true},
    {"working_distance_mm", &SpecimenSpec::workingDistanceMm, nullptr, nullptr, true},
    {"tone_gamma", &SpecimenSpec::toneGamma, nullptr, nullptr, true},
    {"mm_per_px_tol", nullptr, &DeclaredTolerances::scaleRel, nullptr, true},
    {"h_final_tol_mm", nullptr, &DeclaredTolerances::hFinalMm, nullptr, true},
    {"n_tol", nullptr, &DeclaredTolerances::n, nullptr, true},
    {"tolerance_mu", nullptr, nullptr, &ReadingTolerance::absMu, true},
    {"tolerance_rel", nullptr, nullptr, &ReadingTolerance::relMu, true},
};

// A whole, finite number, surrounding blanks allowed.
bool parseValue(std::string_view text, double *out)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
    if (text.empty() || text.size() > 64) return false;
    char buf[65];
    std::memcpy(buf, text.data(), text.size());
    buf[text.size()] = 0;
    char *end = nullptr;
    const double v = std::strtod(buf, &end);
    if (end != buf + text.size() || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

} // namespace

const char *const kSpecimenKeys[] = {
    "n",          "mm_per_px",     "k_mpa",          "d0_mm", "h0_mm",        "h_final_mm",    "working_distance_mm",
    "tone_gamma", "mm_per_px_tol", "h_final_tol_mm", "n_tol", "tolerance_mu", "tolerance_rel", nullptr};

bool setSpecimenField(std::string_view key, std::string_view text, SpecimenSpec *spec, std::string *why)
{
    for (const SpecimenField &f : kFields) {
        if (key != f.key) continue;
        double v;
        if (!parseValue(text, &v)) {
            *why = std::string("bad number in ") + f.key + ": '" + std::string(text) + "'";
            return false;
        }
        if (f.nonNegative && v < 0) {
            *why = std::string(f.key) + " must not be negative";
            return false;
        }
        if (f.value) spec->*f.value = v;
        if (f.tolerance) spec->tolerances.*f.tolerance = v;
        if (f.decision) spec->tolerance.*f.decision = v;
        return true;
    }
    why->clear();
    return false;
}

bool checkSpecimen(const SpecimenSpec &spec, bool needsScale, std::string *why)
{
    // With a calibration the scale may be left out (0: the calibration's at the image centre
    // sizes the search).
    if (!(spec.mmPerPx > 0) && !(!needsScale && spec.mmPerPx == 0)) {
        *why = "mm_per_px must be positive";
        return false;
    }
    if (!(spec.h0Mm > 0)) {
        *why = "h0_mm must be positive";
        return false;
    }
    if (!(spec.toneGamma >= 1 && spec.toneGamma <= 3)) {
        *why = "tone_gamma must lie in 1-3 (1: levels proportional to light; about 2.2: a camera's sRGB-like output)";
        return false;
    }
    return true;
}

} // namespace icacam::reading
