#include "host_tools/loop/loop_drift.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "host_tools/loop/loop_physics.h"

namespace icacam::host::loop {

namespace {

constexpr double kFactorMin = 0.7, kFactorMax = 1.4; // beyond any calibration slip

double xOf(const Candidate &c, size_t i, double xMean)
{
    return std::isfinite(c.x[i]) ? c.x[i] - xMean : 0;
}

double muAt(const friction::FrictionModel &model, const LoopRecord &r, double factor)
{
    friction::ModelInputs in = inputsOf(r);
    in.uMm = r.uMm / std::clamp(factor, kFactorMin, kFactorMax);
    return model.estimate(in).mu + r.muOffset;
}

struct Params {
    double a = 1, b = 0, xMean = 0;
    double cov00 = 0, cov11 = 0, scatter = 0;
};

// Gauss–Newton in (a, b) over the records where train holds; numerical derivatives in s.
Params fit(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, const Candidate &c,
           const std::vector<bool> &train)
{
    Params p;
    double sx = 0;
    int nx = 0;
    for (size_t i = 0; i < usable.size(); ++i)
        if (train[i] && std::isfinite(c.x[i])) sx += c.x[i], ++nx;
    p.xMean = nx ? sx / nx : 0;
    const double h = 1e-4;
    double j00 = 0, j01 = 0, j11 = 0, sse = 0;
    int count = 0;
    for (int it = 0; it < 30; ++it) {
        double g0 = 0, g1 = 0;
        j00 = j01 = j11 = sse = 0;
        count = 0;
        for (size_t i = 0; i < usable.size(); ++i) {
            if (!train[i]) continue;
            const LoopRecord &r = usable[i];
            const double x = xOf(c, i, p.xMean), s = p.a + p.b * x;
            const double res = muAt(model, r, s) - r.muRef;
            const double ds = (muAt(model, r, s + h) - muAt(model, r, s - h)) / (2 * h); // dμ/ds
            const double d0 = ds, d1 = ds * x;
            g0 += d0 * res, g1 += d1 * res;
            j00 += d0 * d0, j01 += d0 * d1, j11 += d1 * d1;
            sse += res * res;
            ++count;
        }
        const double det = j00 * j11 - j01 * j01;
        if (!(det > 0)) break;
        const double da = (j11 * g0 - j01 * g1) / det, db = (j00 * g1 - j01 * g0) / det;
        p.a -= da, p.b -= db;
        if (std::fabs(da) < 1e-10 && std::fabs(db) < 1e-12) break;
    }
    const double det = j00 * j11 - j01 * j01;
    p.scatter = count > 2 ? std::sqrt(sse / (count - 2)) : 0;
    if (det > 0) {
        p.cov00 = p.scatter * p.scatter * j11 / det;
        p.cov11 = p.scatter * p.scatter * j00 / det;
    }
    return p;
}

} // namespace

bool ordersInTime(const std::string &name)
{
    std::string n = name;
    for (char &ch : n) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    for (const char *word : {"sequence", "date", "time", "day", "hour", "order", "index", "run"})
        if (n.find(word) != std::string::npos) return true;
    return false;
}

DriftFit fitDrift(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, const Candidate &x,
                  const std::vector<int> &fold, int folds)
{
    DriftFit d;
    std::vector<bool> every(usable.size(), true);
    const Params p = fit(model, usable, x, every);
    d.xMean = p.xMean, d.level = p.a, d.slope = p.b;
    d.levelSigma = std::sqrt(p.cov00), d.slopeSigma = std::sqrt(p.cov11), d.scatter = p.scatter;
    // As for a grouping's factor (loop_physics.h): the pooled scatter assumes every record's
    // μ error alike; the jackknife over the records carries whatever acts. The larger is stated.
    if (usable.size() >= 4) {
        std::vector<double> a, b;
        for (size_t leave = 0; leave < usable.size(); ++leave) {
            every[leave] = false;
            const Params q = fit(model, usable, x, every);
            every[leave] = true;
            a.push_back(q.a + q.b * (p.xMean - q.xMean)); // the level at the full fit's x̄
            b.push_back(q.b);
        }
        const double m = double(usable.size());
        auto spread = [m](const std::vector<double> &v) {
            double mean = 0, var = 0;
            for (double t : v) mean += t;
            mean /= m;
            for (double t : v) var += (t - mean) * (t - mean);
            return std::sqrt((m - 1) / m * var);
        };
        d.levelSigma = std::max(d.levelSigma, spread(a));
        d.slopeSigma = std::max(d.slopeSigma, spread(b));
    }
    d.xMin = INFINITY, d.xMax = -INFINITY;
    for (double v : x.x)
        if (std::isfinite(v)) d.xMin = std::min(d.xMin, v), d.xMax = std::max(d.xMax, v);
    d.startFactor = p.a + p.b * (d.xMin - p.xMean);
    d.endFactor = p.a + p.b * (d.xMax - p.xMean);
    for (size_t i = 0; i < usable.size(); ++i)
        d.muAfter.push_back(muAt(model, usable[i], p.a + p.b * xOf(x, i, p.xMean)));
    d.cvErrors.assign(usable.size(), 0);
    for (int k = 0; k < folds; ++k) {
        std::vector<bool> train(usable.size());
        for (size_t i = 0; i < usable.size(); ++i) train[i] = fold[i] != k;
        const Params q = fit(model, usable, x, train);
        for (size_t i = 0; i < usable.size(); ++i)
            if (fold[i] == k) d.cvErrors[i] = muAt(model, usable[i], q.a + q.b * xOf(x, i, q.xMean)) - usable[i].muRef;
    }
    return d;
}

FittedForm driftForm(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable, const Candidate &x,
                     const std::vector<int> &fold, int folds)
{
    Candidate one{x.name, "categorical", {}, std::vector<std::string>(usable.size(), "all"), false};
    const PhysicalFit base = fitGrouping(model, usable, one, GroupReading::Scale, fold, folds);
    const DriftFit d = fitDrift(model, usable, x, fold, folds);
    FittedForm f;
    f.form = "drift";
    f.baseline = base.cvErrors;
    f.errors = d.cvErrors;
    for (size_t i = 0; i < usable.size(); ++i) {
        f.baselineFit.push_back(base.muAfter[i] - usable[i].muRef);
        f.errorsFit.push_back(d.muAfter[i] - usable[i].muRef);
    }
    f.params0 = 1;
    f.params1 = 2;
    return f;
}

void applyDrift(const friction::FrictionModel &model, std::vector<LoopRecord> *records, const Candidate &x,
                const std::vector<bool> &train)
{
    const Params p = fit(model, *records, x, train);
    for (size_t i = 0; i < records->size(); ++i)
        takeOutLengthFactor(&(*records)[i], std::clamp(p.a + p.b * xOf(x, i, p.xMean), kFactorMin, kFactorMax));
}

} // namespace icacam::host::loop
