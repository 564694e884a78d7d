// Stable names for statuses, flags, decisions and advised inputs: they appear in CSV, JSON and on serial.
#include "reading/reading.h"

namespace icacam::reading {

const char *statusName(Status s)
{
    switch (s) {
    case Status::Ok: return "ok";
    case Status::Warn: return "warn";
    default: return "error";
    }
}

const char *flagName(int bit)
{
    static const char *const kNames[kFlagCount] = {"n_out_of_range",
                                                   "k_out_of_range",
                                                   "mu_below_model",
                                                   "mu_above_model",
                                                   "u_outside_model",
                                                   "low_contrast",
                                                   "low_coverage",
                                                   "high_scatter",
                                                   "blurred",
                                                   "saturated",
                                                   "specimen_clipped",
                                                   "elliptical",
                                                   "centre_offset",
                                                   "scale_suspect",
                                                   "narrow_ring",
                                                   "no_silhouette",
                                                   "reduction_outside_model",
                                                   "radii_inconsistent",
                                                   "aspect_outside_model",
                                                   "silhouette_unreliable",
                                                   "reduction_not_nominal",
                                                   "contact_edge_undecided",
                                                   "contact_edge_ramp",
                                                   "working_distance_decides",
                                                   "tilt_disagrees"};
    return bit >= 0 && bit < kFlagCount ? kNames[bit] : "unknown";
}

const char *decisionName(Decision d)
{
    return d == Decision::Within ? "within" : "beyond";
}

const char *adviceInputName(AdviceInput a)
{
    switch (a) {
    case AdviceInput::HFinal: return "h_final_mm";
    case AdviceInput::HFinalTol: return "h_final_tol_mm";
    case AdviceInput::ScaleTol: return "mm_per_px_tol";
    case AdviceInput::NTol: return "n_tol";
    case AdviceInput::WorkingDistance: return "working_distance_mm";
    default: return "none";
    }
}

} // namespace icacam::reading
