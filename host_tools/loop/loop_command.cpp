// `icacam loop`: close the loop on measured records (PRODUCT.md §5, docs/loop.md).
#include "host_tools/loop/loop_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>

#include "friction/friction_models.h"
#include "host_tools/cli_options.h"
#include "host_tools/fe/fe_table_sources.h"
#include "host_tools/fe/reduction_slope.h"
#include "host_tools/image_file.h"
#include "host_tools/loop/journal_records.h"
#include "host_tools/loop/loop_fit.h"
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
                       "       icacam loop --journal DIR --reference CSV --report DIR [--calibrations DIR]\n"
                       "                   [options as above]\n"
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
           "  --calibrations DIR  where the calibration files the journal names are (default the\n"
           "                 journal folder): frames the device measured through one are re-measured\n"
           "                 through it\n"
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

std::map<std::string, std::vector<double>> reductionChange(const FrictionModel &model, const ResidualSet &set,
                                                           const fe::ReductionSlope &slope);

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
    return reductionChange(model, set, *slope);
}

// The change in μ when each record's u is carried to 50 % with the FE du/dr, as the form "fe"
// of the recorded reduction.
std::map<std::string, std::vector<double>> reductionChange(const FrictionModel &model, const ResidualSet &set,
                                                           const fe::ReductionSlope &slope)
{
    std::map<std::string, std::vector<double>> physicalForms;
    std::vector<double> change(set.usable.size(), 0);
    for (size_t i = 0; i < set.usable.size(); ++i) {
        const LoopRecord &r = set.usable[i];
        if (r.reduction < 0) continue;
        ModelInputs in;
        in.uMm = r.uMm, in.n = r.n, in.kMpa = r.kMpa, in.d0Mm = r.d0Mm, in.h0Mm = r.h0Mm;
        in.uMm = fe::uAtModelReduction(model, slope, in, r.reduction);
        change[i] = r.muModel - (model.estimate(in).mu + r.muOffset);
    }
    physicalForms["reduction"] = std::move(change);
    return physicalForms;
}

// A grouping (a camera, a lens, a material) is also ranked in its physical form: a length
// factor per group, or an n per material (loop_physics.h); a condition that orders the
// records in time as a drift of the scale along it (loop_drift.h).
std::map<std::string, FittedForm> groupingForms(const FrictionModel &model, const ResidualSet &set)
{
    std::map<std::string, FittedForm> fittedForms;
    for (const Candidate &c : set.candidates) {
        if (c.symptom) continue;
        if (c.kind == "categorical")
            fittedForms[c.name] = groupingForm(model, set.usable, c, set.fold, set.folds);
        else if (c.kind == "numeric" && ordersInTime(c.name))
            fittedForms[c.name] = driftForm(model, set.usable, c, set.fold, set.folds);
    }
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
        in.uMm = fe::uAtModelReduction(model, slope, in, carriedReduction(r)); // < 0: left as measured
        set->muPhysical[i] = model.estimate(in).mu + r.muOffset;
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

// A slope per level of the grouping: each level's own line in the condition.
void readLevelSlopes(const Candidate &c, const ResidualSet &set, const std::string &form, LoopEffectStep *step)
{
    std::map<std::string, std::vector<size_t>> members;
    for (size_t i = 0; i < c.levels.size(); ++i) members[c.levels[i]].push_back(i);
    for (const auto &[level, idx] : members) {
        Candidate part{c.name, "numeric", {}, {}, false};
        std::vector<double> y, scale, u;
        for (size_t i : idx) {
            part.x.push_back(c.x[i]);
            y.push_back(set.residual[i]);
            scale.push_back(set.scaleSens[i]);
            u.push_back(set.uSens[i]);
        }
        step->slopeLevels.push_back(level);
        step->levelSlopes.push_back(fitLinearEffect(part, y, form, scale, u));
    }
}

// The material grouping a numeric recorded condition is a declared property of (constant
// within each material: its n, its K), if any.
const Candidate *materialDeclaring(const ResidualSet &set, const Candidate &c)
{
    if (c.kind != "numeric" || c.symptom) return nullptr;
    for (const Candidate &g : set.candidates)
        if (isMaterialGrouping(set.usable, g) && !g.symptom && sameRecords(c, g)) return &g;
    return nullptr;
}

// A condition that orders the records in time, ranked in the form `mu` (its gain over a
// constant offset larger than the drift's over one factor for every record), is still read
// as a drift of the scale where the drift fits the held-out records better than that offset
// in μ: a scale drifting beside another scale error (a camera) leaves most of both to the one
// factor the drift is ranked against.
bool drifts(const FrictionModel &model, const ResidualSet &set, const Candidate &c, double cvRmsMu, DriftFit *out)
{
    *out = fitDrift(model, set.usable, c, set.fold, set.folds);
    return rms(out->cvErrors) < cvRmsMu;
}

// The leading candidate of a round as an effect in its physical form (fitted on every record),
// with the regression patch beside it. held: the held-out errors of its physical form where
// the ranking computed them for this round alone.
LoopEffectStep readEffect(const FrictionModel &model, const ResidualSet &set, const RankedCandidate &lead,
                          bool physicalReduction)
{
    LoopEffectStep step;
    step.name = lead.name, step.kind = lead.kind, step.form = lead.form, step.patchForm = lead.patchForm;
    step.z = lead.z, step.cvRmsPatch = lead.cvRmsPatch, step.cvRmsAfter = lead.cvRmsAfter;
    step.symptom = lead.symptom, step.viaSymptom = lead.viaSymptom;
    step.preferredOver = lead.preferredOver, step.pointedBy = lead.pointedBy;
    step.given = lead.given, step.givenZ = lead.givenZ;
    step.subsumes = lead.subsumes, step.subsumesZ = lead.subsumesZ, step.subsumedZ = lead.subsumedZ;
    step.sameResidual = lead.sameResidual;
    step.witnessZ = std::isfinite(lead.witnessZ) ? lead.witnessZ : 0;
    // The reduction's names (h_final_mm, reduction) are one cause, not two that cannot be told apart.
    for (const std::string &other : lead.inseparable)
        if (!(isReductionCandidate(lead.name) && isReductionCandidate(other))) step.inseparable.push_back(other);
    const Candidate *c = nullptr;
    for (const Candidate &cand : set.candidates)
        if (cand.name == lead.name) c = &cand;
    // A declared property of each material (its n, its K) is the material's: read as an n
    // per material.
    if (const Candidate *g = c ? materialDeclaring(set, *c) : nullptr) {
        step.via = c->name;
        step.name = g->name, step.kind = g->kind;
        // The grouping it is read as is not a condition it cannot be told from.
        step.inseparable.erase(std::remove(step.inseparable.begin(), step.inseparable.end(), g->name),
                               step.inseparable.end());
        c = g;
    }
    if (physicalReduction)
        step.reading = "fe_slope";
    else if (!c || isReductionCandidate(lead.name) || lead.symptom)
        step.reading = "patch";
    else if (c->kind == "categorical") {
        const GroupReading reading = readingOf(set.usable, *c);
        step.grouping = fitGrouping(model, set.usable, *c, reading, set.fold, set.folds);
        step.reading = reading == GroupReading::Scale ? "scale" : "n";
        step.cvRmsAfter = rms(step.grouping.cvErrors);
    } else if (ordersInTime(c->name) && c->kind == "numeric" &&
               (lead.form != "mu" || drifts(model, set, *c, lead.cvRmsAfter, &step.drift))) {
        if (lead.form != "mu") step.drift = fitDrift(model, set.usable, *c, set.fold, set.folds);
        step.reading = "drift";
        step.cvRmsAfter = rms(step.drift.cvErrors);
    } else {
        step.reading = "process";
        if (c->kind == "interaction")
            readLevelSlopes(*c, set, lead.form, &step);
        else
            step.linear = fitLinearEffect(*c, set.residual, lead.form, set.scaleSens, set.uSens);
    }
    return step;
}

// The records of one round: residual, sensitivities and the candidates left.
void setRound(ResidualSet *set, const std::vector<LoopRecord> &records, const std::set<std::string> &taken)
{
    set->usable = records;
    set->residual.clear(), set->scaleSens.clear(), set->uSens.clear();
    for (const LoopRecord &r : records) {
        set->residual.push_back(r.muModel - r.muRef);
        set->scaleSens.push_back(r.scaleSens);
        set->uSens.push_back(r.uSens);
    }
    set->candidates.clear();
    for (Candidate &c : buildCandidates(records))
        if (!taken.count(c.name)) set->candidates.push_back(std::move(c));
}

const Candidate *candidateNamed(const ResidualSet &set, const std::string &name)
{
    for (const Candidate &c : set.candidates)
        if (c.name == name) return &c;
    return nullptr;
}

// The candidates a round turned down as carried by a few records, with those records (a
// candidate turned down in several rounds is named as the last of them saw it).
void noteCarried(const ResidualSet &round, const std::vector<RankedCandidate> &ranking, int roundNo,
                 const RankingOptions &opt, LoopSummary *s)
{
    for (const RankedCandidate &r : ranking) {
        if (!r.carried) continue;
        RecordFinding f = recordFinding(r, candidateNamed(round, r.name), round.usable, round.residual, roundNo,
                                        fit::normalUpperQuantile(opt.alpha));
        const auto it = std::find_if(s->carried.begin(), s->carried.end(),
                                     [&](const RecordFinding &o) { return o.candidate == r.name; });
        if (it == s->carried.end())
            s->carried.push_back(std::move(f));
        else
            *it = std::move(f);
    }
}

// The best candidate a round left, for why the loop stopped: its z against the family's, and
// where it is carried by a few records, its z without them.
std::string bestLeft(const ResidualSet &round, const std::vector<RankedCandidate> &ranking)
{
    if (ranking.empty()) return "";
    const RankedCandidate &b = ranking.front();
    std::string s =
        " (best left: " + b.name + ", z " + f4(b.z, "%.1f") + " against the family's " + f4(b.zFamily, "%.1f");
    if (b.carried) {
        std::string ids;
        for (size_t i : b.influential)
            if (i < round.usable.size()) ids += (ids.empty() ? "" : ", ") + round.usable[i].id;
        s += ", " + f4(b.zWithout, "%.1f") + " without " + ids + ": carried by " +
             (b.influential.size() == 1 ? "that record" : "those records");
    }
    return s + ")";
}

// What an added effect takes out of later rounds: itself, every name of the reduction when
// it is the reduction (one cause), and the conditions it cannot be told from; the
// reduction carried physically stays (below).
void markTaken(const LoopEffectStep &step, std::set<std::string> *taken)
{
    // Carried with the FE du/dr, the reduction stays a candidate: what it explains after the
    // carry is the FE slope's own error.
    if (step.reading == "fe_slope") return;
    taken->insert(step.name);
    if (!step.via.empty()) taken->insert(step.via);
    if (isReductionCandidate(step.name))
        for (const char *name : {"reduction", "h_final_mm", "diag_reduction_est"}) taken->insert(name);
    taken->insert(step.inseparable.begin(), step.inseparable.end());
    taken->insert(step.sameResidual.begin(), step.sameResidual.end());
}

// One round: the candidates left (not taken) ranked on what the records' residual now is,
// the reduction in its FE form while it has not been carried. Fills *round.
std::vector<RankedCandidate> rankRound(const FrictionModel &model, const fe::ReductionSlope *slope,
                                       const std::vector<LoopRecord> &records, const std::set<std::string> &taken,
                                       bool carried, const std::vector<int> &fold, int folds, const RankingOptions &opt,
                                       ResidualSet *round)
{
    round->folds = folds, round->fold = fold;
    setRound(round, records, taken);
    std::map<std::string, std::vector<double>> physicalForms;
    if (slope && !carried && !model.correctsReduction()) physicalForms = reductionChange(model, *round, *slope);
    const std::map<std::string, FittedForm> fittedForms = groupingForms(model, *round);
    return rankCandidates(round->candidates, round->residual, opt, &round->scaleSens, &round->uSens, &physicalForms,
                          &fittedForms);
}

// The round's records with a candidate ranked on `rankedOn` taken out in its physical form
// (fitted on every record), and the names it takes out of later rounds.
std::vector<LoopRecord> withCandidateOut(const FrictionModel &model, const fe::ReductionSlope *slope,
                                         const ResidualSet &round, const ResidualSet &rankedOn,
                                         const RankedCandidate &lead, bool carried, std::set<std::string> *taken)
{
    const bool physicalReduction = isReductionCandidate(lead.name) && !model.correctsReduction() && slope && !carried;
    const LoopEffectStep step = readEffect(model, rankedOn, lead, physicalReduction);
    std::vector<LoopRecord> records = round.usable;
    if (const Candidate *c = candidateNamed(round, step.name))
        applyEffect(model, slope, step, *c, &records, round.fold, -1);
    markTaken(step, taken);
    return records;
}

// Two effects can hide each other: each one's records carry the other's scatter, and neither
// is significant over the family on its own. When no recorded condition is, the leading one
// that passes the test of a single comparison is taken out: where a recorded condition is
// then significant over the family (not through a symptom), and the leader is significant
// over the family with that one taken out instead, the leader counts (`given`) and is put
// first; the other leads the next round, on the records the leader leaves.
void lookPastAMaskingEffect(const FrictionModel &model, const fe::ReductionSlope *slope, const ResidualSet &round,
                            const std::set<std::string> &taken, bool carried, const RankingOptions &opt,
                            std::vector<RankedCandidate> *ranking)
{
    std::vector<RankedCandidate> &r = *ranking;
    if (r.empty() || (r.front().significant && !r.front().symptom)) return;
    size_t lead = 0;
    while (lead < r.size() && (r[lead].symptom || !passesSingleComparison(r[lead], opt))) ++lead;
    if (lead == r.size()) return;
    std::set<std::string> takenLead = taken;
    const std::vector<LoopRecord> leadOut = withCandidateOut(model, slope, round, round, r[lead], carried, &takenLead);
    ResidualSet next;
    const std::vector<RankedCandidate> after =
        rankRound(model, slope, leadOut, takenLead, carried, round.fold, round.folds, opt, &next);
    // The other must be another cause: the reduction carried with the FE stays a candidate for
    // the FE slope's own error, which is the same cause.
    if (after.empty() || !after.front().significant || after.front().symptom || after.front().viaSymptom ||
        after.front().name == r[lead].name ||
        (isReductionCandidate(after.front().name) && isReductionCandidate(r[lead].name)))
        return;
    std::set<std::string> takenOther = taken;
    const std::vector<LoopRecord> otherOut =
        withCandidateOut(model, slope, round, next, after.front(), carried, &takenOther);
    ResidualSet again;
    const std::vector<RankedCandidate> given =
        rankRound(model, slope, otherOut, takenOther, carried, round.fold, round.folds, opt, &again);
    const auto it =
        std::find_if(given.begin(), given.end(), [&](const RankedCandidate &g) { return g.name == r[lead].name; });
    if (it == given.end() || !it->significant || it->viaSymptom) return;
    RankedCandidate moved = r[lead];
    moved.significant = true;
    moved.given = after.front().name;
    moved.givenZ = it->z;
    for (size_t j = 0; j < lead; ++j)
        if (r[j].symptom && r[j].significant) moved.aheadOfBetter.push_back(r[j].name);
    r.erase(r.begin() + long(lead));
    r.insert(r.begin(), std::move(moved));
}

// The z of `name` in a ranking and whether it is significant there (not through a symptom).
bool significantIn(const std::vector<RankedCandidate> &ranking, const std::string &name, double *z)
{
    *z = 0;
    for (const RankedCandidate &c : ranking)
        if (c.name == name) {
            *z = c.z;
            return c.significant && !c.viaSymptom;
        }
    return false;
}

// The share two corrections have in common: R² between what each took out of the residual.
double sharedShare(const std::vector<LoopRecord> &before, const std::vector<LoopRecord> &a,
                   const std::vector<LoopRecord> &b)
{
    const size_t n = before.size();
    std::vector<double> da(n), db(n);
    double ma = 0, mb = 0;
    for (size_t i = 0; i < n; ++i) {
        da[i] = before[i].muModel - a[i].muModel, db[i] = before[i].muModel - b[i].muModel;
        ma += da[i] / double(n), mb += db[i] / double(n);
    }
    double saa = 0, sbb = 0, sab = 0;
    for (size_t i = 0; i < n; ++i) {
        saa += (da[i] - ma) * (da[i] - ma), sbb += (db[i] - mb) * (db[i] - mb), sab += (da[i] - ma) * (db[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab * sab / (saa * sbb) : 0;
}

// Two recorded conditions can explain the same part of the residual (a press speed and an
// ambient temperature that happen to rise together within one material). The leader is
// weighed against each significant recorded condition below it (the first three): each is
// taken out in its physical form and the other ranked on what it leaves. Where the leader is
// still significant, it adds to the other and leads. Where it is not and the other is with
// the leader taken out, the other explains what the leader did and more: it leads
// (`subsumes`). Where neither is and the two take out mostly the same (R² of their
// corrections above one half), the records cannot say which it is: the leader is read, and
// the other is named beside it (`sameResidual`) and not added after it.
void weighRivals(const FrictionModel &model, const fe::ReductionSlope *slope, const ResidualSet &round,
                 const std::set<std::string> &taken, bool carried, const RankingOptions &opt,
                 std::vector<RankedCandidate> *ranking)
{
    constexpr int kRivals = 3;
    std::vector<RankedCandidate> &r = *ranking;
    // A length factor the outline witnesses is read from the geometry: a cause acting on μ
    // does not explain it away, though it may take up its part of μ's residual.
    if (r.empty() || !r.front().significant || r.front().symptom || r.front().witnessed) return;
    int tried = 0;
    for (size_t k = 1; k < r.size() && tried < kRivals; ++k) {
        const RankedCandidate &lead = r.front(), &rival = r[k];
        if (rival.symptom || !rival.significant || rival.viaSymptom) continue;
        if (std::find(lead.inseparable.begin(), lead.inseparable.end(), rival.name) != lead.inseparable.end()) continue;
        if (isReductionCandidate(lead.name) && isReductionCandidate(rival.name)) continue;
        ++tried;
        std::set<std::string> takenRival = taken, takenLead = taken;
        ResidualSet next;
        const std::vector<LoopRecord> rivalOut =
            withCandidateOut(model, slope, round, round, rival, carried, &takenRival);
        if (takenRival.count(lead.name)) continue;
        double leadZ = 0, rivalZ = 0;
        if (significantIn(rankRound(model, slope, rivalOut, takenRival, carried, round.fold, round.folds, opt, &next),
                          lead.name, &leadZ))
            continue;
        const std::vector<LoopRecord> leadOut = withCandidateOut(model, slope, round, round, lead, carried, &takenLead);
        const bool rivalStands =
            !takenLead.count(rival.name) &&
            significantIn(rankRound(model, slope, leadOut, takenLead, carried, round.fold, round.folds, opt, &next),
                          rival.name, &rivalZ);
        if (!rivalStands) {
            // The same part of the residual: most of what one takes out the other does too.
            if (sharedShare(round.usable, leadOut, rivalOut) > 0.5) r.front().sameResidual.push_back(rival.name);
            continue;
        }
        RankedCandidate moved = rival;
        moved.subsumes = lead.name, moved.subsumesZ = rivalZ, moved.subsumedZ = leadZ;
        r.erase(r.begin() + long(k));
        r.insert(r.begin(), std::move(moved));
        return;
    }
}

// Held-out errors with every effect fitted on each fold's training records: record i as the
// records of its fold's state give it.
std::vector<double> heldOut(const std::vector<std::vector<LoopRecord>> &perFold, const std::vector<int> &fold)
{
    std::vector<double> e(fold.size());
    for (size_t i = 0; i < fold.size(); ++i)
        e[i] = perFold[size_t(fold[i])][i].muModel - perFold[size_t(fold[i])][i].muRef;
    return e;
}

// Backfitting: a few rounds of refitting each effect on the records every other one leaves,
// each grouping's levels relative to its typical level (applyEffect's onlyDiffering).
constexpr int kBackfitRounds = 4;
void backfit(const FrictionModel &model, const fe::ReductionSlope *slope, const ResidualSet &first,
             const std::vector<LoopEffectStep> &effects, std::vector<EffectShare> *shares)
{
    if (effects.size() < 2) return;
    for (int round = 0; round < kBackfitRounds; ++round)
        for (size_t j = 0; j < effects.size(); ++j) {
            const LoopEffectStep &e = effects[j];
            const Candidate *c = candidateNamed(first, e.name);
            if (!c || e.reading == "fe_slope") continue;
            std::vector<LoopRecord> others = withShares(model, slope, first.usable, *shares, j, false);
            const std::vector<LoopRecord> before = others;
            applyEffect(model, slope, e, *c, &others, first.fold, -1, true);
            (*shares)[j] = shareOf(before, others);
        }
}

// A length factor the outline witnesses (over the family's critical z) that μ's residual no
// longer confirms once other effects were fitted: they took up part of it (a material's n,
// fitted to μ with a stale camera's images among its records, carries a share of that camera's
// error). Taken out first, before every effect added so far, on each fold's training records,
// it is added where the held-out RMS with every effect refitted that way drops by the minimum
// relative gain. Returns the step with its held-out records per fold, or false.
bool witnessedFactorFirst(const FrictionModel &model, const fe::ReductionSlope *slope, const ResidualSet &first,
                          const ResidualSet &round, const std::vector<RankedCandidate> &ranking,
                          const std::set<std::string> &taken, const LoopSummary &s, double cvNow,
                          const RankingOptions &opt, LoopEffectStep *step,
                          std::vector<std::vector<LoopRecord>> *perFold)
{
    for (const RankedCandidate &r : ranking) {
        if (!std::isfinite(r.witnessZ) || !(r.witnessZ > r.zFamily) || taken.count(r.name) || r.symptom) continue;
        const Candidate *c = candidateNamed(first, r.name);
        if (!c || c->kind != "categorical" || readingOf(first.usable, *c) != GroupReading::Scale) continue;
        LoopEffectStep trialStep = readEffect(model, round, r, false);
        std::vector<std::vector<LoopRecord>> trial(size_t(first.folds), first.usable);
        for (int k = 0; k < first.folds; ++k) {
            applyEffect(model, slope, trialStep, *c, &trial[size_t(k)], first.fold, k);
            for (const LoopEffectStep &e : s.effects)
                if (const Candidate *ce = candidateNamed(first, e.name))
                    applyEffect(model, slope, e, *ce, &trial[size_t(k)], first.fold, k);
        }
        const double cvWith = rms(heldOut(trial, first.fold));
        if (!(cvWith < (1 - opt.minRelativeGain) * cvNow)) continue;
        trialStep.cvRmsBefore = cvNow;
        trialStep.cvRmsAfter = cvWith;
        trialStep.takenFirst = true;
        *step = std::move(trialStep);
        *perFold = std::move(trial);
        return true;
    }
    return false;
}

// After the first effect: take it out of the records (fitted on all of them for the next
// ranking, and on each fold's training records for the held-out error), rank again on what
// is left, and add the leader while it is significant (family-wise, as the first) and the
// held-out RMS with every effect refitted per fold drops.
void addFurtherEffects(const FrictionModel &model, const fe::ReductionSlope *slope, const ResidualSet &first,
                       const RankingOptions &opt, LoopSummary *s, std::vector<EffectShare> *shares)
{
    constexpr size_t kMaxEffects = 5;
    std::vector<LoopRecord> all = first.usable;
    std::vector<std::vector<LoopRecord>> perFold(size_t(first.folds), first.usable);
    std::set<std::string> taken;
    const LoopEffectStep &lead = s->effects.front();
    const Candidate *c = candidateNamed(first, lead.name);
    if (!c) return;
    applyEffect(model, slope, lead, *c, &all, first.fold, -1);
    shares->push_back(shareOf(first.usable, all));
    for (int k = 0; k < first.folds; ++k) applyEffect(model, slope, lead, *c, &perFold[size_t(k)], first.fold, k);
    markTaken(lead, &taken);
    bool carried = lead.reading == "fe_slope";
    double cvNow = rms(heldOut(perFold, first.fold));
    // An effect added: taken out of the records (fitted on all of them) and of each fold's,
    // with its held-out records per fold.
    auto add = [&](LoopEffectStep step, const Candidate &cand, std::vector<std::vector<LoopRecord>> trial) {
        perFold = std::move(trial);
        const std::vector<LoopRecord> before = all;
        applyEffect(model, slope, step, cand, &all, first.fold, -1);
        shares->push_back(shareOf(before, all));
        markTaken(step, &taken);
        carried = carried || step.reading == "fe_slope";
        cvNow = step.cvRmsAfter;
        s->cvRmsAfter = cvNow;
        s->effects.push_back(std::move(step));
        // The next round looks at what every effect so far leaves fitted together: an effect
        // fitted while a later one was still in the records carries part of it, and that part
        // would read as a further effect.
        backfit(model, slope, first, s->effects, shares);
        all = withShares(model, slope, first.usable, *shares, shares->size(), false);
    };
    while (s->effects.size() < kMaxEffects) {
        ResidualSet round;
        std::vector<RankedCandidate> ranking =
            rankRound(model, slope, all, taken, carried, first.fold, first.folds, opt, &round);
        lookPastAMaskingEffect(model, slope, round, taken, carried, opt, &ranking);
        weighRivals(model, slope, round, taken, carried, opt, &ranking);
        noteCarried(round, ranking, int(s->effects.size()) + 1, opt, s);
        if (ranking.empty() || !ranking.front().significant) {
            LoopEffectStep step;
            std::vector<std::vector<LoopRecord>> trial;
            if (witnessedFactorFirst(model, slope, first, round, ranking, taken, *s, cvNow, opt, &step, &trial)) {
                step.ranking = ranking;
                const Candidate *cand = candidateNamed(round, step.name);
                add(std::move(step), *cand, std::move(trial));
                continue;
            }
            s->lastRanking = ranking;
            s->stopped = "no further candidate is significant" + bestLeft(round, ranking);
            return;
        }
        const RankedCandidate &next = ranking.front();
        const bool physicalReduction =
            isReductionCandidate(next.name) && !model.correctsReduction() && slope && !carried;
        LoopEffectStep step = readEffect(model, round, next, physicalReduction);
        step.ranking = ranking;
        const Candidate *cand = candidateNamed(round, step.name);
        if (!cand) return;
        std::vector<std::vector<LoopRecord>> trial = perFold;
        for (int k = 0; k < first.folds; ++k) applyEffect(model, slope, step, *cand, &trial[size_t(k)], first.fold, k);
        step.cvRmsBefore = cvNow;
        step.cvRmsAfter = rms(heldOut(trial, first.fold));
        s->lastRanking = ranking;
        if (!(step.cvRmsAfter < (1 - opt.minRelativeGain) * cvNow)) {
            s->stopped = "`" + next.name + "` is significant on the residual left, but the held-out RMS with it (" +
                         f4(step.cvRmsAfter) + ") does not drop below " + f4(cvNow) + " by " +
                         f4(100 * opt.minRelativeGain, "%.0f") + " %";
            return;
        }
        add(std::move(step), *cand, std::move(trial));
    }
    s->stopped = "the most effects one run adds (" + std::to_string(kMaxEffects) + ")";
}

// The estimates of several effects, each fitted with every other one taken out (backfitting:
// a few rounds of refitting each on the records the others leave). An effect fitted while
// another was still in the records carries part of it; these are the estimates stated.
void refitTogether(const FrictionModel &model, const fe::ReductionSlope *slope, const ResidualSet &first,
                   std::vector<EffectShare> shares, LoopSummary *s)
{
    if (s->effects.size() < 2) return;
    constexpr int kRounds = kBackfitRounds;
    for (int round = 0; round < kRounds; ++round)
        for (size_t j = 0; j < s->effects.size(); ++j) {
            LoopEffectStep &e = s->effects[j];
            const Candidate *c = candidateNamed(first, e.name);
            if (!c || e.reading == "fe_slope") continue;
            std::vector<LoopRecord> others = withShares(model, slope, first.usable, shares, j, false);
            const std::vector<LoopRecord> before = others;
            applyEffect(model, slope, e, *c, &others, first.fold, -1, true);
            shares[j] = shareOf(before, others);
            if (round + 1 < kRounds) continue;
            ResidualSet set;
            set.folds = first.folds, set.fold = first.fold;
            set.usable = before;
            for (const LoopRecord &r : before) {
                set.residual.push_back(r.muModel - r.muRef);
                set.scaleSens.push_back(r.scaleSens);
                set.uSens.push_back(r.uSens);
            }
            if (e.reading == "scale" || e.reading == "n") {
                e.grouping = fitGrouping(model, before, *c, e.reading == "n" ? GroupReading::N : GroupReading::Scale,
                                         first.fold, first.folds);
                relativeToTypical(&e.grouping);
            } else if (e.reading == "drift")
                e.drift = fitDrift(model, before, *c, first.fold, first.folds);
            else if (e.reading == "process" && c->kind == "interaction") {
                e.slopeLevels.clear(), e.levelSlopes.clear();
                readLevelSlopes(*c, set, e.form, &e);
            } else if (e.reading == "process")
                e.linear = fitLinearEffect(*c, set.residual, e.form, set.scaleSens, set.uSens);
        }
    const LoopEffectStep &lead = s->effects.front();
    s->grouping = lead.grouping, s->linear = lead.linear, s->drift = lead.drift;
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
                           const std::vector<std::string> &feSweeps, const std::string &calibrationDir)
{
    Manifest manifest;
    JournalJoin join;
    std::string err;
    if (!readJournalManifest(journalDir, referenceCsv, &manifest, &join, &err, calibrationDir))
        throw std::runtime_error(err);
    const std::string source = "Journal: `" + journalDir + "` (" + std::to_string(join.lines) + " lines, " +
                               std::to_string(join.results) + " results, " + std::to_string(join.scaleChecks) +
                               " scale checks), joined by record id with `" + referenceCsv +
                               "`: " + std::to_string(join.joined) +
                               " records with a reference value and a saved frame (" + std::to_string(join.calibrated) +
                               " measured through the calibration file the device used, and re-measured through it), "
                               "re-measured with the current pipeline (the device's own results are the device_* "
                               "columns); " +
                               join.geometry;
    LoopSummary s = runLoopOn(manifest, source, join.skipped, reportDir, modelName, opt, feSweeps);
    s.journal = join;
    return s;
}

// Each material's m where the records carry the press's force (none: an empty section).
RateSensitivity rateFromForces(const std::vector<LoopRecord> &usable, const std::vector<std::string> &feSweeps)
{
    fe::UpsettingForce force;
    std::string e;
    for (const LoopRecord &r : usable)
        if (r.columns.count("force_kn") || r.columns.count("peak_force_kn")) {
            if (!force.load(feSweeps, &e)) {
                std::cerr << "icacam loop: no rate sensitivity: " << e << "\n";
                return {};
            }
            return fitRateSensitivity(usable, force);
        }
    return {};
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
    s.rate = rateFromForces(set.usable, feSweeps);

    fe::ReductionSlope slope;
    bool slopeLoaded = false;
    const std::map<std::string, std::vector<double>> physicalForms =
        reductionForms(*model, set, feSweeps, &slope, &slopeLoaded);
    const std::map<std::string, FittedForm> fittedForms = groupingForms(*model, set);
    s.ranking =
        rankCandidates(set.candidates, set.residual, opt, &set.scaleSens, &set.uSens, &physicalForms, &fittedForms);
    lookPastAMaskingEffect(*model, slopeLoaded ? &slope : nullptr, set, {}, false, opt, &s.ranking);
    weighRivals(*model, slopeLoaded ? &slope : nullptr, set, {}, false, opt, &s.ranking);
    noteCarried(set, s.ranking, 1, opt, &s);
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
            s.physical = slopeLoaded = true;
    }
    if (s.physical) {
        set.slopeCases = slope.cases();
        correctReduction(*model, slope, &set, &s);
    }
    if (s.chosen.empty()) {
        s.stopped = "no candidate is significant" + bestLeft(set, s.ranking);
    } else {
        LoopEffectStep first = readEffect(*model, set, s.ranking.front(), s.physical);
        first.cvRmsBefore = s.rmsBefore;
        if (s.physical) first.cvRmsAfter = s.rmsPhysical;
        s.cvRmsAfter = first.cvRmsAfter;
        s.chosen = first.name;
        s.reading = first.reading, s.cvRmsPatch = first.cvRmsPatch;
        s.grouping = first.grouping, s.linear = first.linear, s.drift = first.drift;
        s.effects.push_back(first);
        std::vector<EffectShare> shares;
        addFurtherEffects(*model, slopeLoaded ? &slope : nullptr, set, opt, &s, &shares);
        refitTogether(*model, slopeLoaded ? &slope : nullptr, set, shares, &s);
    }
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
    std::string manifestPath, journalDir, referenceCsv, calibrationDir, reportDir, modelName = friction::kDefaultModel;
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
        else if (opts.is("--calibrations"))
            calibrationDir = opts.value();
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
    if (!calibrationDir.empty() && journalDir.empty())
        throw cli::UsageError("--calibrations applies to --journal", usage());
    // By default the FE data the product's table was generated from (its kFeSources).
    if (feSweeps.empty())
        for (const std::string &name : fe::splitSources(friction::reduction_table::kFeSources))
            feSweeps.push_back(repoFile(name));
    const loop::LoopSummary s = journalDir.empty() ? loop::runLoop(manifestPath, reportDir, modelName, opt, feSweeps)
                                                   : loop::runJournalLoop(journalDir, referenceCsv, reportDir,
                                                                          modelName, opt, feSweeps, calibrationDir);
    std::cout << "records " << s.records << " usable " << s.usable << "\n"
              << "rms_before " << f4(s.rmsBefore) << "\ncv_rms_offset " << f4(s.cvRmsOffset) << "\n"
              << "top " << (s.ranking.empty() ? "-" : s.ranking.front().name) << "\n"
              << "chosen " << (s.chosen.empty() ? "(none)" : s.chosen) << "\n"
              << "rms_after " << f4(s.cvRmsAfter) << (s.physical ? " (physical FE du/dr correction)" : "") << "\n";
    loop::printPhysical(std::cout, s);
    for (const loop::RecordFinding &f : s.carried) {
        std::cout << "carried_by " << f.candidate << " z " << f4(f.z, "%.1f") << " -> " << f4(f.zWithout, "%.1f")
                  << " without";
        for (const loop::CarryingRecord &r : f.records) std::cout << " " << loop::describe(r, f.candidate);
        std::cout << "\n";
    }
    if (s.physical)
        std::cout << "fe_slope_scale " << f4(s.slopeScale, "%.3f") << " cv_rms_scaled " << f4(s.cvRmsPhysicalScaled)
                  << "\n";
    for (const loop::RateFit &r : s.rate.materials) {
        std::cout << "rate_m " << r.material << " ";
        if (r.fitted)
            std::cout << f4(r.m, "%.3f") << " +- " << f4(r.coverage * r.mSigma, "%.3f")
                      << " (k=" << f4(r.coverage, "%.2f") << ", " << r.records << " records)\n";
        else
            std::cout << "- (" << r.why << ")\n";
    }
    std::cout << "report " << reportDir << "/report.md\n";
    return 0;
}

} // namespace icacam::host
