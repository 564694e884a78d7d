#include "host_tools/coverage_score.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

namespace icacam::host {

namespace {

double median(std::vector<double> v)
{
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double cell(const ManifestRow &r, const std::string &key)
{
    double v;
    return r.has(key) && parseNumber(r.get(key), &v) ? v : std::numeric_limits<double>::quiet_NaN();
}

struct Accumulator {
    ConditionScore s;
    std::vector<double> ratios, abs;
    void add(const std::string &id, const std::string &status, double dmu, double sigma, double muTrue,
             const ScoreOptions &opt)
    {
        ++s.measured;
        const double a = std::fabs(dmu);
        abs.push_back(a);
        ratios.push_back(sigma > 0 ? a / sigma : (a == 0 ? 0 : std::numeric_limits<double>::infinity()));
        if (a <= opt.k * sigma) ++s.withinK;
        if (a > std::fabs(s.worstDmu) || s.worstId.empty()) s.worstDmu = dmu, s.worstId = id, s.worstStatus = status;
        const bool right = isRight(dmu, muTrue, opt);
        if (right) ++s.right;
        if (status == "ok") {
            ++s.ok;
            if (right) ++s.okRight;
            if (!right) ++s.silentWrong;
            if (a > std::fabs(s.worstOkDmu) || s.worstOkId.empty()) s.worstOkDmu = dmu, s.worstOkId = id;
        }
    }
    ConditionScore finish()
    {
        s.medianRatio = median(ratios);
        s.medianAbs = median(abs);
        return s;
    }
};

} // namespace

const ConditionScore *ScoreReport::find(const std::string &condition) const
{
    for (const ConditionScore &c : conditions)
        if (c.condition == condition) return &c;
    return nullptr;
}

bool scoreResults(const Manifest &results, const Manifest &truth, const ScoreOptions &opt, ScoreReport *out,
                  std::string *error)
{
    *out = {};
    for (const char *c : {"id", "status", "mu", "mu_sigma"})
        if (!results.hasColumn(c)) {
            *error = std::string("results: no '") + c + "' column";
            return false;
        }
    for (const char *c : {"id", "mu"})
        if (!truth.hasColumn(c)) {
            *error = std::string("truth: no '") + c + "' column";
            return false;
        }
    const bool budget = results.hasColumn("sigma_model");
    std::map<std::string, const ManifestRow *> byId;
    for (const ManifestRow &r : results.rows) byId[r.get("id")] = &r;

    // Which σ: the model's own error drops out when the truth is the measuring model's own.
    auto dropModel = [&](const ManifestRow &r) {
        if (!budget || opt.modelSigma == ModelSigma::Keep) return false;
        if (opt.modelSigma == ModelSigma::Drop) return true;
        return r.get("model").rfind("paper", 0) == 0;
    };
    int dropped = 0, kept = 0;
    std::vector<std::string> order;
    std::map<std::string, Accumulator> acc;
    Accumulator all;
    all.s.condition = "all";
    for (const ManifestRow &t : truth.rows) {
        const std::string id = t.get("id"), cond = t.get("condition", "all");
        if (!acc.count(cond)) {
            order.push_back(cond);
            acc[cond].s.condition = cond;
        }
        Accumulator &a = acc[cond];
        ++a.s.total;
        if (cond != "all") ++all.s.total;
        const double muTrue = cell(t, "mu");
        const auto it = byId.find(id);
        if (it == byId.end()) {
            out->notes.push_back(id + ": no result");
            continue;
        }
        const ManifestRow &r = *it->second;
        const std::string status = r.get("status");
        const double mu = cell(r, "mu");
        if (status == "error" || !std::isfinite(mu) || !std::isfinite(muTrue)) continue;
        double sigma = cell(r, "mu_sigma");
        if (!std::isfinite(sigma)) {
            out->notes.push_back(id + ": a value without mu_sigma (counted as σ = 0)");
            sigma = 0;
        }
        if (dropModel(r)) {
            const double m = cell(r, "sigma_model");
            if (std::isfinite(m)) sigma = std::sqrt(std::max(0.0, sigma * sigma - m * m));
            ++dropped;
        } else
            ++kept;
        a.add(id, status, mu - muTrue, sigma, muTrue, opt);
        if (cond != "all") all.add(id, status, mu - muTrue, sigma, muTrue, opt);
    }
    std::set<std::string> truthIds;
    for (const ManifestRow &t : truth.rows) truthIds.insert(t.get("id"));
    for (const auto &entry : byId)
        if (!truthIds.count(entry.first)) out->notes.push_back(entry.first + ": no truth");
    for (const std::string &c : order) out->conditions.push_back(acc[c].finish());
    if (order.size() > 1 || (order.size() == 1 && order[0] != "all")) out->conditions.push_back(all.finish());
    if (!budget)
        out->sigmaSource = "σ = mu_sigma (no budget columns in the results)";
    else if (dropped && !kept)
        out->sigmaSource = "σ = sqrt(mu_sigma² − sigma_model²): the truth is the measuring model's own";
    else if (kept && !dropped)
        out->sigmaSource = "σ = mu_sigma (budget columns; sigma_model kept)";
    else
        out->sigmaSource = "σ = sqrt(mu_sigma² − sigma_model²) for paper models, mu_sigma for the others";
    return true;
}

std::string formatScore(const ScoreReport &r, const ScoreOptions &opt, bool markdown)
{
    std::string s;
    char line[512];
    auto signedOrDash = [](double v, const std::string &id) -> std::string {
        if (id.empty()) return "—";
        char b[64];
        std::snprintf(b, sizeof b, "%+.4f", v);
        return b;
    };
    char k[16];
    std::snprintf(k, sizeof k, "%g", opt.k);
    if (markdown) {
        s += std::string("| condition | measured | ok | ok on right | silent wrong | within ") + k +
             " σ | median \\|Δμ\\|/σ | median \\|Δμ\\| | worst Δμ | worst Δμ with ok |\n";
        s += "|---|---|---|---|---|---|---|---|---|---|\n";
    } else {
        const std::string within = std::string("within ") + k + " sigma";
        std::snprintf(line, sizeof line, "%-16s %9s %5s %14s %12s %14s %18s %12s %22s %12s\n", "condition", "measured",
                      "ok", "ok on right", "silent wrong", within.c_str(), "median |dmu|/sigma", "median |dmu|",
                      "worst dmu", "worst ok dmu");
        s += line;
    }
    for (const ConditionScore &c : r.conditions) {
        char measured[32], within2[32], ratio[32], med[32], worst[96], okRight[48];
        std::snprintf(measured, sizeof measured, "%d of %d", c.measured, c.total);
        std::snprintf(okRight, sizeof okRight, "%d of %d", c.okRight, c.right);
        std::snprintf(within2, sizeof within2, "%.0f %%", 100 * c.withinFraction());
        std::snprintf(ratio, sizeof ratio, "%.2f", c.medianRatio);
        std::snprintf(med, sizeof med, "%.4f", c.medianAbs);
        std::snprintf(worst, sizeof worst, "%s (%s)", signedOrDash(c.worstDmu, c.worstId).c_str(),
                      c.worstId.empty() ? "" : c.worstStatus.c_str());
        const std::string worstOk = signedOrDash(c.worstOkDmu, c.worstOkId);
        if (markdown)
            std::snprintf(line, sizeof line, "| %s | %s | %d | %s | %d | %s | %s | %s | %s | %s |\n",
                          c.condition.c_str(), measured, c.ok, okRight, c.silentWrong, c.measured ? within2 : "—",
                          c.measured ? ratio : "—", c.measured ? med : "—", c.worstId.empty() ? "—" : worst,
                          worstOk.c_str());
        else
            std::snprintf(line, sizeof line, "%-16s %9s %5d %14s %12d %14s %18s %12s %22s %12s\n", c.condition.c_str(),
                          measured, c.ok, okRight, c.silentWrong, c.measured ? within2 : "-", c.measured ? ratio : "-",
                          c.measured ? med : "-", c.worstId.empty() ? "-" : worst, worstOk.c_str());
        s += line;
    }
    std::snprintf(line, sizeof line,
                  "%s; right: |Δμ| ≤ max(%g, %g·μ), ok on right: the right readings that say ok; silent wrong: status "
                  "ok and not right; Δμ = measured − true.\n",
                  r.sigmaSource.c_str(), opt.toleranceAbs, opt.toleranceRel);
    s += markdown ? "\n" + std::string(line) : std::string(line);
    return s;
}

} // namespace icacam::host
