#include "host_tools/loop/loop_effects.h"

namespace icacam::host::loop {

void refreshRecords(const friction::FrictionModel &model, std::vector<LoopRecord> *records)
{
    for (LoopRecord &r : *records) {
        const friction::ModelInputs in = inputsOf(r);
        const friction::ModelEstimate e = model.estimate(in);
        r.muModel = e.mu + r.muOffset;
        r.scaleSens = e.dMuDu * r.uMm;
        r.uSens = e.dMuDu;
    }
}

double carriedReduction(const LoopRecord &r)
{
    if (r.reduction >= 0) return r.reduction;
    const auto est = r.diagnostics.find("diag_reduction_est");
    return est != r.diagnostics.end() ? est->second : -1;
}

std::vector<double> sensitivityOf(const std::vector<LoopRecord> &records, const std::string &form)
{
    std::vector<double> s;
    for (const LoopRecord &r : records) s.push_back(form == "scale" ? r.scaleSens : form == "u" ? r.uSens : 1.0);
    return s;
}

void applyEffect(const friction::FrictionModel &model, const fe::ReductionSlope *slope, const LoopEffectStep &step,
                 const Candidate &candidate, std::vector<LoopRecord> *records, const std::vector<int> &fold, int k,
                 bool onlyDiffering)
{
    std::vector<bool> train(records->size());
    for (size_t i = 0; i < records->size(); ++i) train[i] = k < 0 || fold[i] != k;
    if (step.reading == "fe_slope") {
        if (slope)
            for (LoopRecord &r : *records) {
                friction::ModelInputs in = inputsOf(r);
                in.hFinalMm = 0;
                r.uMm = fe::uAtModelReduction(model, *slope, in, carriedReduction(r));
            }
    } else if (step.reading == "scale" || step.reading == "n") {
        applyGrouping(model, records, candidate, step.reading == "scale" ? GroupReading::Scale : GroupReading::N, train,
                      onlyDiffering);
    } else if (step.reading == "drift") {
        applyDrift(model, records, candidate, train);
    } else {
        std::vector<double> y;
        for (const LoopRecord &r : *records) y.push_back(r.muModel - r.muRef);
        const std::vector<double> sens = sensitivityOf(*records, step.form);
        const bool linear = step.form == "scale" || step.form == "u";
        const std::vector<double> pred = predictFrom(candidate, y, fold, k, linear ? &sens : nullptr);
        for (size_t i = 0; i < records->size(); ++i) (*records)[i].muOffset -= pred[i];
    }
    refreshRecords(model, records);
}

EffectShare shareOf(const std::vector<LoopRecord> &before, const std::vector<LoopRecord> &after)
{
    EffectShare e;
    for (size_t i = 0; i < before.size(); ++i) {
        e.uFactor.push_back(after[i].uMm > 0 ? before[i].uMm / after[i].uMm : 1.0);
        e.nShift.push_back(after[i].n - before[i].n);
        e.muShift.push_back(after[i].muOffset - before[i].muOffset);
        const auto b = before[i].diagnostics.find("diag_rmax_over_r0"),
                   a = after[i].diagnostics.find("diag_rmax_over_r0");
        e.outlineFactor.push_back(b != before[i].diagnostics.end() && a != after[i].diagnostics.end() && a->second > 0
                                      ? b->second / a->second
                                      : 1.0);
    }
    return e;
}

std::vector<LoopRecord> withShares(const friction::FrictionModel &model, const fe::ReductionSlope *slope,
                                   const std::vector<LoopRecord> &original, const std::vector<EffectShare> &shares,
                                   size_t skip, bool carry)
{
    std::vector<LoopRecord> out = original;
    for (size_t j = 0; j < shares.size(); ++j) {
        if (j == skip) continue;
        for (size_t i = 0; i < out.size(); ++i) {
            out[i].uMm /= shares[j].uFactor[i];
            if (const auto it = out[i].diagnostics.find("diag_rmax_over_r0"); it != out[i].diagnostics.end())
                it->second /= shares[j].outlineFactor[i];
            out[i].n += shares[j].nShift[i];
            out[i].muOffset += shares[j].muShift[i];
        }
    }
    if (carry && slope)
        for (LoopRecord &r : out) {
            friction::ModelInputs in = inputsOf(r);
            in.hFinalMm = 0;
            r.uMm = fe::uAtModelReduction(model, *slope, in, carriedReduction(r));
        }
    refreshRecords(model, &out);
    return out;
}

} // namespace icacam::host::loop
