#include "firmware/screen.h"

#include <cstdio>

#include "firmware/font5x7.h"

namespace icacam::fw {

using vision::ErrorCode;

const char *shortError(ErrorCode c)
{
    switch (c) {
    case ErrorCode::None: return "";
    case ErrorCode::NotConfigured: return "not configured";
    case ErrorCode::FrameTooLarge: return "frame too large";
    case ErrorCode::BadFrame: return "bad frame";
    case ErrorCode::BadSpecimen: return "check scale and d0";
    case ErrorCode::NoSpecimen: return "no specimen";
    case ErrorCode::Saturated: return "image saturated";
    case ErrorCode::TooDark: return "image too dark";
    case ErrorCode::OuterEdgeNotFound: return "outer edge not found";
    case ErrorCode::InnerEdgeNotFound: return "inner edge not found";
    case ErrorCode::Blurred: return "image blurred";
    case ErrorCode::InconsistentRing: return "edges out of order";
    case ErrorCode::CalibrationSize: return "calibration size";
    }
    return "unknown error";
}

const char *shortFlag(int bit)
{
    static const char *const kWords[reading::kFlagCount] = {
        "n outside 0.05-0.5", "K outside model",   "mu below model",     "mu above model",   "u outside model",
        "low contrast",       "edge coverage low", "edges scatter",      "image blurred",    "saturated",
        "specimen clipped",   "elliptical",        "not concentric",     "check scale",      "narrow ring",
        "no silhouette",      "reduction outside", "radii inconsistent", "H0/D0 outside",    "silhouette unusable",
        "not pressed to 50%", "edges undecided",   "contact edge ramp",  "declare distance", "tilt disagrees"};
    return bit >= 0 && bit < reading::kFlagCount ? kWords[bit] : "check";
}

namespace {

// Word-wraps text into rows [row, lastRow] of the screen.
void wrap(hal::MonoBitmap *bmp, int row, int lastRow, std::string_view text)
{
    while (!text.empty() && row <= lastRow) {
        size_t take = text.size() <= size_t(kColumns) ? text.size() : text.rfind(' ', size_t(kColumns));
        if (take == std::string_view::npos || take == 0) take = size_t(kColumns);
        drawText(bmp, 0, row++, text.substr(0, take));
        text.remove_prefix(take);
        while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    }
}

} // namespace

void drawIdle(hal::MonoBitmap *bmp, const Config &cfg, long records, std::string_view note)
{
    bmp->clear();
    char line[64];
    drawText(bmp, 0, 0, "icacam  ready");
    std::snprintf(line, sizeof line, "n=%.3f K=%.0f", cfg.n, cfg.kMpa);
    drawText(bmp, 0, 2, line);
    std::snprintf(line, sizeof line, "%.5f mm/px", cfg.mmPerPx);
    drawText(bmp, 0, 3, line);
    if (!cfg.material.empty()) drawText(bmp, 0, 4, cfg.material);
    std::snprintf(line, sizeof line, "%ld in journal", records);
    drawText(bmp, 0, 6, line);
    if (!note.empty()) drawText(bmp, 0, 7, note);
}

void drawBusy(hal::MonoBitmap *bmp, long id)
{
    bmp->clear();
    char line[40];
    std::snprintf(line, sizeof line, "#%ld", id);
    drawText(bmp, 0, 0, line);
    drawText(bmp, 0, 3, "measuring...");
}

namespace {

// The advice in the display's words: the input and U after, or what U mostly is.
void adviceLine(const reading::Advice &a, char *line, size_t size)
{
    using reading::AdviceInput;
    if (a.scaleUnchecked) // an oblique view: neither height nor scale checked
        std::snprintf(line, size, "oblique: calibrate");
    else if (a.input == AdviceInput::None)
        std::snprintf(line, size, "U: %s", a.modelLeads ? "model's own" : "edges'");
    else if (a.input == AdviceInput::HFinal && a.reductionUnchecked)
        std::snprintf(line, size, "h unchecked U->%.4f", a.uThen); // 21 columns
    else if (a.input == AdviceInput::HFinal)
        std::snprintf(line, size, "h_final_mm U->%.4f", a.uThen);
    else if (a.input == AdviceInput::WorkingDistance)
        std::snprintf(line, size, "distance U->%.4f", a.uThen); // working_distance_mm
    else
        std::snprintf(line, size, "%s %g U->%.4f", reading::adviceInputName(a.input), a.value, a.uThen);
}

} // namespace

void drawResult(hal::MonoBitmap *bmp, long id, const reading::Reading &m, std::string_view note)
{
    bmp->clear();
    char line[64];
    std::snprintf(line, sizeof line, "#%ld %s", id, reading::statusName(m.status));
    drawText(bmp, 0, 0, line);
    if (!m.hasValue()) {
        wrap(bmp, 2, 5, shortError(m.error));
    } else {
        // μ ± U (k = 2), the decision against the lab's tolerance, then the checks' findings
        // (warn) or the advice (ok).
        std::snprintf(line, sizeof line, "\xCE\xBC=%.3f\xC2\xB1%.3f U", m.mu, m.expanded());
        drawText(bmp, 0, 2, line);
        std::snprintf(line, sizeof line, "u=%.3f mm", m.uMm);
        drawText(bmp, 0, 3, line);
        std::snprintf(line, sizeof line, "U %s tol %.3f", reading::decisionName(m.decision), m.toleranceMu);
        drawText(bmp, 0, 4, line);
        int row = 5;
        for (int b = 0; b < reading::kFlagCount && row <= 6; ++b)
            if (m.flags & (1u << b)) drawText(bmp, 0, row++, shortFlag(b));
        if (row <= 6) {
            adviceLine(m.advice, line, sizeof line);
            drawText(bmp, 0, row, line);
        }
    }
    if (!note.empty()) drawText(bmp, 0, 7, note);
}

void drawProblem(hal::MonoBitmap *bmp, std::string_view title, std::string_view words)
{
    bmp->clear();
    drawText(bmp, 0, 0, title);
    wrap(bmp, 2, 7, words);
}

void drawSettings(hal::MonoBitmap *bmp, const Config &cfg)
{
    bmp->clear();
    char line[64];
    drawText(bmp, 0, 0, "settings");
    std::snprintf(line, sizeof line, "n     %.4f", cfg.n);
    drawText(bmp, 0, 2, line);
    std::snprintf(line, sizeof line, "K     %.0f MPa", cfg.kMpa);
    drawText(bmp, 0, 3, line);
    std::snprintf(line, sizeof line, "D0 %.1f H0 %.1f mm", cfg.d0Mm, cfg.h0Mm);
    drawText(bmp, 0, 4, line);
    std::snprintf(line, sizeof line, "scale %.6f", cfg.mmPerPx);
    drawText(bmp, 0, 5, line);
    drawText(bmp, 0, 6, cfg.material);
}

} // namespace icacam::fw
