#include "reading/reading_record.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace icacam::reading {

namespace {

enum class Field : uint8_t { Status, Flags, Message, Model, Number };

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
};
constexpr int kFieldCount = int(sizeof kFields / sizeof kFields[0]);

// What to declare or improve when a budget component leads past the tolerance.
const char *remedy(uint32_t flags)
{
    if (flags & kFlagReductionUncertain) return "declare h_final_mm (the final height) for a reading within tolerance";
    if (flags & kFlagScaleUncertain) return "check mm_per_px on the end-face plane, or calibrate the camera";
    if (flags & kFlagEdgesUncertain) return "edges scatter: clean the end face, relight or refocus";
    if (flags & kFlagNUncertain) return "n's tolerance dominates: a closer n is needed";
    if (flags & kFlagModelUncertain) return "the friction model's own error exceeds the tolerance here";
    return nullptr;
}

} // namespace

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
    if (m.status == Status::Ok) return;
    char flags[512];
    flagList(m.flags, flags, sizeof flags);
    const char *hint = remedy(m.flags);
    if (hint)
        std::snprintf(buf, size, "check flags: %s; 2 mu_sigma %.4f beyond the tolerance %.4f: %s", flags, 2 * m.muSigma,
                      m.toleranceMu, hint);
    else
        std::snprintf(buf, size, "check flags: %s", flags);
}

void writeReading(const Reading *m, std::string_view message, std::string_view model, RecordSink &sink)
{
    const bool value = m && m->hasValue();
    char flags[512], words[768];
    flags[0] = words[0] = 0;
    if (value) flagList(m->flags, flags, sizeof flags);
    if (message.empty() && m) {
        readingMessage(*m, words, sizeof words);
        message = words;
    }
    for (const FieldSpec &f : kFields) {
        switch (f.kind) {
        case Field::Status: sink.text(f.name, m ? statusName(m->status) : "error"); break;
        case Field::Flags: sink.text(f.name, flags); break;
        case Field::Message: sink.text(f.name, message); break;
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
