#include "host_tools/loop/loop_report.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "host_tools/loop/loop_physics_report.h"
#include "host_tools/loop/loop_plot.h"
#include "host_tools/number_text.h"

#ifndef ICACAM_LOOP_SOURCE_DIR
#define ICACAM_LOOP_SOURCE_DIR "."
#endif

namespace icacam::host::loop {

namespace fs = std::filesystem;

namespace {

std::string f4(double v, const char *fmt = "%.4f")
{
    return numberText(fmt, v);
}

// Paths as the report names them: relative to the source tree when under it (a report
// committed from one checkout reads the same in another).
std::string joined(const std::vector<std::string> &v)
{
    const std::string root = fs::path(ICACAM_LOOP_SOURCE_DIR).lexically_normal().string() + "/";
    std::string s;
    for (const std::string &x : v) {
        const std::string p = fs::path(x).lexically_normal().string();
        s += (s.empty() ? "" : ", ") + (p.rfind(root, 0) == 0 ? p.substr(root.size()) : p);
    }
    return s;
}

std::string pathIn(const ReportContext &c, const std::string &name)
{
    return (fs::path(c.dir) / name).string();
}

// The rankings of every round: the first on the residual as the model reads it, then the
// round that added each further effect, then the round that added nothing.
std::vector<const std::vector<RankedCandidate> *> rounds(const LoopSummary &s)
{
    std::vector<const std::vector<RankedCandidate> *> out{&s.ranking};
    for (size_t i = 1; i < s.effects.size(); ++i) out.push_back(&s.effects[i].ranking);
    auto same = [](const std::vector<RankedCandidate> &a, const std::vector<RankedCandidate> &b) {
        if (a.size() != b.size()) return false;
        for (size_t k = 0; k < a.size(); ++k)
            if (a[k].name != b[k].name || a[k].z != b[k].z) return false;
        return true;
    };
    if (!s.lastRanking.empty() && !same(s.lastRanking, *out.back())) out.push_back(&s.lastRanking);
    return out;
}

// The ids of a candidate's most influential records, ';'-separated.
std::string influentialIds(const RankedCandidate &r, const ResidualSet &set)
{
    std::string ids;
    for (size_t i : r.influential)
        if (i < set.usable.size()) ids += (ids.empty() ? "" : ";") + set.usable[i].id;
    return ids;
}

void writeRankingCsv(const ReportContext &c, const ResidualSet &set, const LoopSummary &s)
{
    std::ofstream f(pathIn(c, "ranking.csv"));
    f << "rank,candidate,kind,form,cv_rms_before,cv_rms_after,gain,z,correlation,chosen,symptom,round,"
         "influential,z_without,carried\n";
    const std::vector<const std::vector<RankedCandidate> *> all = rounds(s);
    for (size_t round = 0; round < all.size(); ++round) {
        // The candidate a round added: the first effect, then each further one in its round.
        const std::string added = round < s.effects.size() ? s.effects[round].name : "";
        int k = 0;
        for (const RankedCandidate &r : *all[round]) {
            ++k;
            f << k << "," << r.name << "," << r.kind << "," << r.form << "," << f4(r.cvRmsBefore, "%.5f") << ","
              << f4(r.cvRmsAfter, "%.5f") << "," << f4(r.gain, "%.5f") << "," << f4(r.z, "%.2f") << ","
              << f4(r.correlation, "%.3f") << ","
              << (k == 1 && !added.empty() && (r.name == added || r.name == s.effects[round].via) ? "yes"
                  : r.significant                                                                 ? "significant"
                                                                                                  : "no")
              << "," << (r.symptom ? "yes" : "no") << "," << round + 1 << "," << influentialIds(r, set) << ","
              << (r.influential.empty() ? "" : f4(r.zWithout, "%.2f")) << "," << (r.carried ? "yes" : "no") << "\n";
        }
    }
}

// Per record; corrected: the physical form fitted on every record.
void writeRecordsCsv(const ReportContext &c, const ResidualSet &set, const LoopSummary &s)
{
    const bool corrected = s.physical || !s.grouping.muAfter.empty();
    const std::vector<double> &muCorrected = s.physical ? set.muPhysical : s.grouping.muAfter;
    std::ofstream f(pathIn(c, "records.csv"));
    f << "id,n,u_mm,reduction,mu_ref,mu_model,residual,mu_corrected,residual_corrected\n";
    for (size_t i = 0; i < set.usable.size(); ++i) {
        const LoopRecord &r = set.usable[i];
        f << r.id << "," << r.n << "," << f4(r.uMm, "%.5f") << "," << f4(r.reduction, "%.4f") << "," << r.muRef << ","
          << f4(r.muModel, "%.5f") << "," << f4(set.residual[i], "%.5f") << ","
          << (corrected ? f4(muCorrected[i], "%.5f") : "") << ","
          << (corrected ? f4(muCorrected[i] - r.muRef, "%.5f") : "") << "\n";
    }
}

void plotCandidate(const std::string &path, const Candidate &c, const std::vector<double> &res,
                   const RankedCandidate &rc)
{
    Series s;
    s.y = res;
    s.colour = 0x1f77b4;
    std::vector<std::string> ticks;
    if (c.kind == "categorical") {
        std::map<std::string, int> idx;
        for (const std::string &l : c.levels) idx.emplace(l, 0);
        int k = 0;
        for (auto &[l, i] : idx) {
            i = k++;
            ticks.push_back(l.empty() ? "(none)" : l);
        }
        for (size_t i = 0; i < c.levels.size(); ++i)
            s.x.push_back(idx[c.levels[i]] + 0.25 * (double(i % 7) / 6.0 - 0.5));
    } else {
        s.x = c.x;
    }
    const std::string title = "residual vs " + c.name + "  (CV gain " + f4(rc.gain) + ", z " + f4(rc.z, "%.1f") + ")";
    scatterPlot(path, title, c.name, "mu_model - mu_ref", {s}, ticks);
}

// The residual against the three leading candidates; returns the plots' file names.
std::vector<std::string> plotLeadingCandidates(const ReportContext &c, const ResidualSet &set, const LoopSummary &s)
{
    std::vector<std::string> plots;
    for (size_t k = 0; k < s.ranking.size() && k < 3; ++k) {
        for (const Candidate &cand : set.candidates) {
            if (cand.name != s.ranking[k].name) continue;
            const std::string name = "residual_vs_" + cand.name + ".png";
            plotCandidate(pathIn(c, name), cand, set.residual, s.ranking[k]);
            plots.push_back(name);
        }
    }
    return plots;
}

// μ against μ_ref as the model reads it and after the chosen effect: its physical
// correction, its physical form (held out), or its regression (held out).
std::string plotBeforeAfter(const ReportContext &c, const ResidualSet &set, const LoopSummary &s)
{
    const std::vector<LoopRecord> &usable = set.usable;
    Series before, after;
    before.label = c.modelName + " (before), RMS " + f4(s.rmsBefore);
    before.colour = 0xb0b0b0;
    after.colour = 0xd62728;
    for (size_t i = 0; i < usable.size(); ++i) {
        before.x.push_back(usable[i].muRef);
        before.y.push_back(usable[i].muModel);
    }
    std::vector<Series> ser{before};
    if (s.physical) {
        after.label = "reduction-corrected (after), RMS " + f4(s.rmsPhysical);
        for (size_t i = 0; i < usable.size(); ++i) {
            after.x.push_back(usable[i].muRef);
            after.y.push_back(set.muPhysical[i]);
        }
        ser.push_back(after);
    } else if (!s.grouping.cvErrors.empty()) {
        after.label = "with " + s.chosen + " as " + (s.reading == "n" ? "n per material" : "a scale per group") +
                      " (after, CV), RMS " + f4(s.effects.front().cvRmsAfter);
        for (size_t i = 0; i < usable.size(); ++i) {
            after.x.push_back(usable[i].muRef);
            after.y.push_back(usable[i].muRef + s.grouping.cvErrors[i]);
        }
        ser.push_back(after);
    } else if (!s.chosen.empty()) {
        after.label = "with " + s.chosen + " (after, CV), RMS " + f4(s.effects.front().cvRmsAfter);
        for (const Candidate &cand : set.candidates)
            if (cand.name == s.chosen) {
                const std::vector<double> p = cvPredict(cand, set.residual, set.fold, set.folds,
                                                        s.ranking.front().form == "scale" ? &set.scaleSens
                                                        : s.ranking.front().form == "u"   ? &set.uSens
                                                                                          : nullptr);
                for (size_t i = 0; i < usable.size(); ++i) {
                    after.x.push_back(usable[i].muRef);
                    after.y.push_back(usable[i].muModel - p[i]);
                }
            }
        ser.push_back(after);
    }
    scatterPlot(pathIn(c, "before_after.png"), "mu: model vs reference", "mu_ref", "mu (model)", ser, {}, true);
    return "before_after.png";
}

void writeErrorTable(std::ostream &f, const LoopSummary &s)
{
    f << "\n## Error in μ (μ_model − μ_ref)\n\n| | RMS |\n|---|---|\n";
    f << "| before (model as is) | " << f4(s.rmsBefore) << " |\n";
    f << "| constant offset only (k-fold) | " << f4(s.cvRmsOffset) << " |\n";
    if (!s.ranking.empty())
        f << "| regression patch: the best linear model of the residual in " << s.ranking.front().name << " (form `"
          << s.ranking.front().patchForm << "`, k-fold) | " << f4(s.ranking.front().cvRmsPatch) << " |\n";
    if (s.physical) {
        f << "| **after: u carried to 50 % with FE du/dr, μ = model(u50, n)** (no parameter fitted here) | **"
          << f4(s.rmsPhysical) << "** |\n";
        f << "| same with the FE slope's scale fitted per fold (k-fold; scale on all records "
          << f4(s.slopeScale, "%.3f") << ") | " << f4(s.cvRmsPhysicalScaled) << " |\n";
    } else if (!s.grouping.cvErrors.empty() || s.reading == "drift") {
        f << "| **after: " << s.chosen << " in its physical form ("
          << (s.reading == "n"       ? "n per material"
              : s.reading == "drift" ? "a length factor drifting along it"
                                     : "a length factor per group")
          << ", k-fold)** | **" << f4(s.effects.front().cvRmsAfter) << "** |\n";
    } else if (!s.chosen.empty()) {
        f << "| **after (" << s.chosen << ", regression, k-fold)** | **" << f4(s.effects.front().cvRmsAfter)
          << "** |\n";
    }
    for (size_t i = 1; i < s.effects.size(); ++i)
        f << "| **then " << s.effects[i].name << " (" << s.effects[i].reading
          << "; held out, every effect so far refitted per fold)** | **" << f4(s.effects[i].cvRmsAfter) << "** |\n";
    if (s.effects.size() > 1) {
        f << "\nEffects in the order added:";
        for (size_t i = 0; i < s.effects.size(); ++i)
            f << (i ? ", " : " ") << "`" << s.effects[i].name << "` (" << s.effects[i].reading << ", "
              << f4(s.effects[i].cvRmsAfter) << ")";
        f << ".\n";
    }
}

void writeRankingTable(std::ostream &f, const std::vector<RankedCandidate> &ranking, size_t rows)
{
    f << "\n| # | candidate | kind | form | CV RMS before | CV RMS after | gain | z | r |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
    for (size_t k = 0; k < ranking.size() && k < rows; ++k) {
        const RankedCandidate &r = ranking[k];
        f << "| " << k + 1 << " | " << r.name
          << (r.significant ? " *"
              : r.carried   ? " †"
                            : "")
          << " | " << r.kind << (r.symptom ? " (symptom)" : "") << " | " << r.form << " | " << f4(r.cvRmsBefore)
          << " | " << f4(r.cvRmsAfter) << " | " << f4(r.gain, "%.5f") << " | " << f4(r.z, "%.1f") << " | "
          << f4(r.correlation, "%.2f") << " |\n";
    }
}

void writeChosenEffect(std::ostream &f, const ReportContext &c, const ResidualSet &set, const LoopSummary &s)
{
    f << "\n## Chosen effect\n\n";
    if (s.chosen.empty()) {
        f << "None: no candidate has a significant positive cross-validated gain (Bonferroni over " << s.ranking.size()
          << " candidates, α = " << c.options.alpha << ", and ≥ " << c.options.minRelativeGain * 100
          << " % of the CV RMS). The model is left as it is.\n";
    } else if (s.physical) {
        f << "`" << s.chosen << "`: the "
          << (s.chosen == "diag_reduction_est" ? "silhouette (R_max against the FE) says"
                                               : "recorded final height says")
          << " the specimens were not upset to the model's "
             "50 % height reduction. The ICA width u grows with the reduction (the contact edge keeps moving "
             "out while the folded side becomes contact), so the model, which maps u to μ at 50 %, reads a "
             "deeper upset as more friction. Correction: u50 = u − (du/dr)(r − 0.5), du/dr from the FE sweep "
             "(`"
          << joined(c.feSweeps) << "`, " << set.slopeCases
          << " cases, quadratic in n and μ), then μ = model(u50, n). "
             "Check of the FE slope: the least-squares scale of the FE du/dr on these records is "
          << f4(s.slopeScale, "%.3f")
          << (std::fabs(s.slopeScale - 1) <= 0.15
                  ? " (the FE runs carry the effect found in the data).\n"
                  : ": the data's effect differs from the FE slope by that factor. The FE du/dr is the weak "
                    "part (the contact edge's resolution, docs/fe.md): better-converged FE runs past 50 %, "
                    "not a factor fitted to these records, are the next step.\n");
    } else if (isReductionCandidate(s.chosen) && c.model->correctsReduction()) {
        f << "`" << s.chosen << "`: the model `" << c.model->name()
          << "` already carries u to 50 % with the FE "
             "du/dr (friction/reduction_table.h). A reduction effect left in its residual means the FE slope "
             "is off: the residual grows with the reduction when the FE du/dr is too small (run with "
             "`--model paper` for the least-squares scale of the FE slope). Reported here as its "
             "one-candidate k-fold model, not built into the product: better FE runs are the fix.\n";
    } else {
        writePhysicalSection(f, s.effects.front(), true, s);
    }
    writeSymptomNote(f, s);
    for (size_t i = 1; i < s.effects.size(); ++i) {
        f << "\n## Effect " << i + 1 << ", on the residual the effects above left\n\n";
        writePhysicalSection(f, s.effects[i], false, s);
        f << "\nIts round's ranking (on the residual the effects above left):\n";
        writeRankingTable(f, s.effects[i].ranking, 8);
    }
    if (!s.chosen.empty()) f << "\nThe loop stopped: " << s.stopped << ".\n";
    if (!s.lastRanking.empty()) {
        f << "\nThe ranking on the residual the effects left:\n";
        writeRankingTable(f, s.lastRanking, 8);
    }
}

// The candidates significant only through a few records, with those records: a finding
// about the images, not about the population.
void writeCarried(std::ostream &f, const RankingOptions &options, const LoopSummary &s)
{
    if (s.carried.empty()) return;
    f << "\n## Records that carry an effect\n\n"
         "Each candidate below is significant over the family with every record, and its z falls below even a "
         "single comparison's critical z without its most influential records (the record whose leaving out "
         "lowers its z the most, then the next on the records left: "
      << numberText("%g", 100 * options.influentialShare)
      << " % of the records, at least one). It is not added: what these records show is about them, not about "
         "the population. Look at these images (and their reference values).\n";
    for (const RecordFinding &c : s.carried) {
        f << "\n`" << c.candidate << "` (form `" << c.form << "`, "
          << (c.round == 1 ? std::string("on the residual as the model reads it")
                           : "on the residual the first " + std::to_string(c.round - 1) + " effect" +
                                 (c.round > 2 ? "s" : "") + " left")
          << "): z " << f4(c.z, "%.1f") << " with every record, " << f4(c.zWithout, "%.1f") << " without "
          << (c.records.size() == 1 ? "this one" : "these") << " (the family's critical z " << f4(c.zFamily, "%.1f")
          << ", a single comparison's " << f4(c.zNeeded, "%.1f") << "); k-fold gain " << f4(c.gain, "%.5f")
          << " with every record, " << f4(c.gainWithout, "%.5f") << " without.\n\n| record | residual left | "
          << c.candidate << " | far from the other records (diagnostics) | flags |\n|---|---|---|---|---|\n";
        for (const CarryingRecord &r : c.records) {
            std::string far;
            for (const auto &[name, value] : r.outlying)
                if (name != c.candidate) far += (far.empty() ? "" : ", ") + name + " " + f4(value, "%.4g");
            f << "| " << r.id << " | " << f4(r.residual, "%+.4f") << " | " << (r.value.empty() ? "—" : r.value) << " | "
              << (far.empty() ? "—" : far) << " | " << (r.flags.empty() ? "—" : r.flags) << " |\n";
        }
    }
}

void writeReportMd(const ReportContext &c, const ResidualSet &set, const LoopSummary &s,
                   const std::vector<std::string> &plots)
{
    std::ofstream f(pathIn(c, "report.md"));
    f << "# icacam loop report\n\n";
    f << c.source << ", model `" << c.modelName << "`, " << set.folds << "-fold CV, seed " << c.options.seed
      << ". Records: " << s.records << ", usable " << s.usable << ".\n\n";
    for (const std::string &k : set.skipped) f << "- skipped " << k << "\n";
    writeErrorTable(f, s);
    writeChosenEffect(f, c, set, s);
    f << "\n## Ranking (best first; full list in ranking.csv)\n";
    writeRankingTable(f, s.ranking, 15);
    f << "\n(* significant; † significant only through a few records, below; a symptom is a measured quantity, the "
         "rest are recorded conditions)\n";
    writeCarried(f, c.options, s);
    writeRateSection(f, s.rate);
    f << "\n## Plots\n\n";
    for (const std::string &p : plots) f << "![" << p << "](" << p << ")\n\n";
}

} // namespace

void writeLoopReport(const ReportContext &context, const ResidualSet &set, const LoopSummary &s)
{
    writePhysicalCsv(pathIn(context, "physical.csv"), s);
    writeRankingCsv(context, set, s);
    writeRecordsCsv(context, set, s);
    writeRateCsv(pathIn(context, "rate.csv"), s.rate);
    std::vector<std::string> plots = plotLeadingCandidates(context, set, s);
    plots.push_back(plotBeforeAfter(context, set, s));
    writeReportMd(context, set, s, plots);
}

} // namespace icacam::host::loop
