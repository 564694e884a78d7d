#include "host_tools/loop/loop_physics_report.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace icacam::host::loop {

namespace {

std::string fmt(double v, const char *f = "%.4f")
{
    char b[48];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// Coverage factor of the stated (expanded) uncertainty: about 95 % for a normal estimate.
constexpr double kCoverage = 2.0;

// A group whose estimate differs from what it declared by more than its expanded uncertainty.
bool differs(const GroupFit &g)
{
    return g.fitted && std::fabs(g.value - g.declared) > kCoverage * g.sigma;
}

std::string list(const std::vector<std::string> &v)
{
    std::string s;
    for (const std::string &x : v) s += (s.empty() ? "`" : ", `") + x + "`";
    return s;
}

// The FE study that would model a process variable: by what the column records.
std::string nextStudy(const std::string &name)
{
    auto has = [&](const char *w) { return name.find(w) != std::string::npos; };
    if (has("speed") || has("rate") || has("velocity"))
        return "a rate-dependent flow curve: FE runs in CalculiX with a viscoplastic material (*PLASTIC with a "
               "*CREEP rate term, fitted to the material's flow curves at two or more strain rates) at the recorded "
               "press speeds, giving du/dv(n, μ) as the sweep gives du/dr; then the model carries u to the reference "
               "speed as it carries u to 50 %";
    if (has("temp") || has("ambient") || has("_c"))
        return "temperature-dependent flow curves (*PLASTIC tables per temperature in CalculiX) and, if the "
               "lubricant is the suspect, μ measured at those temperatures: FE runs at the recorded temperatures "
               "giving du/dT(n, μ)";
    return "an FE study that varies `" + name +
           "` over its recorded range (its physics is not in the sweep), "
           "giving du/d(" +
           name + ")";
}

} // namespace

void writePhysicalCsv(const std::string &path, const LoopSummary &s)
{
    std::ofstream f(path);
    f << "candidate,reading,level,records,declared,value,sigma,expanded,verdict,silhouette,silhouette_sigma\n";
    if (s.reading == "scale" || s.reading == "n")
        for (const GroupFit &g : s.grouping.groups)
            f << s.chosen << "," << s.reading << "," << g.level << "," << g.records << "," << fmt(g.declared) << ","
              << fmt(g.value, "%.5f") << "," << fmt(g.sigma, "%.5f") << "," << fmt(kCoverage * g.sigma, "%.5f") << ","
              << (!g.fitted    ? "too_few_records"
                  : differs(g) ? (s.reading == "scale" ? "recalibrate" : "revise_n")
                               : "consistent")
              << "," << (g.silhouette > 0 ? fmt(g.silhouette, "%.5f") : "") << ","
              << (g.silhouette > 0 ? fmt(g.silhouetteSigma, "%.5f") : "") << "\n";
    else if (s.reading == "process")
        f << s.chosen << ",process_" << s.linear.form << ",," << s.usable << ",0," << fmt(s.linear.slope, "%.6g") << ","
          << fmt(s.linear.sigma, "%.6g") << "," << fmt(kCoverage * s.linear.sigma, "%.6g") << ",fe_study,,\n";
    else if (s.reading == "fe_slope")
        f << s.chosen << ",fe_slope_scale,," << s.usable << ",1," << fmt(s.slopeScale, "%.5f") << ",,,"
          << (std::fabs(s.slopeScale - 1) <= 0.15 ? "consistent" : "fe_slope_off") << ",,\n";
}

void writePhysicalSection(std::ostream &f, const LoopSummary &s)
{
    const RankedCandidate &lead = s.ranking.front();
    f << "`" << s.chosen << "` (" << lead.kind << ", ranked in form `" << lead.form << "`).\n\n";
    f << "| held-out error in μ (k-fold) | RMS |\n|---|---|\n";
    f << "| before (model as is) | " << fmt(s.rmsBefore) << " |\n";
    f << "| constant offset only | " << fmt(s.cvRmsOffset) << " |\n";
    f << "| patch: the best linear regression of the residual (form `" << lead.patchForm << "`) | " << fmt(s.cvRmsPatch)
      << " |\n";
    if (s.reading == "scale" || s.reading == "n")
        f << "| **physical: " << (s.reading == "scale" ? "a length factor per group" : "an n per material") << "** | **"
          << fmt(s.cvRmsAfter) << "** |\n";
    f << "\n";
    if (s.reading == "scale") {
        f << "Read as a length scale per group of images (`" << s.chosen
          << "`): every length a group's camera measures is off by one factor s (measured/true), so μ = "
             "model(u/s, n). s fitted per group by least squares against μ_ref; σ the larger of the pooled "
             "scatter's (after the fit, "
          << fmt(s.grouping.scatter) << " in μ) and the jackknife's over the group's records; U = " << kCoverage
          << " σ (≈ 95 %).\n\n";
        f << "| " << s.chosen
          << " | records | factor s (measured/true) | σ | U (k = 2) | fix mm_per_px by × | verdict | "
             "silhouette check: R_max against the consistent groups' (± 2σ) |\n"
             "|---|---|---|---|---|---|---|---|\n";
        for (const GroupFit &g : s.grouping.groups)
            f << "| " << g.level << " | " << g.records << " | " << fmt(g.value) << " | " << fmt(g.sigma) << " | "
              << fmt(kCoverage * g.sigma) << " | " << fmt(1 / g.value) << " | "
              << (!g.fitted    ? "too few records"
                  : differs(g) ? "**recalibrate**"
                               : "consistent with 1")
              << (g.silhouette > 0 && g.fitted && differs(g)
                      ? (std::fabs(g.silhouette - 1) > kCoverage * g.silhouetteSigma &&
                                 (g.silhouette - 1) * (g.value - 1) > 0
                             ? " (the silhouette agrees)"
                             : " (the silhouette does not: check before recalibrating)")
                      : "")
              << " | "
              << (g.silhouette > 0 ? fmt(g.silhouette) + " ± " + fmt(kCoverage * g.silhouetteSigma) : std::string("—"))
              << " |\n";
        f << "\nRecommended: for every group marked *recalibrate*, recalibrate that camera (`icacam calibrate`, its "
             "calibration file) or multiply its `mm_per_px` by 1/s; its lengths read s × true. Groups consistent "
             "with 1 show what the model itself contributes. The silhouette check uses the geometry alone (the "
             "measured R_max against the FE's at each record's n, μ_ref and reduction, relative to the other "
             "groups whose factor is consistent with 1, ± 2σ statistical): a camera's scale moves it by the same "
             "factor, a friction or model effect does not.\n";
    } else if (s.reading == "n") {
        f << "Read as the strain-hardening exponent per material (`" << s.chosen
          << "`): the n that makes that material's records consistent, "
             "μ = model(u, n + Δn), Δn fitted by least squares against μ_ref; σ the larger of the pooled "
             "scatter's (after the fit, "
          << fmt(s.grouping.scatter) << " in μ) and the jackknife's over the material's records; U = " << kCoverage
          << " σ (≈ 95 %).\n\n";
        f << "| " << s.chosen
          << " | records | declared n | fitted n | σ | U (k = 2) | verdict |\n|---|---|---|---|---|---|---|\n";
        for (const GroupFit &g : s.grouping.groups)
            f << "| " << g.level << " | " << g.records << " | " << fmt(g.declared) << " | " << fmt(g.value) << " | "
              << fmt(g.sigma) << " | " << fmt(kCoverage * g.sigma) << " | "
              << (!g.fitted    ? "too few records"
                  : differs(g) ? "**declared n is off**"
                               : "consistent")
              << " |\n";
        f << "\nRecommended: for a material marked *declared n is off*, refit its flow curve σ = K·ε^n over the "
             "strains the upset reaches (a flow curve read at the wrong strain range gives another n) and declare "
             "the new n; the fitted n above is what its records say.\n";
    } else if (s.reading == "process") {
        const LinearEffect &e = s.linear;
        const char *unit = e.form == "u" ? "mm of u" : e.form == "scale" ? "relative u" : "μ";
        f << "A recorded process variable the FE does not model. Best form `" << e.form << "` ("
          << (e.form == "u"       ? "an additive shift of u, linear in it"
              : e.form == "scale" ? "a relative change of u, linear in it"
                                  : "an offset in μ, linear in it")
          << "): " << fmt(e.slope, "%.4g") << " ± " << fmt(e.sigma, "%.2g") << " (1 σ) " << unit << " per unit of `"
          << s.chosen << "`"
          << (e.form == "scale" ? " (u changes by " + fmt(100 * e.slope, "%.2f") + " % per unit)" : std::string())
          << "; over the recorded range " << fmt(e.xMin, "%.3g") << "–" << fmt(e.xMax, "%.3g")
          << " it moves μ by about " << fmt(e.muSpan)
          << ". It is applied here as that regression (the patch); "
             "there is no physical form to add yet.\n\n";
        f << "Next step: " << nextStudy(s.chosen) << ".\n";
    } else if (s.reading == "patch") {
        f << "Applied as its one-candidate regression of the residual (k-fold). "
          << (lead.symptom ? "It is a measured quantity and no recorded condition explains the residual as well: "
                             "the cause was not recorded. Form `scale` points to the optics (calibration, lens, "
                             "working distance), form `u` to the upsetting.\n"
                           : "\n");
    }
}

void writeSymptomNote(std::ostream &f, const LoopSummary &s)
{
    if (s.ranking.empty() || s.chosen.empty()) return;
    const RankedCandidate &lead = s.ranking.front();
    if (lead.symptom) return;
    if (!lead.preferredOver.empty())
        f << "\n`" << lead.name << "` (a recorded condition) is ranked ahead of " << list(lead.preferredOver)
          << " (measured, with a slightly lower CV RMS): their held-out errors are not significantly smaller "
             "(paired z < 2), and a measured quantity answers to any cause that moves the geometry; the recorded "
             "condition names the cause.\n";
    if (lead.viaSymptom)
        f << "\n`" << lead.name << "` is not significant on its own over the whole family of candidates (z "
          << fmt(lead.z, "%.1f")
          << "); it counts because the symptoms above established the effect and it explains them as well, "
             "and it passes the test of a single comparison.\n";
    if (!lead.pointedBy.empty())
        f << "\nSymptoms that pointed to it (measured quantities that explain the residual significantly, best "
             "first): "
          << list(lead.pointedBy) << ". `" << lead.name << "` is the recorded condition behind them.\n";
    else
        f << "\nNo measured quantity explains the residual significantly on its own: `" << lead.name
          << "` is found from the recorded conditions alone.\n";
}

void printPhysical(std::ostream &out, const LoopSummary &s)
{
    out << "reading " << (s.reading.empty() ? "-" : s.reading) << "\n";
    if (!s.chosen.empty()) out << "cv_rms_patch " << fmt(s.cvRmsPatch) << "\n";
    for (const GroupFit &g : s.grouping.groups)
        out << (s.reading == "scale" ? "factor " : "n ") << g.level << " " << fmt(g.value) << " +- "
            << fmt(kCoverage * g.sigma) << " (k=2)" << (s.reading == "n" ? " declared " + fmt(g.declared) : "")
            << (differs(g) ? " differs" : "") << "\n";
    if (s.reading == "process")
        out << "slope " << s.linear.form << " " << fmt(s.linear.slope, "%.4g") << " +- " << fmt(s.linear.sigma, "%.2g")
            << " per unit of " << s.chosen << "\n";
    if (!s.ranking.empty() && !s.ranking.front().pointedBy.empty() && !s.chosen.empty())
        out << "pointed_by " << s.ranking.front().pointedBy.front() << "\n";
}

} // namespace icacam::host::loop
