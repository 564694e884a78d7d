// `icacam loop`: close the loop on measured records (PRODUCT.md §5, docs/loop.md).
#include "host_tools/loop/loop_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include "friction/friction_models.h"
#include "host_tools/cli_options.h"
#include "host_tools/fe/fe_table_sources.h"
#include "host_tools/fe/reduction_slope.h"
#include "host_tools/image_file.h"
#include "host_tools/loop/journal_records.h"
#include "host_tools/loop/loop_physics_report.h"
#include "host_tools/loop/loop_records.h"
#include "host_tools/loop/loop_report.h"
#include "host_tools/manifest.h"
#include "host_tools/number_text.h"
#include "host_tools/record_measurer.h"
#include "vision/end_face_analyzer.h"

#include "friction/reduction_table.h"

#ifndef ICACAM_LOOP_SOURCE_DIR
#define ICACAM_LOOP_SOURCE_DIR "."
#endif

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::friction;
using namespace icacam::reading;
using namespace icacam::vision;

namespace {

std::string usage()
{
    const loop::RankingOptions d;
    return std::string("usage: icacam loop --manifest FILE --report DIR [--model NAME] [--folds N] [--seed S]\n"
                       "                   [--fe-sweep CSV]... [--alpha A]\n"
                       "       icacam loop --journal DIR --reference CSV --report DIR [options as above]\n"
                       "  --model NAME   the friction model (default ") +
           friction::kDefaultModel + "; known: " + cli::modelNames() +
           ")\n"
           "  --folds N      k of the k-fold cross-validation (default " +
           std::to_string(d.folds) +
           ")\n"
           "  --seed S       the folds' random seed (default " +
           std::to_string(d.seed) +
           ")\n"
           "  --alpha A      family-wise significance of a chosen effect (default " +
           numberText("%g", d.alpha) +
           ")\n"
           "  --fe-sweep CSV the FE runs of the physical reduction correction (default the base the\n"
           "                 models' tables came from: " +
           friction::reduction_table::kFeSources +
           ")\n"
           "Measures every record (image + mm_per_px, or r_inner_mm + r_outer_mm; with --journal an\n"
           "icacam-fw journal folder's saved frames, joined by record id with the CSV's mu_ref and\n"
           "recorded columns, re-measured with the current pipeline), takes the residual\n"
           "μ_model − mu_ref, ranks every recorded column and every pipeline diagnostic by the k-fold\n"
           "cross-validated gain of a one-candidate model of the residual, and corrects the leading\n"
           "effect. With a model that does not carry the reduction itself (paper, fe), a height\n"
           "reduction other than 50 % is corrected physically: u is carried to 50 % with du/dr from\n"
           "the FE sweep before μ = model(u, n). Writes ranking.csv, report.md, records.csv and PNG\n"
           "plots to DIR (docs/loop.md). The generated tables the models read are made by\n"
           "`icacam fe tables`.\n";
}

// A repository file: under the source tree this tool was built from, else relative to here.
std::string repoFile(const std::string &name)
{
    const fs::path p = fs::path(ICACAM_LOOP_SOURCE_DIR) / name;
    return fs::exists(p) ? p.string() : name;
}

std::string f4(double v, const char *fmt = "%.4f")
{
    char b[48];
    std::snprintf(b, sizeof b, fmt, v);
    return b;
}

} // namespace

namespace loop {

namespace {

// Every row read (readLoopRecord); the usable ones with their residual and μ's
// sensitivities, the others listed with why.
ResidualSet measureRecords(const Manifest &manifest, const FrictionModel &model,
                           const std::vector<std::string> &skippedBefore)
{
    ResidualSet set;
    set.skipped = skippedBefore;
    host::RecordMeasurer measurer(model, SpecimenSpec{});
    for (const ManifestRow &row : manifest.rows) {
        LoopRecord r;
        r.id = row.get("id", "line" + std::to_string(row.line));
        std::string why;
        if (readLoopRecord(row, manifest, measurer, &r, &why))
            set.usable.push_back(std::move(r));
        else
            set.skipped.push_back(r.id + ": " + why);
    }
    for (const LoopRecord &r : set.usable) {
        set.residual.push_back(r.muModel - r.muRef);
        set.scaleSens.push_back(r.scaleSens);
        set.uSens.push_back(r.uSens);
    }
    return set;
}

// The recorded reduction is also ranked by its physics: the change in μ when u is carried
// to 50 % with the FE du/dr (form "fe"), not only by a linear patch. Loads *slope when a
// reduction is recorded and the model does not carry it itself.
std::map<std::string, std::vector<double>> reductionForms(const FrictionModel &model, const ResidualSet &set,
                                                          const std::vector<std::string> &feSweeps,
                                                          fe::ReductionSlope *slope, bool *slopeLoaded)
{
    std::map<std::string, std::vector<double>> physicalForms;
    bool anyRecorded = false;
    for (const LoopRecord &r : set.usable) anyRecorded = anyRecorded || r.reduction >= 0;
    if (!anyRecorded || model.correctsReduction()) return physicalForms;
    std::string e;
    *slopeLoaded = slope->load(feSweeps, &e);
    if (!*slopeLoaded) {
        std::cerr << "icacam loop: no physical correction: " << e << "\n";
        return physicalForms;
    }
    std::vector<double> change(set.usable.size(), 0);
    for (size_t i = 0; i < set.usable.size(); ++i) {
        const LoopRecord &r = set.usable[i];
        if (r.reduction < 0) continue;
        ModelInputs in;
        in.uMm = r.uMm, in.n = r.n, in.kMpa = r.kMpa, in.d0Mm = r.d0Mm, in.h0Mm = r.h0Mm;
        in.uMm = fe::uAtModelReduction(model, *slope, in, r.reduction);
        change[i] = r.muModel - model.estimate(in).mu;
    }
    physicalForms["reduction"] = std::move(change);
    return physicalForms;
}

// A grouping (a camera, a lens, a material) is also ranked in its physical form: a length
// factor per group, or an n per material (loop_physics.h).
std::map<std::string, FittedForm> groupingForms(const FrictionModel &model, const ResidualSet &set)
{
    std::map<std::string, FittedForm> fittedForms;
    for (const Candidate &c : set.candidates)
        if (c.kind == "categorical" && !c.symptom)
            fittedForms[c.name] = groupingForm(model, set.usable, c, set.fold, set.folds);
    return fittedForms;
}

// k-fold RMS of the residual after a constant offset fitted on the other folds.
double offsetCvRms(const std::vector<double> &res, const std::vector<int> &fold, int folds)
{
    std::vector<double> e(res.size());
    for (int k = 0; k < folds; ++k) {
        double sum = 0;
        int cnt = 0;
        for (size_t i = 0; i < res.size(); ++i)
            if (fold[i] != k) {
                sum += res[i];
                ++cnt;
            }
        for (size_t i = 0; i < res.size(); ++i)
            if (fold[i] == k) e[i] = res[i] - (cnt ? sum / cnt : 0);
    }
    return rms(e);
}

// The physical correction of the reduction: u carried to 50 % with the FE du/dr from the
// recorded reduction, or from the silhouette's estimate where none was recorded.
void correctReduction(const FrictionModel &model, const fe::ReductionSlope &slope, ResidualSet *set, LoopSummary *s)
{
    const std::vector<LoopRecord> &usable = set->usable;
    const std::vector<double> &res = set->residual;
    std::vector<double> after(usable.size()), delta(usable.size());
    for (size_t i = 0; i < usable.size(); ++i) {
        const LoopRecord &r = usable[i];
        ModelInputs in;
        in.uMm = r.uMm;
        in.n = r.n;
        in.kMpa = r.kMpa;
        in.d0Mm = r.d0Mm;
        in.h0Mm = r.h0Mm;
        double red = r.reduction;
        if (red < 0) {
            auto est = r.diagnostics.find("diag_reduction_est");
            if (est != r.diagnostics.end()) red = est->second;
        }
        in.uMm = fe::uAtModelReduction(model, slope, in, red); // red < 0: left as measured
        set->muPhysical[i] = model.estimate(in).mu;
        after[i] = set->muPhysical[i] - r.muRef;
        delta[i] = r.muModel - set->muPhysical[i]; // what the correction removed
    }
    s->rmsPhysical = rms(after);
    // The FE slope's scale, fitted by least squares (all records and per fold): a check that
    // the FE du/dr carries the data's effect, not a parameter of the correction.
    auto fitScale = [&](int k) {
        double sdd = 0, sdr = 0;
        for (size_t i = 0; i < res.size(); ++i)
            if (k < 0 || set->fold[i] != k) {
                sdd += delta[i] * delta[i];
                sdr += delta[i] * res[i];
            }
        return sdd > 0 ? sdr / sdd : 0.0;
    };
    s->slopeScale = fitScale(-1);
    std::vector<double> cvErr(res.size());
    for (int k = 0; k < set->folds; ++k) {
        const double a = fitScale(k);
        for (size_t i = 0; i < res.size(); ++i)
            if (set->fold[i] == k) cvErr[i] = res[i] - a * delta[i];
    }
    s->cvRmsPhysicalScaled = rms(cvErr);
    s->cvRmsAfter = s->rmsPhysical; // no parameter is fitted to these records: held out as is
}

// Any other chosen effect in its physical form, with the regression patch beside it.
void readChosenEffect(const FrictionModel &model, const ResidualSet &set, LoopSummary *s)
{
    const Candidate *lead = nullptr;
    for (const Candidate &c : set.candidates)
        if (c.name == s->chosen) lead = &c;
    if (lead) s->cvRmsPatch = s->ranking.front().cvRmsPatch;
    if (s->physical)
        s->reading = "fe_slope";
    else if (lead && (isReductionCandidate(s->chosen) || lead->symptom))
        s->reading = "patch";
    else if (lead && lead->kind == "categorical") {
        const GroupReading reading = readingOf(set.usable, *lead);
        s->grouping = fitGrouping(model, set.usable, *lead, reading, set.fold, set.folds);
        s->reading = reading == GroupReading::Scale ? "scale" : "n";
        s->cvRmsAfter = rms(s->grouping.cvErrors);
    } else if (lead) {
        s->reading = "process";
        s->linear = fitLinearEffect(*lead, set.residual, s->ranking.front().form, set.scaleSens, set.uSens);
    }
}

} // namespace

LoopSummary runLoop(const std::string &manifestPath, const std::string &reportDir, const std::string &modelName,
                    const RankingOptions &opt, const std::vector<std::string> &feSweeps)
{
    Manifest manifest;
    std::string err;
    if (!readManifest(manifestPath, &manifest, &err)) throw std::runtime_error(err);
    return runLoopOn(manifest, "Manifest: `" + manifestPath + "`", {}, reportDir, modelName, opt, feSweeps);
}

LoopSummary runJournalLoop(const std::string &journalDir, const std::string &referenceCsv, const std::string &reportDir,
                           const std::string &modelName, const RankingOptions &opt,
                           const std::vector<std::string> &feSweeps)
{
    Manifest manifest;
    JournalJoin join;
    std::string err;
    if (!readJournalManifest(journalDir, referenceCsv, &manifest, &join, &err)) throw std::runtime_error(err);
    const std::string source = "Journal: `" + journalDir + "` (" + std::to_string(join.lines) + " lines, " +
                               std::to_string(join.results) + " results, " + std::to_string(join.scaleChecks) +
                               " scale checks), joined by record id with `" + referenceCsv +
                               "`: " + std::to_string(join.joined) +
                               " records with a reference value and a saved frame, "
                               "re-measured with the current pipeline (the device's own results are the device_* "
                               "columns); " +
                               join.geometry;
    LoopSummary s = runLoopOn(manifest, source, join.skipped, reportDir, modelName, opt, feSweeps);
    s.journal = join;
    return s;
}

LoopSummary runLoopOn(const Manifest &manifest, const std::string &source,
                      const std::vector<std::string> &skippedBefore, const std::string &reportDir,
                      const std::string &modelName, const RankingOptions &opt, const std::vector<std::string> &feSweeps)
{
    const FrictionModel *model = frictionModel(modelName);
    if (!model) throw std::runtime_error("unknown model '" + modelName + "' (known: " + cli::modelNames() + ")");
    fs::create_directories(reportDir);

    ResidualSet set = measureRecords(manifest, *model, skippedBefore);
    LoopSummary s;
    s.records = int(manifest.rows.size());
    s.usable = int(set.usable.size());
    if (set.usable.size() < 6) throw std::runtime_error("fewer than 6 usable records (measured, with mu_ref)");
    s.rmsBefore = rms(set.residual);
    set.folds = std::clamp(opt.folds, 2, int(set.usable.size()));
    set.fold = foldAssignment(set.usable.size(), set.folds, opt.seed);
    set.candidates = buildCandidates(set.usable);

    fe::ReductionSlope slope;
    bool slopeLoaded = false;
    const std::map<std::string, std::vector<double>> physicalForms =
        reductionForms(*model, set, feSweeps, &slope, &slopeLoaded);
    const std::map<std::string, FittedForm> fittedForms = groupingForms(*model, set);
    s.ranking =
        rankCandidates(set.candidates, set.residual, opt, &set.scaleSens, &set.uSens, &physicalForms, &fittedForms);
    s.cvRmsOffset = offsetCvRms(set.residual, set.fold, set.folds);
    s.cvRmsAfter = s.rmsBefore;
    if (!s.ranking.empty() && s.ranking.front().significant) {
        s.chosen = s.ranking.front().name;
        s.cvRmsAfter = s.ranking.front().cvRmsAfter;
    }

    // A model that carries u to 50 % itself (paper_reduction) must not be corrected twice: a
    // reduction effect left in its residual is the FE slope's own error (reported as such).
    // The reduction leads when it is chosen as recorded or as the image measures it
    // (diag_reduction_est, from the silhouette): the recorded value is used when there is
    // one, the image's estimate otherwise.
    set.muPhysical.assign(set.usable.size(), NAN);
    if (isReductionCandidate(s.chosen) && !model->correctsReduction()) {
        std::string e;
        if (!slopeLoaded && !slope.load(feSweeps, &e))
            std::cerr << "icacam loop: no physical correction: " << e << "\n";
        else
            s.physical = true;
    }
    if (s.physical) {
        set.slopeCases = slope.cases();
        correctReduction(*model, slope, &set, &s);
    }
    readChosenEffect(*model, set, &s);
    writeLoopReport({reportDir, source, modelName, model, opt, feSweeps}, set, s);
    return s;
}

} // namespace loop

int loopCommand(const std::vector<std::string> &args)
{
    if (!args.empty() && args[0] == "table")
        throw cli::UsageError(std::string("the generated tables (the reduction carry's du/dr among them) are made "
                                          "by `icacam fe tables`, as: ") +
                                  friction::reduction_table::kProvenance,
                              usage());
    std::string manifestPath, journalDir, referenceCsv, reportDir, modelName = friction::kDefaultModel;
    std::vector<std::string> feSweeps;
    loop::RankingOptions opt;
    cli::OptionReader opts(args, usage());
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << usage();
            return 0;
        } else if (opts.is("--manifest"))
            manifestPath = opts.value();
        else if (opts.is("--journal"))
            journalDir = opts.value();
        else if (opts.is("--reference"))
            referenceCsv = opts.value();
        else if (opts.is("--report"))
            reportDir = opts.value();
        else if (opts.is("--model")) {
            modelName = opts.value();
            if (!frictionModel(modelName))
                opts.fail("unknown model '" + modelName + "' (known: " + cli::modelNames() + ")");
        } else if (opts.is("--fe-sweep"))
            feSweeps.push_back(opts.value());
        else if (opts.is("--folds"))
            opt.folds = int(opts.wholeNumber(2, 1000));
        else if (opts.is("--seed"))
            opt.seed = uint32_t(opts.wholeNumber(0, 4294967295L));
        else if (opts.is("--alpha")) {
            opt.alpha = opts.number();
            if (!(opt.alpha > 0 && opt.alpha < 1)) opts.fail("a probability between 0 and 1 (exclusive)");
        } else
            opts.unknown();
    }
    if (manifestPath.empty() == journalDir.empty() || reportDir.empty())
        opts.missing("--report and one of --manifest or --journal");
    if (journalDir.empty() != referenceCsv.empty())
        throw cli::UsageError("--journal and --reference go together", usage());
    // By default the FE data the product's table was generated from (its kFeSources).
    if (feSweeps.empty())
        for (const std::string &name : fe::splitSources(friction::reduction_table::kFeSources))
            feSweeps.push_back(repoFile(name));
    const loop::LoopSummary s =
        journalDir.empty() ? loop::runLoop(manifestPath, reportDir, modelName, opt, feSweeps)
                           : loop::runJournalLoop(journalDir, referenceCsv, reportDir, modelName, opt, feSweeps);
    std::cout << "records " << s.records << " usable " << s.usable << "\n"
              << "rms_before " << f4(s.rmsBefore) << "\ncv_rms_offset " << f4(s.cvRmsOffset) << "\n"
              << "top " << (s.ranking.empty() ? "-" : s.ranking.front().name) << "\n"
              << "chosen " << (s.chosen.empty() ? "(none)" : s.chosen) << "\n"
              << "rms_after " << f4(s.cvRmsAfter) << (s.physical ? " (physical FE du/dr correction)" : "") << "\n";
    loop::printPhysical(std::cout, s);
    if (s.physical)
        std::cout << "fe_slope_scale " << f4(s.slopeScale, "%.3f") << " cv_rms_scaled " << f4(s.cvRmsPhysicalScaled)
                  << "\n";
    std::cout << "report " << reportDir << "/report.md\n";
    return 0;
}

} // namespace icacam::host
