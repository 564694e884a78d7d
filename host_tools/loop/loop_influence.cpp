#include "host_tools/loop/loop_influence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "host_tools/loop/loop_fit.h"

namespace icacam::host::loop {

namespace {

template <typename T> std::vector<T> kept(const std::vector<T> &v, const std::vector<bool> &keep)
{
    std::vector<T> out;
    if (v.size() != keep.size()) return v; // not per record (an empty column)
    for (size_t i = 0; i < v.size(); ++i)
        if (keep[i]) out.push_back(v[i]);
    return out;
}

// The records where keep holds, as the form's fits see them.
struct Kept {
    Candidate c;
    std::vector<double> y, sens, baseSens;
    std::vector<int> fold;
    const Candidate *cand = nullptr;
    const std::vector<double> *s = nullptr, *b = nullptr;

    Kept(const Candidate *c0, const std::vector<double> *sens0, const std::vector<double> *base0,
         const std::vector<double> &y0, const std::vector<int> &fold0, const std::vector<bool> &keep)
            : y(kept(y0, keep)), fold(kept(fold0, keep))
    {
        if (c0) {
            c = *c0;
            c.x = kept(c0->x, keep);
            c.levels = kept(c0->levels, keep);
            cand = &c;
        }
        if (sens0) sens = kept(*sens0, keep), s = &sens;
        if (base0) baseSens = kept(*base0, keep), b = &baseSens;
    }
    double z() const
    {
        int p0 = 0, p1 = 0;
        const double sse0 = fit::inSample(nullptr, y, fold, b, &p0);
        const double sse1 = fit::inSample(cand, y, fold, s, &p1);
        return fit::nestedZ(sse0, p0, sse1, p1, y.size());
    }
};

std::string number(double v, const char *fmt)
{
    char b[48];
    std::snprintf(b, sizeof b, fmt, v);
    return b;
}

double median(std::vector<double> v)
{
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// How far a record's value lies from the other records' in robust units: |x − median| over
// 1.4826 · MAD; where most records share one value (MAD 0), any other value is far.
double robustDistance(const std::vector<double> &all, double x)
{
    std::vector<double> v;
    for (double a : all)
        if (std::isfinite(a)) v.push_back(a);
    const double m = median(v);
    for (double &a : v) a = std::fabs(a - m);
    const double mad = 1.4826 * median(v);
    const double d = std::fabs(x - m);
    if (!(mad > 0)) return d > 0 ? std::numeric_limits<double>::infinity() : 0;
    return d / mad;
}

// A record's diagnostics at least this many robust standard deviations from the others' are
// named beside it: a value no ordinary scatter reaches.
constexpr double kOutlying = 5.0;
constexpr size_t kOutlyingNamed = 4;

} // namespace

size_t influentialCount(size_t n, double share)
{
    return std::max<size_t>(1, size_t(std::floor(share * double(n) + 0.5)));
}

InfluenceCheck checkInfluence(const Candidate *c, const std::vector<double> *sens, const std::vector<double> *baseSens,
                              const std::vector<double> &y, const std::vector<int> &fold, int folds, size_t count,
                              double zNeeded)
{
    InfluenceCheck out;
    const size_t n = y.size();
    std::vector<bool> keep(n, true);
    for (size_t step = 0; step < count && step + 4 < n; ++step) {
        size_t worst = n;
        double lowest = std::numeric_limits<double>::infinity();
        for (size_t i = 0; i < n; ++i) {
            if (!keep[i]) continue;
            keep[i] = false;
            const double z = Kept(c, sens, baseSens, y, fold, keep).z();
            keep[i] = true;
            if (z < lowest) lowest = z, worst = i;
        }
        if (worst == n) break;
        keep[worst] = false;
        out.records.push_back(worst);
    }
    const Kept left(c, sens, baseSens, y, fold, keep);
    out.z = left.z();
    out.cvRmsBefore = rms(fit::cvErrors(nullptr, left.y, left.fold, folds, left.b));
    out.cvRmsAfter = rms(fit::cvErrors(left.cand, left.y, left.fold, folds, left.s));
    out.gain = out.cvRmsBefore - out.cvRmsAfter;
    out.stands = out.z > zNeeded;
    return out;
}

RecordFinding recordFinding(const RankedCandidate &r, const Candidate *c, const std::vector<LoopRecord> &records,
                            const std::vector<double> &residual, int round, double zNeeded)
{
    RecordFinding f;
    f.candidate = r.name, f.form = r.form, f.round = round;
    f.z = r.z, f.zWithout = r.zWithout, f.zFamily = r.zFamily, f.zNeeded = zNeeded;
    f.cvRmsAfter = r.cvRmsAfter, f.cvRmsAfterWithout = r.cvRmsAfterWithout;
    f.gain = r.gain, f.gainWithout = r.gainWithout;
    for (size_t i : r.influential) {
        if (i >= records.size()) continue;
        const LoopRecord &rec = records[i];
        CarryingRecord cr;
        cr.id = rec.id;
        cr.residual = i < residual.size() ? residual[i] : 0;
        if (c && c->kind == "categorical" && i < c->levels.size())
            cr.value = c->levels[i];
        else if (c && i < c->x.size() && std::isfinite(c->x[i]))
            cr.value = number(c->logarithmic ? std::exp(c->x[i]) : c->x[i], "%.4g");
        cr.flags = rec.flags;
        std::vector<std::pair<double, std::pair<std::string, double>>> far;
        for (const auto &[name, value] : rec.diagnostics) {
            std::vector<double> all;
            for (const LoopRecord &o : records) {
                const auto it = o.diagnostics.find(name);
                if (it != o.diagnostics.end()) all.push_back(it->second);
            }
            const double d = robustDistance(all, value);
            if (d >= kOutlying) far.push_back({d, {name, value}});
        }
        std::stable_sort(far.begin(), far.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
        for (const auto &[d, named] : far) cr.outlying.push_back(named);
        if (cr.outlying.size() > kOutlyingNamed) cr.outlying.resize(kOutlyingNamed);
        f.records.push_back(std::move(cr));
    }
    return f;
}

std::string describe(const CarryingRecord &r, const std::string &candidate)
{
    std::string s = r.id + " (residual " + number(r.residual, "%+.4f");
    if (!r.value.empty()) s += ", " + candidate + " " + r.value;
    for (const auto &[name, value] : r.outlying)
        if (name != candidate) s += ", " + name + " " + number(value, "%.4g");
    if (!r.flags.empty()) s += ", flags " + r.flags;
    return s + ")";
}

} // namespace icacam::host::loop
