#include "host_tools/loop/loop_records.h"

#include <cmath>

#include "vision/error.h"

namespace icacam::host::loop {

using namespace icacam::reading;

namespace {

// The image's diagnostics, candidates the ranking may name.
void keepDiagnostics(const Reading &m, LoopRecord *r)
{
    auto &d = r->diagnostics;
    d["diag_u_mm"] = r->uMm;
    d["diag_r_inner_mm"] = m.face.rInnerMm;
    d["diag_r_outer_mm"] = m.face.rOuterMm;
    if (m.face.rMaxMm > 0) d["diag_rmax_over_r0"] = m.face.rMaxMm / (0.5 * r->d0Mm);
    if (m.reductionEst >= 0) d["diag_reduction_est"] = m.reductionEst; // from R_max and the FE
    const vision::EndFaceGeometry &g = m.geometry;
    d["diag_inner_contrast"] = g.inner.contrast;
    d["diag_outer_contrast"] = g.outer.contrast;
    d["diag_inner_coverage"] = g.inner.coverage;
    d["diag_outer_coverage"] = g.outer.coverage;
    d["diag_inner_scatter_px"] = g.inner.scatterPx;
    d["diag_outer_scatter_px"] = g.outer.scatterPx;
    d["diag_inner_ellipticity"] = m.innerShape.ellipticity;
    d["diag_outer_ellipticity"] = m.outerShape.ellipticity;
    d["diag_outer_axis_deg"] = m.outerShape.axisDeg;
    d["diag_centre_offset_px"] = m.centreOffsetPx;
    d["diag_edge_width_px"] = g.edgeWidthPx;
    d["diag_saturated_fraction"] = g.saturatedFraction;
    d["diag_u_px"] = m.uPx;
    d["diag_flag_count"] = double(__builtin_popcount(m.flags));
}

} // namespace

bool readLoopRecord(const ManifestRow &row, const Manifest &manifest, RecordMeasurer &measurer, LoopRecord *r,
                    std::string *why)
{
    if (!row.error.empty()) {
        *why = row.error;
        return false;
    }
    if (!row.has("mu_ref") || row.get("mu_ref").empty() || !parseNumber(row.get("mu_ref"), &r->muRef)) {
        *why = row.has("mu_ref") && !row.get("mu_ref").empty() ? "bad number in mu_ref" : "no mu_ref";
        return false;
    }
    double ri = 0, ro = 0;
    const bool radii = row.has("r_inner_mm") && row.has("r_outer_mm") && parseNumber(row.get("r_inner_mm"), &ri) &&
                       parseNumber(row.get("r_outer_mm"), &ro);
    if (!radii && !row.has("image")) {
        *why = "neither image nor r_inner_mm/r_outer_mm";
        return false;
    }
    Reading m;
    SpecimenSpec spec;
    if (radii) {
        if (!measurer.readSpec(row, false, &spec, why)) return false;
        FaceInMm face{ri, ro, 0, 0};
        double rb;
        if (row.has("r_bulge_mm") && parseNumber(row.get("r_bulge_mm"), &rb)) face.rMaxMm = rb;
        m = measurer.instrument().interpret(face, spec);
    } else {
        host::RecordReading reading;
        measurer.measure(row, manifest, &reading);
        if (!reading.measured) {
            *why = reading.message;
            return false;
        }
        if (!reading.reading.hasValue()) {
            *why = vision::errorMessage(reading.reading.error);
            return false;
        }
        spec = reading.spec;
        m = reading.reading;
    }
    if (!(spec.n > 0)) {
        *why = "missing n";
        return false;
    }
    r->n = spec.n, r->kMpa = spec.kMpa, r->d0Mm = spec.d0Mm, r->h0Mm = spec.h0Mm;
    if (spec.hFinalMm > 0 && spec.h0Mm > 0) r->reduction = 1.0 - spec.hFinalMm / spec.h0Mm;
    r->uMm = m.face.uMm;
    if (radii) {
        r->diagnostics["diag_u_mm"] = r->uMm;
        if (m.face.rMaxMm > 0) r->diagnostics["diag_rmax_over_r0"] = m.face.rMaxMm / (0.5 * r->d0Mm);
    } else {
        keepDiagnostics(m, r);
    }
    for (int bit = 0; bit < kFlagCount; ++bit)
        if (m.flags & (1u << bit)) r->flags += (r->flags.empty() ? "" : ";") + std::string(flagName(bit));
    r->muModel = m.declared.mu;
    r->scaleSens = m.declared.dMuDu * r->uMm;
    r->uSens = m.declared.dMuDu;
    for (const std::string &c : manifest.columns) r->columns[c] = row.get(c);
    r->usable = true;
    return true;
}

} // namespace icacam::host::loop
