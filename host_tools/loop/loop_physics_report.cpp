#include "host_tools/loop/loop_physics_report.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <utility>

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

// σ of the drifting factor at x: a and b are nearly uncorrelated (x centred on its mean).
double driftSigmaAt(const DriftFit &d, double x)
{
    const double dx = x - d.xMean;
    return std::sqrt(d.levelSigma * d.levelSigma + dx * dx * d.slopeSigma * d.slopeSigma);
}

std::string list(const std::vector<std::string> &v)
{
    std::string s;
    for (const std::string &x : v) s += (s.empty() ? "`" : ", `") + x + "`";
    return s;
}

// What would model a process variable: by what the column records. A rate is not the flow
// curve's: in CalculiX a rate-sensitive flow curve leaves u as it is over a decade of press
// speed (docs/fe.md, "Rate dependence").
std::string nextStudy(const std::string &name)
{
    auto has = [&](const char *w) { return name.find(w) != std::string::npos; };
    if (has("speed") || has("rate") || has("velocity"))
        return "not the material's rate sensitivity: with σ = K ε^n (ε̇/ε̇₀)^m the FE's u moves by less than 2 % "
               "over a decade of press speed (m 0.05, docs/fe.md), while m itself acts on u as a constant of the "
               "material read with its n; look for friction that depends on speed (the lubricant's regime: μ_ref "
               "measured at the recorded speeds) or for heating of the specimen and the dies at the faster speeds";
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

namespace {

void writePhysicalRows(std::ostream &f, int order, const LoopEffectStep &e, const LoopSummary &s)
{
    const std::string k = std::to_string(order) + ",";
    if (e.reading == "scale" || e.reading == "n")
        for (const GroupFit &g : e.grouping.groups)
            f << k << e.name << "," << e.reading << "," << g.level << "," << g.records << "," << fmt(g.declared) << ","
              << fmt(g.value, "%.5f") << "," << fmt(g.sigma, "%.5f") << "," << fmt(kCoverage * g.sigma, "%.5f") << ","
              << (!g.fitted    ? "too_few_records"
                  : differs(g) ? (e.reading == "scale" ? "recalibrate" : "revise_n")
                               : "consistent")
              << "," << (g.silhouette > 0 ? fmt(g.silhouette, "%.5f") : "") << ","
              << (g.silhouette > 0 ? fmt(g.silhouetteSigma, "%.5f") : "") << "\n";
    else if (e.reading == "process" && e.levelSlopes.empty())
        f << k << e.name << ",process_" << e.linear.form << ",," << s.usable << ",0," << fmt(e.linear.slope, "%.6g")
          << "," << fmt(e.linear.sigma, "%.6g") << "," << fmt(kCoverage * e.linear.sigma, "%.6g") << ",fe_study,,\n";
    else if (e.reading == "process")
        for (size_t j = 0; j < e.levelSlopes.size(); ++j) {
            const LinearEffect &l = e.levelSlopes[j];
            f << k << e.name << ",process_" << l.form << "_per_level," << e.slopeLevels[j] << ",,0,"
              << fmt(l.slope, "%.6g") << "," << fmt(l.sigma, "%.6g") << "," << fmt(kCoverage * l.sigma, "%.6g") << ","
              << (std::fabs(l.slope) > kCoverage * l.sigma ? "fe_study" : "consistent") << ",,\n";
        }
    else if (e.reading == "drift")
        for (const auto &[at, factor] :
             {std::pair{e.drift.xMin, e.drift.startFactor}, std::pair{e.drift.xMax, e.drift.endFactor}})
            f << k << e.name << ",drift," << fmt(at, "%.6g") << "," << s.usable << ",1," << fmt(factor, "%.5f") << ","
              << fmt(driftSigmaAt(e.drift, at), "%.5f") << "," << fmt(kCoverage * driftSigmaAt(e.drift, at), "%.5f")
              << "," << (e.drift.drifts() ? "recalibrate" : "consistent") << ",,\n";
    else if (e.reading == "fe_slope")
        f << k << e.name << ",fe_slope_scale,," << s.usable << ",1," << fmt(s.slopeScale, "%.5f") << ",,,"
          << (std::fabs(s.slopeScale - 1) <= 0.15 ? "consistent" : "fe_slope_off") << ",,\n";
}

} // namespace

void writePhysicalCsv(const std::string &path, const LoopSummary &s)
{
    std::ofstream f(path);
    f << "effect,candidate,reading,level,records,declared,value,sigma,expanded,verdict,silhouette,silhouette_sigma\n";
    for (size_t i = 0; i < s.effects.size(); ++i) writePhysicalRows(f, int(i + 1), s.effects[i], s);
}

void writePhysicalSection(std::ostream &f, const LoopEffectStep &e, bool first, const LoopSummary &s)
{
    f << "`" << e.name << "` (" << e.kind << ", ranked in form `" << e.form << "`"
      << (e.via.empty() ? std::string()
                        : "; it led as `" + e.via + "`, a property each `" + e.name +
                              "` declares, and is read as the " + e.name + "'s")
      << ").\n\n";
    f << "| held-out error in μ (k-fold) | RMS |\n|---|---|\n";
    if (first) {
        f << "| before (model as is) | " << fmt(s.rmsBefore) << " |\n";
        f << "| constant offset only | " << fmt(s.cvRmsOffset) << " |\n";
    } else {
        f << "| with the effects above (each refitted per fold) | " << fmt(e.cvRmsBefore) << " |\n";
    }
    f << "| patch: the best linear regression of the residual (form `" << e.patchForm << "`) | " << fmt(e.cvRmsPatch)
      << " |\n";
    if (e.reading == "scale" || e.reading == "n" || e.reading == "drift" || !first)
        f << "| **physical: "
          << (e.reading == "scale"   ? "a length factor per group"
              : e.reading == "n"     ? "an n per material"
              : e.reading == "drift" ? "a length factor drifting along `" + e.name + "`"
                                     : "as read below")
          << (first ? "" : ", with the effects above") << "** | **" << fmt(e.cvRmsAfter) << "** |\n";
    f << "\n";
    if (e.reading == "scale") {
        bool outline = false;
        for (const GroupFit &g : e.grouping.groups) outline = outline || g.withOutline;
        f << "Read as a length scale per group of images (`" << e.name
          << "`): every length a group's camera measures is off by one factor s (measured/true), so μ = "
             "model(u/s, n). ";
        if (outline)
            f << "The barrel's outline is off by the same s: s per group is the outline's R_max against the FE's "
                 "(at each record's n, μ_ref and reduction) relative to the typical group, times one factor for "
                 "every group fitted to μ_ref; σ the outline's standard error of the group's mean (z "
              << fmt(e.witnessZ, "%.1f")
              << " for the groups differing), μ's held-out error confirming the factors; U = " << kCoverage
              << " σ (≈ 95 %).\n\n";
        else
            f << "s fitted per group by least squares against μ_ref; σ the larger of the pooled scatter's (after "
                 "the fit, "
              << fmt(e.grouping.scatter) << " in μ) and the jackknife's over the group's records; U = " << kCoverage
              << " σ (≈ 95 %).\n\n";
        f << "| " << e.name
          << " | records | factor s (measured/true) | σ | U (k = 2) | fix mm_per_px by × | verdict | "
             "silhouette check: R_max against the consistent groups' (± 2σ) |\n"
             "|---|---|---|---|---|---|---|---|\n";
        for (const GroupFit &g : e.grouping.groups)
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
    } else if (e.reading == "n") {
        f << "Read as the strain-hardening exponent per material (`" << e.name
          << "`): the n that makes that material's records consistent, "
             "μ = model(u, n + Δn), Δn fitted by least squares against μ_ref; σ the larger of the pooled "
             "scatter's (after the fit, "
          << fmt(e.grouping.scatter) << " in μ) and the jackknife's over the material's records; U = " << kCoverage
          << " σ (≈ 95 %).\n\n";
        f << "| " << e.name
          << " | records | declared n | fitted n | σ | U (k = 2) | verdict |\n|---|---|---|---|---|---|---|\n";
        for (const GroupFit &g : e.grouping.groups)
            f << "| " << g.level << " | " << g.records << " | " << fmt(g.declared) << " | " << fmt(g.value) << " | "
              << fmt(g.sigma) << " | " << fmt(kCoverage * g.sigma) << " | "
              << (!g.fitted    ? "too few records"
                  : differs(g) ? "**declared n is off**"
                               : "consistent")
              << " |\n";
        f << "\nRecommended: for a material marked *declared n is off*, refit its flow curve σ = K·ε^n over the "
             "strains the upset reaches (a flow curve read at the wrong strain range gives another n) and declare "
             "the new n; the fitted n above is what its records say.\n";
    } else if (e.reading == "drift") {
        const DriftFit &d = e.drift;
        f << "Read as a length scale drifting along `" << e.name
          << "`: every length the records' images give is off by s(x) = a + b·(x − x̄) (measured/true), "
             "μ = model(u/s(x), n), a and b fitted by least squares against μ_ref; σ from the pooled scatter "
             "after the fit ("
          << fmt(d.scatter) << " in μ); U = " << kCoverage << " σ.\n\n";
        f << "| `" << e.name << "` | factor s | U (k = 2) |\n|---|---|---|\n";
        f << "| " << fmt(d.xMin, "%.6g") << " (first) | " << fmt(d.startFactor) << " | "
          << fmt(kCoverage * driftSigmaAt(d, d.xMin)) << " |\n";
        f << "| " << fmt(d.xMax, "%.6g") << " (last) | " << fmt(d.endFactor) << " | "
          << fmt(kCoverage * driftSigmaAt(d, d.xMax)) << " |\n\n";
        f << "Drift " << fmt(d.slope, "%.4g") << " ± " << fmt(kCoverage * d.slopeSigma, "%.2g")
          << " (k = 2) per unit of `" << e.name << "`"
          << (d.drifts() ? ": the scale moved during the run. Recommended: check the camera's mounting and "
                           "working distance, recalibrate, and check the scale along the run (the reference disc's "
                           "scale check, docs/firmware.md) until it holds.\n"
                         : ": within its uncertainty of none.\n");
    } else if (e.reading == "process" && !e.levelSlopes.empty()) {
        const bool logarithmic = !e.levelSlopes.empty() && e.levelSlopes.front().logarithmic;
        f << "A recorded process variable acting within one level of a grouping (a slope in the level where it "
             "explains the records best, significant against none and against one slope common to every level; "
             "form `"
          << e.form << "`), applied here as that regression (the patch). Each level's own slope per unit of "
          << (logarithmic ? "ln(`" + e.name.substr(0, e.name.find("_by_")) + "`)" : "its variable")
          << ":\n\n| level | records' slope | U (k = 2) | verdict |\n|---|---|---|---|\n";
        for (size_t j = 0; j < e.levelSlopes.size(); ++j) {
            const LinearEffect &l = e.levelSlopes[j];
            f << "| " << e.slopeLevels[j] << " | " << fmt(l.slope, "%.4g") << " | " << fmt(kCoverage * l.sigma, "%.2g")
              << " | " << (std::fabs(l.slope) > kCoverage * l.sigma ? "**acts**" : "none within U") << " |\n";
        }
        f << "\nNext step: " << nextStudy(e.name) << ", for the levels where it acts.\n";
    } else if (e.reading == "process") {
        const LinearEffect &l = e.linear;
        const char *unit = l.form == "u" ? "mm of u" : l.form == "scale" ? "relative u" : "μ";
        f << "A recorded process variable the FE does not model. Best form `" << l.form << "` ("
          << (l.form == "u"       ? "an additive shift of u, linear in it"
              : l.form == "scale" ? "a relative change of u, linear in it"
                                  : "an offset in μ, linear in it")
          << "): " << fmt(l.slope, "%.4g") << " ± " << fmt(l.sigma, "%.2g") << " (1 σ) " << unit << " per unit of "
          << (l.logarithmic ? "ln(`" + e.name + "`) (a rate acts through its logarithm)" : "`" + e.name + "`")
          << (l.form == "scale" ? " (u changes by " + fmt(100 * l.slope, "%.2f") + " % per unit)" : std::string())
          << "; over the recorded range " << fmt(l.xMin, "%.3g") << "–" << fmt(l.xMax, "%.3g")
          << " it moves μ by about " << fmt(l.muSpan)
          << ". It is applied here as that regression (the patch); "
             "there is no physical form to add yet.\n\n";
        f << "Next step: " << nextStudy(e.name) << ".\n";
    } else if (e.reading == "patch" && isReductionCandidate(e.name) && !first) {
        f << "Applied as its one-candidate regression of the residual (k-fold). The reduction was carried to 50 % "
             "with the FE du/dr above; what it explains after that is the FE slope's own error (the FE slope's "
             "least-squares scale on these records: "
          << fmt(s.slopeScale, "%.3f")
          << "). Better-converged FE runs past 50 % are the fix, not this regression, which stays a patch on these "
             "records.\n";
    } else if (e.reading == "patch") {
        f << "Applied as its one-candidate regression of the residual (k-fold). "
          << (e.symptom ? "It is a measured quantity and no recorded condition explains the residual as well: "
                          "the cause was not recorded. Form `scale` points to the optics (calibration, lens, "
                          "working distance), form `u` to the upsetting.\n"
                        : "\n");
    }
    if (e.takenFirst)
        f << "\nTaken out before the effects added ahead of it: the outline shows it (z " << fmt(e.witnessZ, "%.1f")
          << "), and those effects, fitted to μ with its images among their records, had taken up part of it. The "
             "held-out RMS is with it taken out first and every other effect refitted after it on each fold's "
             "training records.\n";
    if (!e.given.empty())
        f << "\nNot significant over the family on its own: with `" << e.given << "` taken out it is (z "
          << fmt(e.givenZ, "%.1f") << "), and `" << e.given
          << "` is with it taken out. Each carried the other's scatter; the next effect is read on what this one "
             "leaves.\n";
    if (!e.subsumes.empty())
        f << "\nRead before `" << e.subsumes << "`, which ranked ahead of it: with `" << e.name
          << "` taken out that one is not significant (z " << fmt(e.subsumedZ, "%.1f") << "), and `" << e.name
          << "` is with it taken out (z " << fmt(e.subsumesZ, "%.1f") << "): it explains what `" << e.subsumes
          << "` did and more.\n";
    if (!e.sameResidual.empty())
        f << "\nCould not be separated from " << list(e.sameResidual)
          << ": they take out mostly the same part of the residual, and with either taken out the other is not "
             "significant. The records cannot say which it is; `"
          << e.name << "` (the lower held-out error) is read here, and the others are not added after it. Records "
          << "where they differ would tell.\n";
    if (!e.inseparable.empty())
        f << "\nNot separable from " << list(e.inseparable) << ": they group these records the same way and explain "
          << "the residual as well (paired z < 2). The records cannot say which it is; `" << e.name
          << "` is read here, and the others are not added after it. Records where they differ would tell.\n";
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
    if (!lead.aheadOfBetter.empty())
        f << "\n`" << lead.name << "` (a recorded condition) is taken before " << list(lead.aheadOfBetter)
          << ", measured quantities that explain the residual significantly better: they see more than it "
             "does, and the next round looks at what it leaves.\n";
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
    for (size_t i = 0; i < s.effects.size(); ++i) {
        const LoopEffectStep &e = s.effects[i];
        out << "effect " << i + 1 << " " << e.name << " " << e.reading << " cv_rms " << fmt(e.cvRmsBefore) << " -> "
            << fmt(e.cvRmsAfter) << "\n";
        bool outline = false;
        for (const GroupFit &g : e.grouping.groups) outline = outline || (e.reading == "scale" && g.withOutline);
        if (outline)
            out << "witnessed " << e.name << " by the outline, z " << fmt(e.witnessZ, "%.1f")
                << (e.takenFirst ? ", taken out before the effects above" : "") << "\n";
        for (const GroupFit &g : e.grouping.groups)
            out << (e.reading == "scale" ? "factor " : "n ") << g.level << " " << fmt(g.value) << " +- "
                << fmt(kCoverage * g.sigma) << " (k=2)" << (e.reading == "n" ? " declared " + fmt(g.declared) : "")
                << (differs(g) ? " differs" : "") << "\n";
        if (e.reading == "process" && e.levelSlopes.empty())
            out << "slope " << e.linear.form << " " << fmt(e.linear.slope, "%.4g") << " +- "
                << fmt(e.linear.sigma, "%.2g") << " per unit of "
                << (e.linear.logarithmic ? "ln(" + e.name + ")" : e.name) << "\n";
        for (size_t j = 0; j < e.levelSlopes.size(); ++j)
            out << "slope " << e.levelSlopes[j].form << " " << e.slopeLevels[j] << " "
                << fmt(e.levelSlopes[j].slope, "%.4g") << " +- " << fmt(e.levelSlopes[j].sigma, "%.2g") << "\n";
        if (e.reading == "drift")
            out << "drift factor " << fmt(e.drift.startFactor) << " -> " << fmt(e.drift.endFactor) << " +- "
                << fmt(kCoverage * driftSigmaAt(e.drift, e.drift.xMax)) << " (k=2)"
                << (e.drift.drifts() ? " differs" : "") << "\n";
        if (!e.inseparable.empty() || !e.sameResidual.empty()) {
            out << "inseparable " << e.name;
            for (const std::string &o : e.inseparable) out << " " << o;
            for (const std::string &o : e.sameResidual) out << " " << o;
            out << "\n";
        }
    }
    if (!s.chosen.empty()) out << "stopped " << s.stopped << "\n";
    if (!s.ranking.empty() && !s.ranking.front().pointedBy.empty() && !s.chosen.empty())
        out << "pointed_by " << s.ranking.front().pointedBy.front() << "\n";
}

} // namespace icacam::host::loop
