#include "host_tools/loop/loop_analysis.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "host_tools/linear_system.h"
#include "host_tools/loop/loop_drift.h"
#include "host_tools/loop/loop_fit.h"
#include "host_tools/loop/loop_influence.h"
#include "host_tools/manifest.h"

namespace icacam::host::loop {

using namespace fit;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

namespace fit {

double normalUpperQuantile(double p) // x with P(Z > x) = p
{
    double lo = -38, hi = 38;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (0.5 * std::erfc(mid / std::sqrt(2.0)) > p)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace fit

namespace {

// Regularised incomplete beta I_x(a, b) (continued fraction, Lentz).
double incompleteBeta(double a, double b, double x)
{
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    if (x > (a + 1) / (a + b + 2)) return 1 - incompleteBeta(b, a, 1 - x);
    const double lnFront = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    if (std::fabs(d) < 1e-300) d = 1e-300;
    d = 1 / d;
    double f = d;
    for (int m = 1; m < 300; ++m) {
        for (int half = 0; half < 2; ++half) {
            const double num = half == 0 ? m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m))
                                         : -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
            d = 1 + num * d;
            if (std::fabs(d) < 1e-300) d = 1e-300;
            c = 1 + num / c;
            if (std::fabs(c) < 1e-300) c = 1e-300;
            d = 1 / d;
            f *= d * c;
            if (half == 1 && std::fabs(d * c - 1) < 1e-14) return std::exp(lnFront) * f / a;
        }
    }
    return std::exp(lnFront) * f / a;
}

} // namespace

namespace fit {

// Nested-model F test of a candidate's in-sample fit against its form's baseline, as the
// normal z of its p-value (capped where the p-value underflows).
double nestedZ(double sse0, int p0, double sse1, int p1, size_t n)
{
    const int df1 = p1 - p0, df2 = int(n) - p1;
    if (df1 < 1 || df2 < 1 || !(sse1 > 0)) return 0;
    const double f = std::max(0.0, (sse0 - sse1) / df1) / (sse1 / df2);
    const double p = incompleteBeta(0.5 * df2, 0.5 * df1, df2 / (df2 + df1 * f)); // P(F' > f)
    return p < 1e-300 ? 37.0 : normalUpperQuantile(std::min(p, 0.5));
}

} // namespace fit

namespace {

double sumSquares(const std::vector<double> &v)
{
    double s = 0;
    for (double x : v) s += x * x;
    return s;
}

double mean(const std::vector<double> &v)
{
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0 : s / double(v.size());
}

// Features of one record for a candidate in a form. mu form: [1] (baseline), [1, x]
// (numeric), one-hot levels (categorical). scale form (g = dμ/du · u): [1, g] (baseline: an
// offset and a global scale), [1, g, g·x] (numeric), [1, g·one-hot] (categorical). Every
// model contains its form's baseline, so a candidate's gain is what its values add. An
// interaction is a slope in one level, the one whose slope explains the training records
// best: [1, (g,) (g·)x·1{level = acting}], with commonSlope also [(g·)x] in every level.
struct Design {
    const Candidate *c;
    const std::vector<double> *g;
    std::vector<std::string> levels; // categorical levels seen in training
    std::vector<double> xMean;       // numeric: training mean (missing values take it)
    std::string acting;              // interaction: the level with the slope
    bool commonSlope = false;        // interaction: a slope common to every level beside it

    size_t size() const
    {
        if (!c) return g ? 2 : 1;
        if (c->kind == "categorical") return g ? 1 + levels.size() : levels.size();
        if (c->kind == "interaction") return (g ? 2 : 1) + (commonSlope ? 2 : 1);
        return g ? 3 : 2;
    }
    void row(size_t i, std::vector<double> *f) const
    {
        f->assign(size(), 0);
        if (c && c->kind == "interaction") {
            (*f)[0] = 1;
            if (g) (*f)[1] = (*g)[i];
            const double x = std::isfinite(c->x[i]) ? c->x[i] - xMean[0] : 0;
            const double gx = g ? (*g)[i] * x : x;
            const size_t at = g ? 2 : 1;
            if (c->levels[i] == acting) (*f)[at] = gx;
            if (commonSlope) (*f)[at + 1] = gx;
            return;
        }
        if (c && c->kind == "categorical") {
            const auto it = std::lower_bound(levels.begin(), levels.end(), c->levels[i]);
            const bool seen = it != levels.end() && *it == c->levels[i];
            const size_t j = size_t(it - levels.begin());
            if (g) {
                (*f)[0] = 1;
                if (seen) (*f)[1 + j] = (*g)[i];
            } else if (seen) {
                (*f)[j] = 1;
            }
            return;
        }
        (*f)[0] = 1;
        if (g) (*f)[1] = (*g)[i];
        if (c) {
            const double x = std::isfinite(c->x[i]) ? c->x[i] - xMean[0] : 0;
            (*f)[g ? 2 : 1] = g ? (*g)[i] * x : x;
        }
    }
};

// Least squares of y in the design over the records where train(i); the training SSE.
template <typename Train>
bool solveDesign(const Design &d, const std::vector<double> &y, Train train, std::vector<double> *q, double *sse)
{
    const size_t p = d.size();
    std::vector<double> a(p * p, 0), b(p, 0), f;
    for (size_t i = 0; i < y.size(); ++i) {
        if (!train(i)) continue;
        d.row(i, &f);
        for (size_t r = 0; r < p; ++r) {
            b[r] += f[r] * y[i];
            for (size_t cc = 0; cc < p; ++cc) a[r * p + cc] += f[r] * f[cc];
        }
    }
    double tr = 0;
    for (size_t r = 0; r < p; ++r) tr += a[r * p + r];
    for (size_t r = 0; r < p; ++r) a[r * p + r] += 1e-10 * tr / double(p) + 1e-300; // degenerate columns
    if (!solveLinearSystem(a, b, q)) return false;
    *sse = 0;
    for (size_t i = 0; i < y.size(); ++i) {
        if (!train(i)) continue;
        d.row(i, &f);
        double v = 0;
        for (size_t r = 0; r < p; ++r) v += f[r] * (*q)[r];
        *sse += (y[i] - v) * (y[i] - v);
    }
    return true;
}

// Fits the candidate (nullptr: the baseline) on the records with fold != k and predicts those
// with fold == k (every record with predictAll). k < 0: fit on all and predict all. sens: the
// scale form.
void fitPredict(const Candidate *c, const std::vector<double> &y, const std::vector<int> &fold, int k,
                std::vector<double> *pred, const std::vector<double> *sens = nullptr, bool predictAll = false,
                bool commonSlope = false)
{
    const size_t n = y.size();
    auto train = [&](size_t i) { return k < 0 || fold[i] != k; };
    Design d{c, sens, {}, {0}, {}, commonSlope};
    double sy = 0;
    int cnt = 0;
    for (size_t i = 0; i < n; ++i)
        if (train(i)) {
            sy += y[i];
            ++cnt;
        }
    const double my = cnt ? sy / cnt : 0;
    if (c && (c->kind == "categorical" || c->kind == "interaction")) {
        std::set<std::string> lv;
        for (size_t i = 0; i < n; ++i)
            if (train(i)) lv.insert(c->levels[i]);
        d.levels.assign(lv.begin(), lv.end());
    }
    if (c && c->kind != "categorical") {
        double sx = 0;
        int nx = 0;
        for (size_t i = 0; i < n; ++i)
            if (train(i) && std::isfinite(c->x[i])) {
                sx += c->x[i];
                ++nx;
            }
        d.xMean[0] = nx ? sx / nx : 0;
    }
    std::vector<double> q;
    double sse = 0;
    bool ok = false;
    if (c && c->kind == "interaction") {
        // The acting level: the one whose slope leaves the least of the training records. Each
        // fold chooses its own, so the held-out error carries the choice (and its family counts
        // one try per level).
        std::vector<double> qLevel;
        double best = INFINITY;
        for (const std::string &level : d.levels) {
            Design t = d;
            t.acting = level;
            if (solveDesign(t, y, train, &qLevel, &sse) && sse < best) best = sse, q = qLevel, d.acting = level;
        }
        ok = !q.empty();
    } else {
        ok = solveDesign(d, y, train, &q, &sse);
    }
    std::vector<double> f;
    const size_t p = d.size();
    for (size_t i = 0; i < n; ++i) {
        if (k >= 0 && fold[i] != k && !predictAll) continue;
        if (!ok) {
            (*pred)[i] = my;
            continue;
        }
        d.row(i, &f);
        double v = 0;
        for (size_t r = 0; r < p; ++r) v += f[r] * q[r];
        // An unseen level in the mu form has no feature: it takes the training mean.
        if (c && c->kind == "categorical" && !sens &&
            !std::binary_search(d.levels.begin(), d.levels.end(), c->levels[i]))
            v = my;
        (*pred)[i] = v;
    }
}

} // namespace

namespace fit {

std::vector<double> cvErrors(const Candidate *c, const std::vector<double> &y, const std::vector<int> &fold, int folds,
                             const std::vector<double> *sens)
{
    std::vector<double> pred(y.size(), 0);
    for (int k = 0; k < folds; ++k) fitPredict(c, y, fold, k, &pred, sens);
    for (size_t i = 0; i < y.size(); ++i) pred[i] = y[i] - pred[i];
    return pred;
}

} // namespace fit

namespace {

// Paired z of a − b (per-record differences of |held-out error|): > 0 when a's are larger.
double pairedZ(const std::vector<double> &a, const std::vector<double> &b)
{
    std::vector<double> d(a.size());
    for (size_t i = 0; i < a.size(); ++i) d[i] = std::fabs(a[i]) - std::fabs(b[i]);
    const double md = mean(d);
    double v = 0;
    for (double x : d) v += (x - md) * (x - md);
    const double se = d.size() > 1 ? std::sqrt(v / double(d.size() - 1) / double(d.size())) : 0;
    return se > 0 ? md / se : 0;
}

// The share of a numeric symptom's variance a candidate explains (numeric: a line; categorical:
// the level means), with the F test of that fit as a normal z.
double explainedShare(const Candidate &symptom, const Candidate &cause, double *z)
{
    std::vector<size_t> idx;
    for (size_t i = 0; i < symptom.x.size(); ++i)
        if (std::isfinite(symptom.x[i]) && (cause.kind == "categorical" || std::isfinite(cause.x[i]))) idx.push_back(i);
    *z = 0;
    if (idx.size() < 4) return 0;
    double my = 0;
    for (size_t i : idx) my += symptom.x[i];
    my /= double(idx.size());
    double sst = 0, sse = 0;
    int params = 2;
    if (cause.kind == "categorical") {
        std::map<std::string, std::pair<double, int>> sums;
        for (size_t i : idx) {
            sums[cause.levels[i]].first += symptom.x[i];
            sums[cause.levels[i]].second++;
        }
        for (size_t i : idx) {
            const auto &[sum, n] = sums[cause.levels[i]];
            sse += (symptom.x[i] - sum / n) * (symptom.x[i] - sum / n);
        }
        params = int(sums.size());
    } else {
        double mx = 0, sxx = 0, sxy = 0;
        for (size_t i : idx) mx += cause.x[i];
        mx /= double(idx.size());
        for (size_t i : idx) {
            sxx += (cause.x[i] - mx) * (cause.x[i] - mx);
            sxy += (cause.x[i] - mx) * (symptom.x[i] - my);
        }
        const double b = sxx > 0 ? sxy / sxx : 0;
        for (size_t i : idx) {
            const double r = symptom.x[i] - my - b * (cause.x[i] - mx);
            sse += r * r;
        }
    }
    for (size_t i : idx) sst += (symptom.x[i] - my) * (symptom.x[i] - my);
    if (!(sst > 0)) return 0;
    *z = nestedZ(sst, 1, sse, params, idx.size());
    return 1 - sse / sst;
}

} // namespace

namespace {

// A record's value of a candidate as a key (a level, or a number as written).
std::string keyOf(const Candidate &c, size_t i)
{
    if (c.kind == "categorical") return c.levels[i];
    if (c.kind == "interaction") return c.levels[i] + "|" + std::to_string(c.x[i]);
    return std::isfinite(c.x[i]) ? std::to_string(c.x[i]) : "";
}

size_t keyCount(const Candidate &c)
{
    return c.kind == "categorical" ? c.levels.size() : c.x.size();
}

// The share of records on which a's value follows from b's (the most common a per value of b).
double functionShare(const Candidate &a, const Candidate &b)
{
    const size_t n = std::min(keyCount(a), keyCount(b));
    std::map<std::string, std::map<std::string, int>> counts;
    for (size_t i = 0; i < n; ++i) ++counts[keyOf(b, i)][keyOf(a, i)];
    int agree = 0;
    for (const auto &[kb, as] : counts) {
        int most = 0;
        for (const auto &[ka, k] : as) most = std::max(most, k);
        agree += most;
    }
    return n ? double(agree) / double(n) : 0;
}

// A recorded numeric condition that varies within a material (press speed, temperature) as
// a slope in one material: an effect confined to one material (its lubricant's regime or its
// heating changing with speed, among others) is not read as that material. How friction and
// heating change with speed and temperature goes with a material (its lubricant pairing, its
// flow curve), so only material groupings get one. Declared properties of a level (n, K of a
// material: a function of some grouping), the reduction and a condition that orders the
// records in time (what moves along the run is the instrument's, a drift) are left out.
void addInteractions(const std::vector<LoopRecord> &usable, std::vector<Candidate> *out)
{
    std::vector<Candidate> added;
    for (const Candidate &x : *out) {
        if (x.kind != "numeric" || x.symptom || isReductionCandidate(x.name) || ordersInTime(x.name)) continue;
        bool declaredProperty = false;
        for (const Candidate &g : *out)
            if (g.kind == "categorical" && !g.symptom && functionShare(x, g) >= 0.95) declaredProperty = true;
        if (declaredProperty) continue;
        for (const Candidate &g : *out) {
            if (g.kind != "categorical" || g.symptom || !isMaterialGrouping(usable, g)) continue;
            Candidate c{x.name + "_by_" + g.name, "interaction", x.x, g.levels, false, x.logarithmic};
            added.push_back(std::move(c));
        }
    }
    out->insert(out->end(), added.begin(), added.end());
}

} // namespace

bool isMaterialGrouping(const std::vector<LoopRecord> &usable, const Candidate &g)
{
    if (g.kind != "categorical" || g.levels.size() != usable.size()) return false;
    // Named as a material: its records may declare n per batch, the shift is per material.
    std::string name = g.name;
    for (char &ch : name) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    for (const char *word : {"material", "alloy", "grade"})
        if (name.find(word) != std::string::npos) return true;
    std::map<std::string, std::set<long>> nPerLevel;
    std::set<long> all;
    for (size_t i = 0; i < usable.size(); ++i) {
        const long n = std::lround(usable[i].n * 1e4);
        nPerLevel[g.levels[i]].insert(n);
        all.insert(n);
    }
    for (const auto &[level, ns] : nPerLevel)
        if (ns.size() != 1) return false;
    return all.size() >= 2;
}

bool isSymptom(const std::string &name)
{
    if (name.rfind("diag_", 0) == 0 || name.rfind("device_", 0) == 0) return true;
    // What a measurement produces (a radii record set's radii, a device record's result).
    static const std::set<std::string> kMeasured = {"mu", "mu_sigma", "status", "flags", "message", "ms", "r_max_z"};
    if (kMeasured.count(name)) return true;
    // Named after a measured quantity: the quantity itself or anything derived from it.
    static const char *const kStems[] = {"r_inner", "r_outer", "r_bulge", "r_max", "u_mm", "u_px", "reduction_est"};
    for (const char *stem : kStems)
        if (name.find(stem) != std::string::npos) return true;
    return false;
}

bool isRate(const std::string &name)
{
    std::string word;
    for (size_t i = 0; i <= name.size(); ++i) {
        const char ch = i < name.size() ? char(std::tolower(static_cast<unsigned char>(name[i]))) : '_';
        if (std::isalnum(static_cast<unsigned char>(ch))) {
            word += ch;
            continue;
        }
        if (word == "speed" || word == "rate" || word == "velocity") return true;
        word.clear();
    }
    return false;
}

bool isReductionCandidate(const std::string &name)
{
    return name == "reduction" || name == "h_final_mm" || name == "diag_reduction_est";
}

bool passesSingleComparison(const RankedCandidate &c, const RankingOptions &opt)
{
    return !c.carried && c.gain > 0 && c.z > normalUpperQuantile(opt.alpha) &&
           c.gain >= opt.minRelativeGain * c.cvRmsBefore;
}

double rms(const std::vector<double> &v)
{
    double s = 0;
    for (double x : v) s += x * x;
    return v.empty() ? 0 : std::sqrt(s / double(v.size()));
}

std::vector<int> foldAssignment(size_t count, int folds, uint32_t seed)
{
    std::vector<size_t> order(count);
    for (size_t i = 0; i < count; ++i) order[i] = i;
    std::mt19937 rng(seed);
    for (size_t i = count; i > 1; --i) { // Fisher–Yates with raw draws: the same on every platform
        const size_t j = size_t(rng() % uint32_t(i));
        std::swap(order[i - 1], order[j]);
    }
    std::vector<int> fold(count, 0);
    for (size_t i = 0; i < count; ++i) fold[order[i]] = int(i % size_t(std::max(folds, 1)));
    return fold;
}

std::vector<Candidate> buildCandidates(const std::vector<LoopRecord> &usable)
{
    std::vector<Candidate> out;
    if (usable.empty()) return out;
    // The press's force measures the flow stress, not the ring: it gives m (loop_rate.h).
    static const std::set<std::string> kSkip = {"id", "image", "mu_ref", "calibration", "force_kn", "peak_force_kn"};
    std::set<std::string> names;
    for (const LoopRecord &r : usable)
        for (const auto &[k, v] : r.columns) names.insert(k);
    for (const std::string &name : names) {
        if (kSkip.count(name)) continue;
        bool numeric = true, any = false;
        std::set<std::string> distinct;
        for (const LoopRecord &r : usable) {
            auto it = r.columns.find(name);
            const std::string v = it == r.columns.end() ? "" : it->second;
            distinct.insert(v);
            if (v.empty()) continue;
            any = true;
            double d;
            if (!parseNumber(v, &d)) numeric = false;
        }
        if (!any || distinct.size() < 2) continue; // constant: explains nothing
        Candidate c;
        c.name = name;
        c.symptom = isSymptom(name);
        bool dates = !numeric;
        for (const std::string &v : distinct) dates = dates && (v.empty() || std::isfinite(dayNumber(v)));
        if (numeric || dates) {
            // A date enters as its day number: a drift along the calendar is a line in it.
            c.kind = "numeric";
            for (const LoopRecord &r : usable) {
                auto it = r.columns.find(name);
                double d;
                c.x.push_back(it == r.columns.end()         ? kNaN
                              : dates                       ? dayNumber(it->second)
                              : parseNumber(it->second, &d) ? d
                                                            : kNaN);
            }
            bool positive = numeric;
            for (double v : c.x) positive = positive && !(v <= 0);
            if (positive && isRate(name)) {
                c.logarithmic = true;
                for (double &v : c.x) v = std::log(v);
            }
        } else {
            if (distinct.size() * 2 > usable.size()) continue; // an identifier, not a factor
            c.kind = "categorical";
            for (const LoopRecord &r : usable) {
                auto it = r.columns.find(name);
                c.levels.push_back(it == r.columns.end() ? "" : it->second);
            }
        }
        out.push_back(std::move(c));
    }
    bool anyReduction = false;
    for (const LoopRecord &r : usable) anyReduction = anyReduction || r.reduction >= 0;
    if (anyReduction) {
        Candidate c{"reduction", "numeric", {}, {}, false};
        for (const LoopRecord &r : usable) c.x.push_back(r.reduction >= 0 ? r.reduction : kNaN);
        out.push_back(std::move(c));
    }
    addInteractions(usable, &out);
    std::set<std::string> diag;
    for (const LoopRecord &r : usable)
        for (const auto &[k, v] : r.diagnostics) diag.insert(k);
    for (const std::string &name : diag) {
        Candidate c{name, "diagnostic", {}, {}, true};
        std::set<double> distinct;
        for (const LoopRecord &r : usable) {
            auto it = r.diagnostics.find(name);
            c.x.push_back(it == r.diagnostics.end() ? kNaN : it->second);
            if (std::isfinite(c.x.back())) distinct.insert(c.x.back());
        }
        if (distinct.size() >= 2) out.push_back(std::move(c));
    }
    return out;
}

double dayNumber(const std::string &text)
{
    int y = 0, m = 0, d = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%4d-%2d-%2d%c", &y, &m, &d, &tail) < 3 || m < 1 || m > 12 || d < 1 || d > 31 ||
        y < 1900)
        return kNaN;
    if (text.size() > 10 && tail != 'T' && tail != ' ') return kNaN;
    // Days since 1970-01-01 (civil calendar, Howard Hinnant's days_from_civil).
    y -= m <= 2;
    const int era = y / 400, yoe = y - era * 400;
    const int doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return double(era * 146097 + doe - 719468);
}

bool sameRecords(const Candidate &a, const Candidate &b)
{
    const size_t n = std::min(keyCount(a), keyCount(b));
    if (n == 0) return false;
    return functionShare(a, b) >= 0.95 && functionShare(b, a) >= 0.95;
}

std::vector<double> cvPredict(const Candidate &c, const std::vector<double> &residual, const std::vector<int> &fold,
                              int folds, const std::vector<double> *scaleSensitivity)
{
    std::vector<double> pred(residual.size(), 0);
    for (int k = 0; k < folds; ++k) fitPredict(&c, residual, fold, k, &pred, scaleSensitivity);
    return pred;
}

std::vector<double> predictFrom(const Candidate &c, const std::vector<double> &residual, const std::vector<int> &fold,
                                int k, const std::vector<double> *sensitivity)
{
    std::vector<double> pred(residual.size(), 0);
    fitPredict(&c, residual, fold, k, &pred, sensitivity, true);
    return pred;
}

namespace {

// The forms an effect can take, each with its baseline's held-out errors: an offset in μ, a
// relative scale of u (optics), an additive shift of u (a process that widens the ring:
// Δμ = dμ/du · Δu).
struct Form {
    const char *name;
    const std::vector<double> *sens;
    std::vector<double> e0;
};

std::vector<Form> linearForms(const std::vector<double> &y, const std::vector<int> &fold, int folds,
                              const std::vector<double> *scaleSensitivity, const std::vector<double> *uSensitivity)
{
    std::vector<Form> formList;
    formList.push_back({"mu", nullptr, cvErrors(nullptr, y, fold, folds)});
    if (scaleSensitivity)
        formList.push_back({"scale", scaleSensitivity, cvErrors(nullptr, y, fold, folds, scaleSensitivity)});
    if (uSensitivity) formList.push_back({"u", uSensitivity, cvErrors(nullptr, y, fold, folds, uSensitivity)});
    return formList;
}

} // namespace

namespace fit {

// In-sample sum of squares and parameter count of a linear model (nullptr: the baseline).
double inSample(const Candidate *c, const std::vector<double> &y, const std::vector<int> &fold,
                const std::vector<double> *sens, int *params, bool commonSlope)
{
    std::vector<double> pred(y.size(), 0);
    fitPredict(c, y, fold, -1, &pred, sens, false, commonSlope);
    for (size_t i = 0; i < y.size(); ++i) pred[i] = y[i] - pred[i];
    if (!c)
        *params = sens ? 2 : 1;
    else if (c->kind == "categorical")
        *params = int(std::set<std::string>(c->levels.begin(), c->levels.end()).size()) + (sens ? 1 : 0);
    else if (c->kind == "interaction")
        *params = (sens ? 2 : 1) + (commonSlope ? 2 : 1);
    else
        *params = sens ? 3 : 2;
    return sumSquares(pred);
}

} // namespace fit

namespace {

// Pearson r of a numeric candidate with the residual (for reading only).
double correlation(const Candidate &c, const std::vector<double> &y)
{
    double sx = 0, sy2 = 0, sxy = 0, mx = 0, myv = mean(y);
    int cnt = 0;
    for (size_t i = 0; i < y.size(); ++i)
        if (std::isfinite(c.x[i])) {
            mx += c.x[i];
            ++cnt;
        }
    mx = cnt ? mx / cnt : 0;
    for (size_t i = 0; i < y.size(); ++i) {
        if (!std::isfinite(c.x[i])) continue;
        sx += (c.x[i] - mx) * (c.x[i] - mx);
        sy2 += (y[i] - myv) * (y[i] - myv);
        sxy += (c.x[i] - mx) * (y[i] - myv);
    }
    return sx > 0 && sy2 > 0 ? sxy / std::sqrt(sx * sy2) : 0;
}

// What ranks one candidate: its held-out errors in its best form against that form's
// baseline, and the in-sample fits of the nested test.
struct FormScore {
    std::vector<double> e1;                  // held-out errors with the candidate
    const std::vector<double> *e0 = nullptr; // held-out errors of the form's baseline
    std::string form = "mu";
    double sse0 = 0, sse1 = 0;
    int p0 = 0, p1 = 0;
    double witnessZ = kNaN; // FittedForm::witnessZ of the form taken
    bool better(const std::vector<double> &base, const std::vector<double> &with) const
    {
        return rms(base) - rms(with) > rms(*e0) - rms(e1);
    }
};

// The candidate's best linear form (mu, scale or u): the regression patch.
FormScore bestLinearForm(const Candidate &c, const std::vector<double> &y, const std::vector<int> &fold, int folds,
                         const std::vector<Form> &formList)
{
    FormScore f;
    f.e1 = cvErrors(&c, y, fold, folds);
    f.e0 = &formList[0].e0;
    const std::vector<double> *formSens = nullptr;
    for (size_t fi = 1; fi < formList.size(); ++fi) {
        std::vector<double> e2 = cvErrors(&c, y, fold, folds, formList[fi].sens);
        if (f.better(formList[fi].e0, e2)) {
            f.e1 = std::move(e2);
            f.e0 = &formList[fi].e0;
            f.form = formList[fi].name;
            formSens = formList[fi].sens;
        }
    }
    // The chosen form's nested test: the in-sample fit against the form's baseline.
    f.sse0 = inSample(nullptr, y, fold, formSens, &f.p0);
    f.sse1 = inSample(&c, y, fold, formSens, &f.p1);
    return f;
}

// A physical form in place of the linear one where it explains more over its baseline: the
// change in μ a physical model makes (form "fe"), or a form fitted elsewhere (a length factor
// or an n per group).
void tryPhysicalForms(const Candidate &c, const std::vector<double> &y, const std::vector<int> &fold, int folds,
                      const std::vector<Form> &formList,
                      const std::map<std::string, std::vector<double>> *physicalForms,
                      const std::map<std::string, FittedForm> *fittedForms, double minRelativeGain, FormScore *f)
{
    if (physicalForms) {
        const auto it = physicalForms->find(c.name);
        if (it != physicalForms->end() && it->second.size() == y.size()) {
            std::vector<double> e2 = cvErrors(nullptr, y, fold, folds, &it->second);
            if (f->better(formList[0].e0, e2)) {
                f->e1 = std::move(e2);
                f->e0 = &formList[0].e0;
                f->form = "fe";
                f->sse0 = inSample(nullptr, y, fold, nullptr, &f->p0);
                f->sse1 = inSample(nullptr, y, fold, &it->second, &f->p1);
            }
        }
    }
    if (fittedForms) {
        const auto it = fittedForms->find(c.name);
        // A form an independent witness supports is read wherever μ's held-out error confirms
        // it (by the minimum relative gain), also where a free regression fits μ a little better.
        const auto confirmed = [&](const FittedForm &w) {
            return std::isfinite(w.witnessZ) && rms(w.baseline) - rms(w.errors) >= minRelativeGain * rms(w.baseline);
        };
        if (it != fittedForms->end() && it->second.errors.size() == y.size() &&
            (f->better(it->second.baseline, it->second.errors) || confirmed(it->second))) {
            f->e1 = it->second.errors;
            f->e0 = &it->second.baseline;
            f->form = it->second.form;
            f->sse0 = sumSquares(it->second.baselineFit), f->p0 = it->second.params0;
            f->sse1 = sumSquares(it->second.errorsFit), f->p1 = it->second.params1;
            f->witnessZ = it->second.witnessZ;
        }
    }
}

// A symptom never outranks a cause it cannot be told from: each significant recorded
// condition moves ahead of every symptom directly above it whose held-out |errors| are not
// significantly smaller than its own (paired z < 2). It stops at a better cause or at a
// symptom that is significantly better (that symptom sees something the cause does not).
void putCausesBeforeSymptoms(std::vector<RankedCandidate> &out, const std::vector<std::vector<double>> &errors,
                             std::vector<size_t> *order)
{
    std::vector<size_t> &o = *order;
    for (size_t k = 1; k < o.size(); ++k) {
        RankedCandidate &c = out[o[k]];
        if (c.symptom || !c.significant) continue;
        size_t pos = k;
        while (pos > 0 && out[o[pos - 1]].symptom && pairedZ(errors[o[k]], errors[o[pos - 1]]) < 2.0) --pos;
        if (pos == k) continue;
        for (size_t j = pos; j < k; ++j) c.preferredOver.push_back(out[o[j]].name);
        const size_t moved = o[k];
        o.erase(o.begin() + long(k));
        o.insert(o.begin() + long(pos), moved);
    }
}

// A significant symptom still leads: it established that there is an effect, and the
// question left is its name. A cause not significant on its own comes first when it
// explains the residual as well as every symptom above it (paired z < 2), passes the test
// of a single comparison (z above the one-sided α quantile, the same minimum gain), and
// explains the leading symptom itself (the symptom's own values, F test at α): of such
// causes, the one that explains the symptom best (R²). A chance correlate of the residual
// rarely also explains the measurement; the cause that moved the geometry does.
void nameTheLeadingSymptomsCause(const std::vector<Candidate> &candidates, std::vector<RankedCandidate> &out,
                                 const std::vector<std::vector<double>> &errors, const RankingOptions &opt,
                                 std::vector<size_t> *order)
{
    std::vector<size_t> &o = *order;
    size_t lead = o.size(); // the first significant symptom, when no significant cause leads
    if (!o.empty() && !(out[o[0]].significant && !out[o[0]].symptom))
        for (size_t k = 0; k < o.size() && lead == o.size(); ++k)
            if (out[o[k]].symptom && out[o[k]].significant && candidates[o[k]].kind != "categorical") lead = k;
    if (lead == o.size()) return;
    const double zSingle = normalUpperQuantile(opt.alpha);
    size_t best = o.size();
    double bestR2 = -1;
    for (size_t k = 0; k < o.size(); ++k) {
        const RankedCandidate &c = out[o[k]];
        if (c.symptom || c.significant || c.kind == "interaction" || !passesSingleComparison(c, opt)) continue;
        bool told = pairedZ(errors[o[k]], errors[o[lead]]) >= 2.0;
        for (size_t j = 0; j < k && !told; ++j) told = out[o[j]].symptom && pairedZ(errors[o[k]], errors[o[j]]) >= 2.0;
        double zAssoc = 0;
        const double r2 = explainedShare(candidates[o[lead]], candidates[o[k]], &zAssoc);
        if (!told && zAssoc > zSingle && r2 > bestR2) best = k, bestR2 = r2;
    }
    if (best == o.size()) return;
    RankedCandidate &c = out[o[best]];
    c.significant = c.viaSymptom = true;
    for (size_t j = 0; j < best; ++j)
        if (out[o[j]].symptom) c.preferredOver.push_back(out[o[j]].name);
    if (best < lead) c.preferredOver.push_back(out[o[lead]].name);
    const size_t moved = o[best];
    o.erase(o.begin() + long(best));
    o.insert(o.begin(), moved);
}

// The effect added leads: the first significant recorded condition, else the first
// significant symptom. A symptom that explains the residual significantly better than that
// condition still sees more than it, and the next round looks at what the condition leaves;
// a candidate with a lower CV RMS that is not significant (a slope per level whose slopes do
// not differ) does not block it.
void putTheAddedEffectFirst(std::vector<RankedCandidate> &out, std::vector<size_t> *order)
{
    std::vector<size_t> &o = *order;
    size_t k = 0;
    while (k < o.size() && !(out[o[k]].significant && !out[o[k]].symptom)) ++k;
    if (k == o.size())
        for (k = 0; k < o.size() && !out[o[k]].significant;) ++k;
    if (k == 0 || k == o.size()) return;
    RankedCandidate &c = out[o[k]];
    for (size_t j = 0; j < k; ++j)
        if (out[o[j]].symptom && out[o[j]].significant && !c.symptom) c.aheadOfBetter.push_back(out[o[j]].name);
    const size_t moved = o[k];
    o.erase(o.begin() + long(k));
    o.insert(o.begin(), moved);
}

// A length factor the outline witnesses is taken out first where it is significant: it is
// read from the geometry, not from μ, and a material's n or a process fitted to μ before it
// would take up part of that camera's error (each material's records include its images).
void putTheWitnessedScaleFirst(std::vector<RankedCandidate> &out, std::vector<size_t> *order)
{
    std::vector<size_t> &o = *order;
    if (o.empty() || !out[o[0]].significant || out[o[0]].witnessed) return;
    for (size_t k = 1; k < o.size(); ++k) {
        RankedCandidate &c = out[o[k]];
        if (!c.witnessed || !c.significant || c.symptom || c.carried) continue;
        const size_t moved = o[k];
        o.erase(o.begin() + long(k));
        o.insert(o.begin(), moved);
        return;
    }
}

// A slope in one level counts only where it differs from the others': the acting level's
// slope beside one common slope, against the common slope alone in the same form, F test
// at the level of a single comparison. The slope is already significant over the family;
// what is left is which of its two forms reads it (a closed test).
bool slopesDiffer(const Candidate &c, const std::vector<double> &y, const std::vector<int> &fold,
                  const std::vector<Form> &formList, const FormScore &f, double zNeeded)
{
    const std::vector<double> *sens = nullptr;
    for (const Form &form : formList)
        if (f.form == form.name) sens = form.sens;
    const Candidate common{c.name, "numeric", c.x, {}, false, c.logarithmic};
    int p0 = 0, p1 = 0;
    const double sse0 = inSample(&common, y, fold, sens, &p0), sse1 = inSample(&c, y, fold, sens, &p1, true);
    return nestedZ(sse0, p0, sse1, p1, y.size()) > zNeeded;
}

// A candidate significant over the family must stay so without its most influential records
// (loop_influence.h): one odd image with a large residual and an extreme value makes a
// regression in that value significant on its own. Its linear forms and the form `fe` are
// checked; a grouping's or a drift's physical form is fitted elsewhere, and a level of fewer
// than three records is not fitted there. A slope in one material is not checked: it is
// fitted on that material's records alone (10–20 of 60), where a record at either end of its
// speeds can carry much of a true slope (on the hidden-effect sets the check turned down a
// true speed within one material, z 4.0, 1.8 without one of its slowest records).
void checkCarried(const Candidate &c, const std::vector<double> &y, const std::vector<int> &fold, int folds,
                  const std::vector<Form> &formList, const std::map<std::string, std::vector<double>> *physicalForms,
                  const FormScore &f, const RankingOptions &opt, RankedCandidate *r)
{
    if (c.kind == "interaction") return;
    const Candidate *cand = &c;
    const std::vector<double> *sens = nullptr, *baseSens = nullptr;
    if (f.form == "fe") {
        cand = nullptr;
        sens = &physicalForms->at(c.name);
    } else {
        bool linear = false;
        for (const Form &form : formList)
            if (f.form == form.name) linear = true, sens = baseSens = form.sens;
        if (!linear) return;
    }
    const InfluenceCheck check =
        checkInfluence(cand, sens, baseSens, y, fold, folds, influentialCount(y.size(), opt.influentialShare),
                       normalUpperQuantile(opt.alpha));
    r->influential = check.records;
    r->zWithout = check.z, r->gainWithout = check.gain, r->cvRmsAfterWithout = check.cvRmsAfter;
    if (check.stands) return;
    r->carried = true;
    r->significant = false;
}

// The tries a candidate makes per form: one, or for a slope in one level one per level (the
// acting level is chosen among them).
size_t triesOf(const Candidate &c)
{
    if (c.kind != "interaction") return 1;
    return std::max<size_t>(std::set<std::string>(c.levels.begin(), c.levels.end()).size(), 1);
}

// The significant recorded conditions the leading one cannot be told from: they group the
// records the same way (each a function of the other on 95 % of them) and their held-out
// errors are not significantly larger (paired z < 2). Two columns that say the same thing
// (a camera always fitted with one lens) cannot be separated by these records.
void nameInseparable(const std::vector<Candidate> &candidates, const std::vector<std::vector<double>> &errors,
                     const std::vector<size_t> &order, std::vector<RankedCandidate> *out)
{
    if (order.empty()) return;
    RankedCandidate &lead = (*out)[order[0]];
    if (!lead.significant || lead.symptom) return;
    for (size_t k = 1; k < order.size(); ++k) {
        const size_t j = order[k];
        const RankedCandidate &other = (*out)[j];
        if (other.symptom || !other.significant) continue;
        if (pairedZ(errors[j], errors[order[0]]) < 2.0 && sameRecords(candidates[order[0]], candidates[j]))
            lead.inseparable.push_back(other.name);
    }
}

} // namespace

std::vector<RankedCandidate> rankCandidates(const std::vector<Candidate> &candidates, const std::vector<double> &y,
                                            const RankingOptions &opt, const std::vector<double> *scaleSensitivity,
                                            const std::vector<double> *uSensitivity,
                                            const std::map<std::string, std::vector<double>> *physicalForms,
                                            const std::map<std::string, FittedForm> *fittedForms)
{
    std::vector<RankedCandidate> out;
    if (y.size() < 4) return out;
    const int folds = std::clamp(opt.folds, 2, int(y.size()));
    const std::vector<int> fold = foldAssignment(y.size(), folds, opt.seed);
    const std::vector<Form> formList = linearForms(y, fold, folds, scaleSensitivity, uSensitivity);
    size_t tries = (physicalForms ? physicalForms->size() : 0) + (fittedForms ? fittedForms->size() : 0);
    for (const Candidate &c : candidates) tries += triesOf(c) * formList.size();
    const double zCrit = normalUpperQuantile(opt.alpha / double(std::max<size_t>(tries, 1)));
    std::vector<std::vector<double>> errors; // held-out errors per candidate, as in out
    for (const Candidate &c : candidates) {
        FormScore f = bestLinearForm(c, y, fold, folds, formList);
        RankedCandidate r;
        r.patchForm = f.form;
        r.cvRmsPatch = rms(f.e1);
        tryPhysicalForms(c, y, fold, folds, formList, physicalForms, fittedForms, opt.minRelativeGain, &f);
        r.name = c.name;
        r.kind = c.kind;
        r.symptom = c.symptom;
        r.form = f.form;
        r.cvRmsBefore = rms(*f.e0);
        r.cvRmsAfter = rms(f.e1);
        r.gain = r.cvRmsBefore - r.cvRmsAfter;
        r.z = nestedZ(f.sse0, f.p0, f.sse1, f.p1, y.size());
        if (std::isfinite(f.witnessZ)) r.z = f.witnessZ, r.witnessed = true;
        if (fittedForms)
            if (const auto w = fittedForms->find(c.name); w != fittedForms->end()) r.witnessZ = w->second.witnessZ;
        if (c.kind != "categorical") r.correlation = correlation(c, y);
        r.zFamily = zCrit;
        r.significant = r.gain > 0 && r.z > zCrit && r.gain >= opt.minRelativeGain * r.cvRmsBefore;
        if (c.kind == "interaction" && r.significant)
            r.significant = slopesDiffer(c, y, fold, formList, f, normalUpperQuantile(opt.alpha));
        if (r.significant) checkCarried(c, y, fold, folds, formList, physicalForms, f, opt, &r);
        out.push_back(r);
        errors.push_back(std::move(f.e1));
    }
    std::vector<size_t> order(out.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return out[a].cvRmsAfter < out[b].cvRmsAfter; });
    putCausesBeforeSymptoms(out, errors, &order);
    nameTheLeadingSymptomsCause(candidates, out, errors, opt, &order);
    putTheAddedEffectFirst(out, &order);
    putTheWitnessedScaleFirst(out, &order);
    // The measurements that point to each significant cause: the significant symptoms, best
    // first (a symptom answers to the cause; alone it does not name it).
    for (size_t k = 0; k < order.size(); ++k) {
        RankedCandidate &c = out[order[k]];
        if (c.symptom || !c.significant) continue;
        for (size_t j : order)
            if (out[j].symptom && out[j].significant) c.pointedBy.push_back(out[j].name);
    }
    nameInseparable(candidates, errors, order, &out);
    std::vector<RankedCandidate> ranked;
    for (size_t i : order) ranked.push_back(std::move(out[i]));
    return ranked;
}

} // namespace icacam::host::loop
