#include "host_tools/loop/loop_physics.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "host_tools/loop/loop_silhouette.h"

namespace icacam::host::loop {

namespace {

// The range a fitted parameter may take: beyond it the model has no data (n) or the
// camera would be off by more than any calibration slip (s).
constexpr double kScaleMin = 0.7, kScaleMax = 1.4;
constexpr double kNMin = 0.02, kNMax = 0.6;

constexpr double kShiftMax = 0.3;

// μ of a record with the group's parameter applied (a factor s, or a shift Δn).
double muWith(const friction::FrictionModel &model, const LoopRecord &r, GroupReading reading, double p)
{
    friction::ModelInputs in = inputsOf(r);
    if (reading == GroupReading::Scale)
        in.uMm = r.uMm / p;
    else
        in.n = std::clamp(r.n + p, kNMin, kNMax);
    return model.estimate(in).mu + r.muOffset;
}

double neutral(GroupReading reading)
{
    return reading == GroupReading::Scale ? 1.0 : 0.0;
}

double declaredN(const std::vector<LoopRecord> &usable, const std::vector<size_t> &members)
{
    double s = 0;
    for (size_t i : members) s += usable[i].n;
    return members.empty() ? 0 : s / double(members.size());
}

// Least squares of μ(p) − μ_ref over the members (Gauss–Newton, numerical derivative).
// Returns p, and Σ J² and the sum of squares at p for the uncertainty.
double fitParameter(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                    const std::vector<size_t> &members, GroupReading reading, double start, double *sumJ2, double *sse)
{
    const double lo = reading == GroupReading::Scale ? kScaleMin : -kShiftMax;
    const double hi = reading == GroupReading::Scale ? kScaleMax : kShiftMax;
    const double h = 1e-4;
    double p = start;
    for (int it = 0; it < 30; ++it) {
        double jr = 0, jj = 0;
        for (size_t i : members) {
            const LoopRecord &r = usable[i];
            const double res = muWith(model, r, reading, p) - r.muRef;
            const double j = (muWith(model, r, reading, p + h) - muWith(model, r, reading, p - h)) / (2 * h);
            jr += j * res;
            jj += j * j;
        }
        if (!(jj > 0)) break;
        const double next = std::clamp(p - jr / jj, lo, hi);
        const bool done = std::fabs(next - p) < 1e-9;
        p = next;
        if (done) break;
    }
    *sumJ2 = 0;
    *sse = 0;
    for (size_t i : members) {
        const LoopRecord &r = usable[i];
        const double res = muWith(model, r, reading, p) - r.muRef;
        const double j = (muWith(model, r, reading, p + h) - muWith(model, r, reading, p - h)) / (2 * h);
        *sumJ2 += j * j;
        *sse += res * res;
    }
    return p;
}

// The jackknife's σ of each level where it exceeds the pooled scatter's.
void jackknifeSigma(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, GroupReading reading,
                    const std::map<std::string, std::vector<size_t>> &members, std::map<std::string, GroupFit> *levels);

double typical(std::vector<double> values, double declared);

// A length factor per level as the outline sees it relative to the typical level, times one
// factor common to every level fitted to μ (loop_silhouette.h): the outline tells the groups
// apart far more sharply than μ's residual, and μ's held-out error judges whether it was the
// scale that told them apart. Levels the outline does not cover keep μ's fit.
void factorsFromOutline(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                        const std::map<std::string, std::vector<size_t>> &members, const OutlineLevels &outline,
                        std::map<std::string, GroupFit> *levels);

// Fits every level on the records where `train` holds; a length factor from the outline where
// the records have one (factorsFromOutline).
std::map<std::string, GroupFit> fitLevels(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                                          const Candidate &g, GroupReading reading, const std::vector<bool> &train,
                                          double *scatter, bool jackknife = false)
{
    std::map<std::string, std::vector<size_t>> members;
    for (size_t i = 0; i < usable.size(); ++i)
        if (train[i]) members[g.levels[i]].push_back(i);
    std::map<std::string, GroupFit> out;
    std::map<std::string, double> sumJ2;
    double sse = 0;
    int dof = 0;
    for (const auto &[level, idx] : members) {
        GroupFit f;
        f.level = level;
        f.records = int(idx.size());
        f.declared = reading == GroupReading::Scale ? 1.0 : declaredN(usable, idx);
        f.value = neutral(reading); // the fitted parameter; a shift is turned into n below
        if (idx.size() >= 3) {
            double s2 = 0;
            f.value = fitParameter(model, usable, idx, reading, neutral(reading), &sumJ2[level], &s2);
            f.fitted = true;
            sse += s2;
            dof += int(idx.size()) - 1;
        }
        out[level] = f;
    }
    // One scatter for all groups (the reference method's and the measurement's, the same for
    // every camera and material): more degrees of freedom than any one group has.
    *scatter = dof > 0 ? std::sqrt(sse / dof) : 0;
    for (auto &[level, f] : out)
        if (f.fitted && sumJ2[level] > 0) f.sigma = *scatter / std::sqrt(sumJ2[level]);
    if (jackknife) jackknifeSigma(model, usable, reading, members, &out);
    if (reading == GroupReading::Scale)
        factorsFromOutline(model, usable, members, outlineLevels(usable, g, train), &out);
    return out;
}

void factorsFromOutline(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                        const std::map<std::string, std::vector<size_t>> &members, const OutlineLevels &outline,
                        std::map<std::string, GroupFit> *levels)
{
    if (outline.mean.size() < 2) return;
    // The levels relative to their typical one, as the outline sees them.
    std::vector<double> q;
    for (const auto &[level, m] : outline.mean) q.push_back(m);
    const double typicalQ = typical(q, 0.0);
    // One factor common to every level, from μ (Gauss–Newton): the records' scale as a whole.
    struct Sums {
        double jr = 0, jj = 0, sse = 0;
        int n = 0;
    };
    auto sums = [&](double common) {
        Sums t;
        const double h = 1e-4;
        for (const auto &[level, idx] : members) {
            const auto m = outline.mean.find(level);
            if (m == outline.mean.end()) continue;
            const double rel = std::exp(m->second - typicalQ);
            for (size_t i : idx) {
                const LoopRecord &r = usable[i];
                const double res = muWith(model, r, GroupReading::Scale, rel * common) - r.muRef;
                const double j = (muWith(model, r, GroupReading::Scale, rel * (common + h)) -
                                  muWith(model, r, GroupReading::Scale, rel * (common - h))) /
                                 (2 * h);
                t.jr += j * res, t.jj += j * j, t.sse += res * res, ++t.n;
            }
        }
        return t;
    };
    double common = 1;
    for (int it = 0; it < 30; ++it) {
        const Sums t = sums(common);
        if (!(t.jj > 0)) return;
        const double next = std::clamp(common - t.jr / t.jj, kScaleMin, kScaleMax);
        const bool done = std::fabs(next - common) < 1e-9;
        common = next;
        if (done) break;
    }
    // The common factor's own uncertainty (μ's scatter about it) enters every level's.
    const Sums t = sums(common);
    const double commonRel = t.n > 1 && t.jj > 0 ? std::sqrt(t.sse / (t.n - 1) / t.jj) / common : 0;
    for (auto &[level, f] : *levels) {
        const auto m = outline.mean.find(level);
        if (m == outline.mean.end()) continue;
        f.value = std::exp(m->second - typicalQ) * common;
        f.sigma = f.value * std::hypot(outline.se.at(level), commonRel);
        f.fitted = true;
        f.withOutline = true;
    }
}

void jackknifeSigma(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, GroupReading reading,
                    const std::map<std::string, std::vector<size_t>> &members, std::map<std::string, GroupFit> *levels)
{
    std::map<std::string, GroupFit> &out = *levels;
    // The scatter-based σ assumes every record's μ error alike; the radii's own noise and the
    // reference's act unequally with u. The jackknife over a group's records carries whatever
    // acts: the larger of the two is stated.
    for (auto &[level, f] : out) {
        const std::vector<size_t> &idx = members.at(level);
        if (!f.fitted || idx.size() < 4) continue;
        std::vector<double> theta;
        for (size_t leave = 0; leave < idx.size(); ++leave) {
            std::vector<size_t> rest;
            for (size_t j = 0; j < idx.size(); ++j)
                if (j != leave) rest.push_back(idx[j]);
            double j2 = 0, s2 = 0;
            theta.push_back(fitParameter(model, usable, rest, reading, f.value, &j2, &s2));
        }
        double mean = 0, var = 0;
        for (double t : theta) mean += t;
        mean /= double(theta.size());
        for (double t : theta) var += (t - mean) * (t - mean);
        const double m = double(theta.size());
        f.sigma = std::max(f.sigma, std::sqrt((m - 1) / m * var));
    }
}

// The value a group reports: the factor, or the declared n plus the fitted shift.
double reported(const GroupFit &f, GroupReading reading)
{
    return reading == GroupReading::Scale ? f.value : f.declared + f.value;
}

// The silhouette check of a length factor: per record R_max measured over the FE's R_max (D0
// scaled) at the declared n, μ_ref and the recorded reduction (else the model's 50 %); per
// group the mean ratio over the mean of the other groups whose μ finds their scale right (the
// FE's own bias cancels), σ from the two means' standard errors.
void silhouetteCheck(const std::vector<LoopRecord> &usable, const Candidate &g, std::vector<GroupFit> *groups)
{
    std::map<std::string, std::vector<double>> ratios;
    for (size_t i = 0; i < usable.size(); ++i) {
        double y = 0;
        if (silhouetteLogRatio(usable[i], &y)) ratios[g.levels[i]].push_back(std::exp(y));
    }
    auto meanSe = [](const std::vector<double> &v, double *se) {
        double m = 0, q = 0;
        for (double x : v) m += x;
        m /= double(v.size());
        for (double x : v) q += (x - m) * (x - m);
        *se = v.size() > 1 ? std::sqrt(q / double(v.size() - 1) / double(v.size())) : 0;
        return m;
    };
    // The reference: the groups whose μ says their scale is right (factor within 2σ of 1).
    std::set<std::string> reference;
    for (const GroupFit &f : *groups)
        if (f.fitted && std::fabs(f.value - 1) <= 2 * f.sigma) reference.insert(f.level);
    for (GroupFit &f : *groups) {
        const auto own = ratios.find(f.level);
        std::vector<double> others;
        for (const auto &[level, v] : ratios)
            if (level != f.level && reference.count(level)) others.insert(others.end(), v.begin(), v.end());
        if (own == ratios.end() || own->second.size() < 3 || others.size() < 3) continue;
        double se1 = 0, se2 = 0;
        const double m1 = meanSe(own->second, &se1), m2 = meanSe(others, &se2);
        f.silhouette = m1 / m2;
        f.silhouetteSigma = f.silhouette * std::sqrt(se1 * se1 / (m1 * m1) + se2 * se2 / (m2 * m2));
    }
}

// The levels relative to the typical one (the median of three or more, else the one nearest
// the declared value): most cameras calibrated right, most materials declared right. A
// level within 2σ of the declared value then stays declared.
// The typical level's parameter: the median of three or more, else the one nearest `declared`.
double typical(std::vector<double> values, double declared)
{
    double anchor = values.front();
    if (values.size() >= 3) {
        std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
        return values[values.size() / 2];
    }
    for (double v : values)
        if (std::fabs(v - declared) < std::fabs(anchor - declared)) anchor = v;
    return anchor;
}

void anchorLevels(GroupReading reading, std::map<std::string, GroupFit> *fit)
{
    std::vector<double> values;
    for (const auto &[level, f] : *fit)
        if (f.fitted) values.push_back(f.value);
    if (values.empty()) return;
    const double declared = neutral(reading);
    const double anchor = typical(values, declared);
    for (auto &[level, f] : *fit) {
        if (!f.fitted) continue;
        f.value = reading == GroupReading::Scale ? f.value / anchor : f.value - anchor;
        if (std::fabs(f.value - declared) <= 2 * f.sigma) f.value = declared;
    }
}

} // namespace

void applyGrouping(const friction::FrictionModel &model, std::vector<LoopRecord> *records, const Candidate &g,
                   GroupReading reading, const std::vector<bool> &train, bool onlyDiffering)
{
    double scatter = 0;
    std::map<std::string, GroupFit> fit = fitLevels(model, *records, g, reading, train, &scatter);
    if (onlyDiffering) anchorLevels(reading, &fit);
    for (size_t i = 0; i < records->size(); ++i) {
        LoopRecord &r = (*records)[i];
        const auto it = fit.find(g.levels[i]);
        const double p = it != fit.end() ? it->second.value : neutral(reading);
        if (reading == GroupReading::Scale)
            takeOutLengthFactor(&r, p);
        else
            r.n = std::clamp(r.n + p, kNMin, kNMax);
    }
}

void relativeToTypical(PhysicalFit *fit)
{
    std::vector<double> values;
    for (const GroupFit &g : fit->groups)
        if (g.fitted) values.push_back(fit->reading == GroupReading::Scale ? g.value : g.value - g.declared);
    if (values.empty()) return;
    const double anchor = typical(values, neutral(fit->reading));
    // The typical level's own uncertainty enters every other level's relative estimate.
    double anchorSigma = 0;
    for (const GroupFit &g : fit->groups)
        if (g.fitted && (fit->reading == GroupReading::Scale ? g.value : g.value - g.declared) == anchor)
            anchorSigma = g.sigma;
    for (GroupFit &g : fit->groups) {
        if (!g.fitted) continue;
        const bool isAnchor = (fit->reading == GroupReading::Scale ? g.value : g.value - g.declared) == anchor;
        g.value = fit->reading == GroupReading::Scale ? g.value / anchor : g.value - anchor;
        if (!isAnchor) g.sigma = std::hypot(g.sigma, anchorSigma);
    }
}

const char *formName(GroupReading reading)
{
    return reading == GroupReading::Scale ? "factor" : "n";
}

FittedForm groupingForm(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                        const Candidate &grouping, const std::vector<int> &fold, int folds)
{
    const GroupReading reading = readingOf(usable, grouping);
    Candidate one = grouping;
    one.levels.assign(usable.size(), "all");
    FittedForm f;
    f.form = formName(reading);
    const PhysicalFit base = fitGrouping(model, usable, one, reading, fold, folds);
    const PhysicalFit per = fitGrouping(model, usable, grouping, reading, fold, folds);
    f.baseline = base.cvErrors;
    f.errors = per.cvErrors;
    for (size_t i = 0; i < usable.size(); ++i) {
        f.baselineFit.push_back(base.muAfter[i] - usable[i].muRef);
        f.errorsFit.push_back(per.muAfter[i] - usable[i].muRef);
    }
    f.params0 = 1;
    f.params1 = 0;
    bool withOutline = false;
    for (const GroupFit &g : per.groups) {
        f.params1 += g.fitted ? 1 : 0;
        withOutline = withOutline || g.withOutline;
    }
    // The factors are the outline's: its test of the groups is the form's (μ's held-out error
    // confirms it in the ranking).
    if (withOutline) f.witnessZ = outlineLevels(usable, grouping, std::vector<bool>(usable.size(), true)).z;
    return f;
}

void takeOutLengthFactor(LoopRecord *r, double factor)
{
    r->uMm /= factor;
    const auto it = r->diagnostics.find("diag_rmax_over_r0");
    if (it != r->diagnostics.end()) it->second /= factor;
}

friction::ModelInputs inputsOf(const LoopRecord &r)
{
    friction::ModelInputs in;
    in.uMm = r.uMm;
    in.n = r.n;
    in.kMpa = r.kMpa;
    in.d0Mm = r.d0Mm;
    in.h0Mm = r.h0Mm;
    in.hFinalMm = r.reduction >= 0 ? r.h0Mm * (1 - r.reduction) : 0;
    return in;
}

GroupReading readingOf(const std::vector<LoopRecord> &usable, const Candidate &g)
{
    return isMaterialGrouping(usable, g) ? GroupReading::N : GroupReading::Scale;
}

PhysicalFit fitGrouping(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, const Candidate &g,
                        GroupReading reading, const std::vector<int> &fold, int folds)
{
    PhysicalFit out;
    out.reading = reading;
    const std::map<std::string, GroupFit> all =
        fitLevels(model, usable, g, reading, std::vector<bool>(usable.size(), true), &out.scatter, true);
    for (size_t i = 0; i < usable.size(); ++i)
        out.muAfter.push_back(muWith(model, usable[i], reading, all.at(g.levels[i]).value));
    for (auto [level, f] : all) {
        f.value = reported(f, reading);
        out.groups.push_back(f);
    }
    if (reading == GroupReading::Scale) silhouetteCheck(usable, g, &out.groups);
    out.cvErrors.assign(usable.size(), 0);
    for (int k = 0; k < folds; ++k) {
        std::vector<bool> train(usable.size());
        for (size_t i = 0; i < usable.size(); ++i) train[i] = fold[i] != k;
        double scatter = 0;
        const std::map<std::string, GroupFit> fit = fitLevels(model, usable, g, reading, train, &scatter);
        for (size_t i = 0; i < usable.size(); ++i) {
            if (fold[i] != k) continue;
            const auto it = fit.find(g.levels[i]);
            // A level the training folds never saw stays as declared.
            const double p = it != fit.end() ? it->second.value : neutral(reading);
            out.cvErrors[i] = muWith(model, usable[i], reading, p) - usable[i].muRef;
        }
    }
    return out;
}

LinearEffect fitLinearEffect(const Candidate &c, const std::vector<double> &y, const std::string &form,
                             const std::vector<double> &scaleSens, const std::vector<double> &uSens)
{
    LinearEffect e;
    e.form = form;
    const std::vector<double> *g = form == "scale" ? &scaleSens : form == "u" ? &uSens : nullptr;
    // residual = w·(a + b·(x − x̄)), w = 1 in the μ form: ordinary least squares in (a, b).
    double xm = 0;
    int nx = 0;
    e.xMin = INFINITY, e.xMax = -INFINITY;
    for (double x : c.x)
        if (std::isfinite(x)) {
            xm += x;
            ++nx;
            e.xMin = std::min(e.xMin, x);
            e.xMax = std::max(e.xMax, x);
        }
    if (nx < 3) return e;
    xm /= nx;
    double s00 = 0, s01 = 0, s11 = 0, t0 = 0, t1 = 0;
    std::vector<double> w;
    for (size_t i = 0; i < y.size(); ++i) {
        const double wi = g ? (*g)[i] : 1.0;
        const double xi = std::isfinite(c.x[i]) ? c.x[i] - xm : 0;
        s00 += wi * wi, s01 += wi * wi * xi, s11 += wi * wi * xi * xi;
        t0 += wi * y[i], t1 += wi * xi * y[i];
        w.push_back(std::fabs(wi));
    }
    const double det = s00 * s11 - s01 * s01;
    if (!(det > 0)) return e;
    const double a = (s11 * t0 - s01 * t1) / det, b = (s00 * t1 - s01 * t0) / det;
    double sse = 0;
    for (size_t i = 0; i < y.size(); ++i) {
        const double wi = g ? (*g)[i] : 1.0;
        const double xi = std::isfinite(c.x[i]) ? c.x[i] - xm : 0;
        const double r = y[i] - wi * (a + b * xi);
        sse += r * r;
    }
    const double s2 = y.size() > 2 ? sse / double(y.size() - 2) : 0;
    e.slope = b;
    e.sigma = std::sqrt(s2 * s00 / det);
    std::nth_element(w.begin(), w.begin() + long(w.size() / 2), w.end());
    e.muSpan = b * (e.xMax - e.xMin) * w[w.size() / 2];
    e.logarithmic = c.logarithmic;
    if (c.logarithmic) e.xMin = std::exp(e.xMin), e.xMax = std::exp(e.xMax);
    return e;
}

} // namespace icacam::host::loop
