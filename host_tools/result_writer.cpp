#include "result_writer.h"

#include <cmath>
#include <cstdio>

namespace icacam::host {

using vision::Measurement;

std::vector<std::string> ResultWriter::columns()
{
    return {"id", "status", "r_inner_mm", "r_outer_mm", "u_mm", "mu", "mu_sigma", "flags",
            "message", "u_px", "u_sigma_mm", "r_max_mm", "centre_x_px", "centre_y_px",
            "centre_offset_px", "edge_width_px", "saturated_fraction", "inner_contrast",
            "outer_contrast", "inner_coverage", "outer_coverage", "inner_scatter_px",
            "outer_scatter_px", "inner_ellipticity", "outer_ellipticity", "inner_axis_deg",
            "outer_axis_deg", "model", "reduction_est", "r_max_z"};
}

std::string ResultWriter::flagList(uint32_t flags)
{
    std::string s;
    for (int b = 0; b < vision::kFlagCount; ++b)
        if (flags & (1u << b)) s += (s.empty() ? "" : ";") + std::string(vision::flagName(b));
    return s;
}

namespace {
std::string num(double v, int prec)
{
    if (!std::isfinite(v)) return "";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", prec, v);
    return buf;
}
std::string csvQuote(const std::string &s)
{
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
    return q + "\"";
}
std::string jsonQuote(const std::string &s)
{
    std::string q = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') { q += '\\'; q += char(c); }
        else if (c < 0x20) { char b[8]; std::snprintf(b, sizeof b, "\\u%04x", c); q += b; }
        else q += char(c);
    }
    return q + "\"";
}
} // namespace

void ResultWriter::header()
{
    if (jsonl_) return;
    const auto cols = columns();
    for (size_t i = 0; i < cols.size(); ++i) out_ << (i ? "," : "") << cols[i];
    out_ << "\n";
}

void ResultWriter::write(const ResultRow &r)
{
    std::vector<std::string> v(columns().size());
    v[0] = r.id;
    v[1] = r.status;
    v[8] = r.message;
    v[27] = r.model;
    const Measurement *m = r.m;
    if (m && m->hasValue()) {
        v[2] = num(m->rInnerMm, 5); v[3] = num(m->rOuterMm, 5); v[4] = num(m->uMm, 5);
        v[5] = num(m->mu, 5); v[6] = num(m->muSigma, 5); v[7] = flagList(m->flags);
        v[9] = num(m->uPx, 3); v[10] = num(m->uSigmaMm, 5);
        v[11] = m->rMaxPx > 0 ? num(m->rMaxMm, 4) : "";
        v[12] = num(m->centreX, 2); v[13] = num(m->centreY, 2);
        v[14] = num(m->centreOffsetPx, 3); v[15] = num(m->edgeWidthPx, 3);
        v[16] = num(m->saturatedFraction, 4);
        v[17] = num(m->inner.contrast, 2); v[18] = num(m->outer.contrast, 2);
        v[19] = num(m->inner.coverage, 3); v[20] = num(m->outer.coverage, 3);
        v[21] = num(m->inner.scatterPx, 3); v[22] = num(m->outer.scatterPx, 3);
        v[23] = num(m->inner.ellipticity, 5); v[24] = num(m->outer.ellipticity, 5);
        v[25] = num(m->inner.axisDeg, 1); v[26] = num(m->outer.axisDeg, 1);
        v[28] = m->reductionEst >= 0 ? num(m->reductionEst, 4) : "";
        v[29] = m->rMaxPx > 0 ? num(m->rMaxZ, 2) : "";
    }
    const auto cols = columns();
    if (jsonl_) {
        out_ << "{";
        for (size_t i = 0; i < cols.size(); ++i) {
            out_ << (i ? "," : "") << jsonQuote(cols[i]) << ":";
            const bool numeric = i >= 2 && i != 7 && i != 8 && i != 27;
            if (v[i].empty()) out_ << (numeric ? "null" : "\"\"");
            else out_ << (numeric ? v[i] : jsonQuote(v[i]));
        }
        out_ << "}\n";
    } else {
        for (size_t i = 0; i < cols.size(); ++i) out_ << (i ? "," : "") << csvQuote(v[i]);
        out_ << "\n";
    }
    out_.flush();
}

} // namespace icacam::host
