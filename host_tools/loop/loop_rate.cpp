#include "host_tools/loop/loop_rate.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "host_tools/manifest.h"
#include "host_tools/number_text.h"

namespace icacam::host::loop {

namespace {

constexpr int kMinRecords = 4;
constexpr double kMinSpeedSpan = 2.0;

bool numberIn(const LoopRecord &r, const std::string &column, double *v)
{
    const auto it = r.columns.find(column);
    return it != r.columns.end() && parseNumber(it->second, v);
}

// The columns every usable record may carry, by name.
std::vector<std::string> columnNames(const std::vector<LoopRecord> &usable)
{
    std::vector<std::string> names;
    for (const LoopRecord &r : usable)
        for (const auto &[k, v] : r.columns)
            if (std::find(names.begin(), names.end(), k) == names.end()) names.push_back(k);
    std::sort(names.begin(), names.end());
    return names;
}

std::string speedColumnOf(const std::vector<LoopRecord> &usable, const std::vector<std::string> &names)
{
    for (const std::string &name : names) {
        if (!isRate(name)) continue;
        bool positive = true;
        for (const LoopRecord &r : usable) {
            double v;
            if (numberIn(r, name, &v) && !(v > 0)) positive = false;
        }
        if (positive) return name;
    }
    return "";
}

// Student's t at 97.5 % for ν degrees of freedom (tabulated to 10, then t ≈ z + 2.37/ν + 2.8/ν²,
// within 0.01 of the table there).
double studentT975(int nu)
{
    static const double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228};
    if (nu < 1) return NAN;
    if (nu <= 10) return kTable[nu - 1];
    return 1.96 + 2.37 / nu + 2.8 / (double(nu) * nu);
}

std::string f(const char *fmt, double v)
{
    return numberText(fmt, v);
}

} // namespace

RateSensitivity fitRateSensitivity(const std::vector<LoopRecord> &usable, const fe::UpsettingForce &force)
{
    RateSensitivity out;
    const std::vector<std::string> names = columnNames(usable);
    for (const char *c : {"force_kn", "peak_force_kn"})
        if (std::find(names.begin(), names.end(), c) != names.end()) out.forceColumn = c;
    if (out.forceColumn.empty()) return out;
    out.speedColumn = speedColumnOf(usable, names);
    // The materials as the ranking reads them (isMaterialGrouping): a column named so, or one
    // whose every level declares one n.
    for (const Candidate &c : buildCandidates(usable))
        if (isMaterialGrouping(usable, c)) {
            out.materialColumn = c.name;
            break;
        }
    struct Point {
        double x, y, v;
    };
    std::map<std::string, std::vector<Point>> byMaterial;
    std::map<std::string, int> seen;
    for (const LoopRecord &r : usable) {
        std::string material;
        if (!out.materialColumn.empty()) {
            const auto it = r.columns.find(out.materialColumn);
            material = it == r.columns.end() ? "" : it->second;
        } else {
            material = "n " + f("%.4g", r.n);
        }
        ++seen[material];
        double kN, v;
        if (out.speedColumn.empty() || !numberIn(r, out.forceColumn, &kN) || !(kN > 0) ||
            !numberIn(r, out.speedColumn, &v) || !(v > 0))
            continue;
        const double reduction = r.reduction > 0 ? r.reduction : 0.5;
        double feKn;
        if (!force.at(r.n, r.muRef, reduction, r.kMpa, r.d0Mm, &feKn) || !(feKn > 0)) {
            ++out.outsideFe;
            continue;
        }
        const double hMm = r.h0Mm * (1 - reduction);
        byMaterial[material].push_back({std::log(v / hMm), std::log(kN / feKn), v});
    }
    for (const auto &[material, count] : seen) {
        RateFit fit;
        fit.material = material;
        const std::vector<Point> &p = byMaterial[material];
        fit.records = int(p.size());
        if (p.empty()) {
            fit.why = out.speedColumn.empty() ? "no press speed recorded" : "no record with a force and a speed";
            out.materials.push_back(fit);
            continue;
        }
        fit.speedMin = fit.speedMax = p[0].v;
        double sx = 0, sy = 0;
        for (const Point &q : p) {
            fit.speedMin = std::min(fit.speedMin, q.v), fit.speedMax = std::max(fit.speedMax, q.v);
            sx += q.x, sy += q.y;
        }
        const double k = double(p.size()), mx = sx / k, my = sy / k;
        double sxx = 0, sxy = 0;
        for (const Point &q : p) sxx += (q.x - mx) * (q.x - mx), sxy += (q.x - mx) * (q.y - my);
        if (fit.records < kMinRecords || fit.speedMax < kMinSpeedSpan * fit.speedMin || !(sxx > 0)) {
            fit.why = fit.records < kMinRecords ? "fewer than 4 records with a force" : "speeds within 2:1";
            out.materials.push_back(fit);
            continue;
        }
        fit.m = sxy / sxx;
        const double a = my - fit.m * mx; // ln(F/F_FE) at ln ε̇ = 0: K at 1 /s over the declared K
        double sse = 0;
        for (const Point &q : p) sse += std::pow(q.y - a - fit.m * q.x, 2);
        const double s2 = sse / (k - 2);
        fit.scatter = std::sqrt(sse / k);
        fit.mSigma = std::sqrt(s2 / sxx);
        fit.coverage = studentT975(fit.records - 2);
        fit.kRatio = std::exp(a);
        fit.kRatioSigma = fit.kRatio * std::sqrt(s2 * (1 / k + mx * mx / sxx));
        fit.fitted = true;
        out.materials.push_back(fit);
    }
    return out;
}

void writeRateSection(std::ostream &md, const RateSensitivity &rate)
{
    if (rate.forceColumn.empty()) return;
    md << "\n## Rate sensitivity from the press's force\n\n"
          "u does not move with the press speed under a rate-sensitive flow curve (every stress scales by the "
          "same factor, friction with the pressure): the speed shows in the force. Per material, ln of `"
       << rate.forceColumn
       << "` over the FE's rate-independent force at the record's n, μ_ref and height against ln ε̇ = ln(`"
       << (rate.speedColumn.empty() ? std::string("—") : rate.speedColumn)
       << "` / h_final): the slope is m, the intercept K at 1 /s over the declared K.\n\n"
          "| material | records | speeds, mm/s | m | U (95 %, k from Student's t) | K(1 /s) / K declared | scatter of "
          "ln F |\n"
          "|---|---|---|---|---|---|---|\n";
    for (const RateFit &r : rate.materials) {
        md << "| " << r.material << " | " << r.records << " | ";
        if (r.records > 0) md << f("%.2f", r.speedMin) << "–" << f("%.2f", r.speedMax);
        if (!r.fitted) {
            md << " | — | — | — | " << r.why << " |\n";
            continue;
        }
        md << " | " << f("%.3f", r.m) << " | " << f("%.3f", r.coverage * r.mSigma) << " (k " << f("%.2f", r.coverage)
           << ") | " << f("%.3f", r.kRatio) << " ± " << f("%.3f", r.coverage * r.kRatioSigma) << " | "
           << f("%.3f", r.scatter) << " |\n";
    }
    if (rate.outsideFe > 0)
        md << "\n"
           << rate.outsideFe << " record(s) outside the FE base's n, μ or reductions, or without k_mpa: not used.\n";
}

void writeRateCsv(const std::string &path, const RateSensitivity &rate)
{
    if (rate.forceColumn.empty()) return;
    std::ofstream csv(path);
    csv << "material,records,speed_min_mm_s,speed_max_mm_s,m,m_sigma,coverage,k_ratio,k_ratio_sigma,scatter,fitted,"
           "why\n";
    for (const RateFit &r : rate.materials)
        csv << r.material << ',' << r.records << ',' << f("%.4g", r.speedMin) << ',' << f("%.4g", r.speedMax) << ','
            << f("%.5f", r.m) << ',' << f("%.5f", r.mSigma) << ',' << f("%.3f", r.coverage) << ','
            << f("%.5f", r.kRatio) << ',' << f("%.5f", r.kRatioSigma) << ',' << f("%.5f", r.scatter) << ','
            << (r.fitted ? 1 : 0) << ',' << r.why << '\n';
}

} // namespace icacam::host::loop
