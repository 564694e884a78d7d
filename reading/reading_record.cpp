#include "reading/reading_record.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace icacam::reading {

namespace {

enum class Field : uint8_t { Status, Flags, Message, Decision, Advice, Model, Number };

struct FieldSpec {
    const char *name;
    Field kind;
    int decimals;
    // Value of a numeric field; NaN when the reading has none (a silhouette not found …).
    double (*value)(const Reading &m);
};

double nan()
{
    return std::nan("");
}

// A silhouette the image showed, or a radius given with the radii.
bool hasSilhouette(const Reading &m)
{
    return m.geometry.rMaxPx > 0 || (!m.imaged && m.face.rMaxMm > 0);
}

// PRODUCT.md §6 columns, then the budget and what the reading was read at, then diagnostics.
const FieldSpec kFields[] = {
    {"status", Field::Status, 0, nullptr},
    {"r_inner_mm", Field::Number, 5, [](const Reading &m) { return m.rInnerMm(); }},
    {"r_outer_mm", Field::Number, 5, [](const Reading &m) { return m.rOuterMm(); }},
    {"u_mm", Field::Number, 5, [](const Reading &m) { return m.uMm; }},
    {"mu", Field::Number, 5, [](const Reading &m) { return m.mu; }},
    {"mu_sigma", Field::Number, 5, [](const Reading &m) { return m.muSigma; }},
    {"flags", Field::Flags, 0, nullptr},
    {"message", Field::Message, 0, nullptr},
    {"decision", Field::Decision, 0, nullptr},
    {"advice", Field::Advice, 0, nullptr},
    {"sigma_edges", Field::Number, 5, [](const Reading &m) { return m.budget.edges; }},
    {"sigma_scale", Field::Number, 5, [](const Reading &m) { return m.budget.scale; }},
    {"sigma_reduction", Field::Number, 5, [](const Reading &m) { return m.budget.reduction; }},
    {"sigma_n", Field::Number, 5, [](const Reading &m) { return m.budget.n; }},
    {"sigma_model", Field::Number, 5, [](const Reading &m) { return m.budget.model; }},
    {"tolerance_mu", Field::Number, 5, [](const Reading &m) { return m.toleranceMu; }},
    {"reduction", Field::Number, 4, [](const Reading &m) { return m.reduction; }},
    {"reduction_sigma", Field::Number, 4, [](const Reading &m) { return m.reductionSigma; }},
    {"scale_factor", Field::Number, 5, [](const Reading &m) { return m.scaleFactor; }},
    {"model", Field::Model, 0, nullptr},
    {"u_px", Field::Number, 3, [](const Reading &m) { return m.uPx; }},
    {"u_sigma_mm", Field::Number, 5, [](const Reading &m) { return m.uSigmaMm; }},
    {"r_max_mm", Field::Number, 4, [](const Reading &m) { return hasSilhouette(m) ? m.rMaxMm() : nan(); }},
    {"centre_x_px", Field::Number, 2, [](const Reading &m) { return m.geometry.centreX; }},
    {"centre_y_px", Field::Number, 2, [](const Reading &m) { return m.geometry.centreY; }},
    {"centre_offset_px", Field::Number, 3, [](const Reading &m) { return m.centreOffsetPx; }},
    {"edge_width_px", Field::Number, 3, [](const Reading &m) { return m.geometry.edgeWidthPx; }},
    {"inner_edge_width_px", Field::Number, 3, [](const Reading &m) { return m.geometry.innerEdgeWidthPx; }},
    {"contact_ramp_px", Field::Number, 3, [](const Reading &m) { return m.geometry.contactRampPx; }},
    {"saturated_fraction", Field::Number, 4, [](const Reading &m) { return m.geometry.saturatedFraction; }},
    {"inner_contrast", Field::Number, 2, [](const Reading &m) { return m.geometry.inner.contrast; }},
    {"outer_contrast", Field::Number, 2, [](const Reading &m) { return m.geometry.outer.contrast; }},
    {"inner_coverage", Field::Number, 3, [](const Reading &m) { return m.geometry.inner.coverage; }},
    {"outer_coverage", Field::Number, 3, [](const Reading &m) { return m.geometry.outer.coverage; }},
    {"inner_scatter_px", Field::Number, 3, [](const Reading &m) { return m.geometry.inner.scatterPx; }},
    {"outer_scatter_px", Field::Number, 3, [](const Reading &m) { return m.geometry.outer.scatterPx; }},
    {"inner_ellipticity", Field::Number, 5, [](const Reading &m) { return m.innerShape.ellipticity; }},
    {"outer_ellipticity", Field::Number, 5, [](const Reading &m) { return m.outerShape.ellipticity; }},
    {"inner_axis_deg", Field::Number, 1, [](const Reading &m) { return m.innerShape.axisDeg; }},
    {"outer_axis_deg", Field::Number, 1, [](const Reading &m) { return m.outerShape.axisDeg; }},
    {"silhouette_coverage", Field::Number, 3,
     [](const Reading &m) { return m.geometry.rMaxPx > 0 ? m.geometry.silhouetteCoverage : nan(); }},
    {"silhouette_scatter_px", Field::Number, 3,
     [](const Reading &m) {
         return m.geometry.rMaxPx > 0 && m.geometry.silhouetteCoverage > 0 ? m.geometry.silhouetteScatterPx : nan();
     }},
    {"reduction_est", Field::Number, 4, [](const Reading &m) { return m.reductionEst >= 0 ? m.reductionEst : nan(); }},
    {"r_max_z", Field::Number, 2, [](const Reading &m) { return hasSilhouette(m) ? m.rMaxZ : nan(); }},
    {"tilt_knee_px", Field::Number, 3,
     [](const Reading &m) {
         return m.geometry.imageFlags &
                        (vision::kImageContactEdgeByTilt | vision::kImageTiltConfirms | vision::kImageTiltDisagrees)
                    ? m.geometry.tiltKneePx
                    : nan();
     }},
    // Where the segment frames' light came from: segment 0's azimuth and the way round.
    {"segment0_seen_deg", Field::Number, 1,
     [](const Reading &m) { return m.geometry.segmentWay != 0 ? m.geometry.segment0SeenDeg : nan(); }},
    {"segment_way", Field::Number, 0,
     [](const Reading &m) { return m.geometry.segmentWay != 0 ? double(m.geometry.segmentWay) : nan(); }},
};
constexpr int kFieldCount = int(sizeof kFields / sizeof kFields[0]);

// What a check's finding means for the reading, and what to supply or do.
const char *findingWords(int bit)
{
    static const char *const kWords[kFlagCount] = {
        "n outside the model's range: the value is extrapolated",
        "K outside the model's range: the value is extrapolated",
        "mu below the model's range: the value is extrapolated",
        "mu above the model's range: the value is extrapolated",
        "u outside what the model covers at this n: the value is extrapolated",
        "an edge has little contrast: relight the end face",
        "an edge was found on too few rays: clean the end face or relight",
        "the boundary points scatter: clean the end face, relight or refocus",
        "the edges are blurred: refocus",
        "part of the ring is clipped: lower the exposure",
        "the specimen runs off the frame: centre it",
        "the end face looks elliptical: square the camera to the fixture or calibrate it",
        "the boundaries are not concentric: square the camera or check the specimen",
        "the silhouette says the scale is off: check mm_per_px on the end-face plane or declare h_final_mm",
        "the ICA reads only a few pixels wide, or narrower than twice its edges' blur: a finer scale or a sharper "
        "focus is needed; where the original face shows no edge "
        "of its own, the ring read may be the contact edge and the barrel's shoulder beyond it (mu low): light the "
        "face and the ring apart",
        "no barrel silhouette: the scale and the final height are unchecked; declare h_final_mm",
        "the final height lies outside what the model covers",
        "the silhouette contradicts the declared scale and final height: check both",
        "the specimen's H0/D0 lies outside what the model covers",
        "the silhouette does not fit the barrel's shape: declare h_final_mm",
        "the silhouette says another height than half: declare h_final_mm (a close camera sees the barrel inside "
        "R_max: declare working_distance_mm)",
        "the profile does not tell which edge ends the flat face: R_i and R_o may be one edge out; check the image "
        "(a diffuse ring light or a matt barrel removes the band; the ring light lit in segments, segment_images, "
        "tells it)",
        "the contact edge ramps away wider than the original face's edge: R_o may read up to that ramp outside; "
        "a diffuse ring light or a matt barrel gives a step; the ring light lit in segments (segment_images) places it",
        "the silhouette reads another height from a close camera than from a far one: declare working_distance_mm "
        "(or h_final_mm)",
        "the segment frames' tilt places the flat face's end a few pixels from the contact edge the frame shows: "
        "R_o may lie between the two; check that the specimen did not move between the frames, and refocus",
    };
    return bit >= 0 && bit < kFlagCount && kWords[bit] ? kWords[bit] : "check";
}

// no_silhouette where the final height was declared: the height is known, the scale is not.
constexpr const char *kNoSilhouetteHeightDeclared =
    "no barrel silhouette: the declared scale is unchecked (a scale taken on the fixture plane would pass): check "
    "mm_per_px on the end-face plane or calibrate the camera";

// contact_edge_undecided where the image showed why (vision's cause bits); nullptr: the
// profile's band, which the flag's own words describe.
const char *undecidedCauseWords(uint32_t imageFlags)
{
    if (imageFlags & vision::kImageUndecidedFaceHoldsEdge)
        return "the face read shows an edge of its own inside it: the ring may begin there, and the ring read be a "
               "band on the barrel beyond it (mu low); check the image (the ring light lit in segments, "
               "segment_images, tells it)";
    if (imageFlags & vision::kImageUndecidedNoStepBeyond)
        return "the contact edge rises onto lighter ground with no outline beyond it: the ring read may be the "
               "barrel's dark band and the original face's edge the contact edge; check the image (a fixture darker "
               "than the barrel shows its outline; the ring light lit in segments, segment_images, tells it)";
    return nullptr;
}

} // namespace

void adviceText(const Advice &a, char *buf, size_t size)
{
    if (size == 0) return;
    if (a.input == AdviceInput::None)
        std::snprintf(buf, size, "none: U %.4f is mostly the %s", a.uNow, a.modelLeads ? "model's own" : "edges'");
    else if (a.input == AdviceInput::HFinal && a.reductionUnchecked)
        std::snprintf(buf, size, "h_final_mm: U %.4f \xE2\x86\x92 %.4f (height unchecked: U covers 45-55 %%)", a.uNow,
                      a.uThen);
    else if (a.input == AdviceInput::HFinal || a.input == AdviceInput::WorkingDistance)
        std::snprintf(buf, size, "%s: U %.4f \xE2\x86\x92 %.4f", adviceInputName(a.input), a.uNow, a.uThen);
    else
        std::snprintf(buf, size, "%s %g: U %.4f \xE2\x86\x92 %.4f", adviceInputName(a.input), a.value, a.uNow, a.uThen);
    if (a.scaleUnchecked) {
        const size_t used = std::strlen(buf);
        std::snprintf(buf + used, size - used, "; oblique view: the declared scale is unchecked, calibrate the camera");
    }
    if (const size_t used = std::strlen(buf); a.segmentWay != 0 && used + 2 < size) {
        std::snprintf(buf + used, size - used, "; ");
        segmentsAdvice(a, buf + used + 2, size - used - 2);
    }
}

void segmentsAdvice(const Advice &a, char *buf, size_t size)
{
    if (size == 0) return;
    buf[0] = 0;
    if (a.segmentWay < 0)
        std::snprintf(buf, size,
                      "the segment frames run the other way round (segment 0 lights from %.0f deg): list them in "
                      "reverse after segment 0; tilt not read",
                      a.segment0SeenDeg);
    else if (a.segmentWay > 0)
        std::snprintf(buf, size, "segment 0 lights from %.0f deg: set segment0_deg %.0f; tilt not read",
                      a.segment0SeenDeg, a.segment0SeenDeg);
}

namespace {} // namespace

int readingFieldCount()
{
    return kFieldCount;
}
const char *readingFieldName(int i)
{
    return i >= 0 && i < kFieldCount ? kFields[i].name : "";
}

void flagList(uint32_t flags, char *buf, size_t size)
{
    if (size == 0) return;
    size_t n = 0;
    buf[0] = 0;
    for (int bit = 0; bit < kFlagCount; ++bit) {
        if (!(flags & (1u << bit))) continue;
        const int w = std::snprintf(buf + n, size - n, "%s%s", n ? ";" : "", flagName(bit));
        if (w < 0 || size_t(w) >= size - n) {
            buf[n] = 0; // a name that does not fit is left out whole
            break;
        }
        n += size_t(w);
    }
}

void readingMessage(const Reading &m, char *buf, size_t size)
{
    if (size == 0) return;
    buf[0] = 0;
    if (m.status == Status::Error) {
        std::snprintf(buf, size, "%s", vision::errorMessage(m.error));
        return;
    }
    size_t n = 0;
    for (int bit = 0; bit < kFlagCount; ++bit) {
        if (!(m.flags & (1u << bit))) continue;
        int w = 0;
        if ((1u << bit) == kFlagContactEdgeUndecided && undecidedCauseWords(m.geometry.imageFlags)) {
            w = std::snprintf(buf + n, size - n, "%s%s", n ? "; " : "", undecidedCauseWords(m.geometry.imageFlags));
        } else if ((1u << bit) == kFlagNoSilhouette && m.advice.heightDeclared) {
            w = std::snprintf(buf + n, size - n, "%s%s", n ? "; " : "", kNoSilhouetteHeightDeclared);
        } else if ((1u << bit) != kFlagReductionNotNominal) {
            w = std::snprintf(buf + n, size - n, "%s%s", n ? "; " : "", findingWords(bit));
        } else if (std::fabs(m.scaleFactor - 1) < 0.0005) {
            w = std::snprintf(buf + n, size - n, "%s%s (%.1f %%; mu %.4f at 50 %%)", n ? "; " : "", findingWords(bit),
                              100 * m.reduction, m.nominalMu);
        } else {
            // The reading took part of the silhouette's discrepancy as the scale's: μ moved by
            // both, and the height alone would leave the reader wondering why μ moved.
            w = std::snprintf(buf + n, size - n, "%s%s (%.1f %%, scale x%.3f; mu %.4f at 50 %% and the declared scale)",
                              n ? "; " : "", findingWords(bit), 100 * m.reduction, m.scaleFactor, m.nominalMu);
        }
        if (w < 0 || size_t(w) >= size - n) {
            buf[n] = 0; // a finding that does not fit is left out whole
            break;
        }
        n += size_t(w);
    }
}

void writeReading(const Reading *m, std::string_view message, std::string_view model, RecordSink &sink)
{
    const bool value = m && m->hasValue();
    char flags[512], words[768], advice[256];
    flags[0] = words[0] = advice[0] = 0;
    if (value) {
        flagList(m->flags, flags, sizeof flags);
        adviceText(m->advice, advice, sizeof advice);
    }
    if (message.empty() && m) {
        readingMessage(*m, words, sizeof words);
        message = words;
    }
    for (const FieldSpec &f : kFields) {
        switch (f.kind) {
        case Field::Status: sink.text(f.name, m ? statusName(m->status) : "error"); break;
        case Field::Flags: sink.text(f.name, flags); break;
        case Field::Message: sink.text(f.name, message); break;
        case Field::Decision: sink.text(f.name, value ? decisionName(m->decision) : ""); break;
        case Field::Advice: sink.text(f.name, advice); break;
        case Field::Model: sink.text(f.name, model); break;
        case Field::Number:
            if (value && std::isfinite(f.value(*m)))
                sink.number(f.name, f.value(*m), f.decimals);
            else
                sink.absent(f.name);
            break;
        }
    }
}

} // namespace icacam::reading
