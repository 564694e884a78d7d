#include "host_tools/score_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace icacam::host {

namespace {

ReadingSide side(const ManifestRow *r, double muTrue, const ScoreOptions &opt, RunCounts *counts)
{
    ReadingSide s;
    if (!r) return s;
    s.present = true;
    s.status = r->get("status");
    s.mu = r->get("mu");
    s.flags = r->get("flags");
    double mu = 0;
    if (s.status == "error" || !parseNumber(s.mu, &mu) || !std::isfinite(muTrue)) return s;
    s.dmu = mu - muTrue;
    s.right = isRight(s.dmu, muTrue, opt);
    ++counts->measured;
    counts->right += s.right;
    if (s.status == "ok") (s.right ? counts->okRight : counts->silentWrong) += 1;
    return s;
}

std::string sideText(const ReadingSide &s)
{
    if (!s.present) return "(no row)";
    char buf[64];
    if (s.status == "error" || s.mu.empty()) return s.status;
    std::snprintf(buf, sizeof buf, "%-4s %+.4f %s", s.status.c_str(), s.dmu,
                  s.right            ? "right"
                  : s.status == "ok" ? "silent wrong"
                                     : "wrong");
    return std::string(buf) + (s.flags.empty() ? "" : " " + s.flags);
}

} // namespace

bool compareResults(const Manifest &before, const Manifest &after, const Manifest &truth, const ScoreOptions &opt,
                    ComparisonReport *out, std::string *error)
{
    *out = {};
    for (const auto &[name, m] : {std::pair<const char *, const Manifest *>{"before", &before}, {"after", &after}})
        for (const char *c : {"id", "status", "mu"})
            if (!m->hasColumn(c)) {
                *error = std::string(name) + ": no '" + c + "' column";
                return false;
            }
    for (const char *c : {"id", "mu"})
        if (!truth.hasColumn(c)) {
            *error = std::string("truth: no '") + c + "' column";
            return false;
        }
    std::map<std::string, const ManifestRow *> was, now;
    for (const ManifestRow &r : before.rows) was[r.get("id")] = &r;
    for (const ManifestRow &r : after.rows) now[r.get("id")] = &r;
    for (const ManifestRow &t : truth.rows) {
        const std::string id = t.get("id");
        double muTrue = NAN;
        parseNumber(t.get("mu"), &muTrue);
        ++out->records;
        const auto b = was.find(id), a = now.find(id);
        ReadingChange c;
        c.id = id;
        c.before = side(b == was.end() ? nullptr : b->second, muTrue, opt, &out->before);
        c.after = side(a == now.end() ? nullptr : a->second, muTrue, opt, &out->after);
        if (c.before.present != c.after.present || c.before.status != c.after.status || c.before.mu != c.after.mu ||
            c.before.flags != c.after.flags)
            out->changed.push_back(c);
    }
    return true;
}

std::string formatComparison(const ComparisonReport &r)
{
    std::string s;
    char line[160];
    std::snprintf(line, sizeof line, "%zu of %d readings differ (status, mu or flags)\n", r.changed.size(), r.records);
    s += line;
    for (const ReadingChange &c : r.changed) {
        std::snprintf(line, sizeof line, "  %-16s ", c.id.c_str());
        s += line + sideText(c.before) + "\n  " + std::string(17, ' ') + "-> " + sideText(c.after) + "\n";
    }
    s += "         measured  right  ok on right  silent wrong\n";
    for (const auto &[name, n] :
         {std::pair<const char *, const RunCounts *>{"before", &r.before}, {"after", &r.after}}) {
        std::snprintf(line, sizeof line, "%-8s %9d %6d %12d %13d\n", name, n->measured, n->right, n->okRight,
                      n->silentWrong);
        s += line;
    }
    return s;
}

} // namespace icacam::host
