#include "host_tools/fe/fe_model_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "friction/fe_model.h"

namespace icacam::host::fe {

// The generated model between its grid points: each interior grid point left out in turn and
// predicted by the model's own interpolation (friction::feMuAlongU) from the rest — along u at
// its n (leave one μ out), and linearly in n between the neighbouring n (leave one n out, a
// gap twice the model's). Only resolved points (u > 0.02 mm) inside the rest's range count.
// This bounds the error between grid points, where the model is not exact.
void writeLeaveOneOut(std::ostream &md, const std::vector<FeRow> &rows)
{
    struct Stat {
        int count = 0;
        double sum = 0, worst = 0;
        std::string where;
        void add(double rel, const char *what)
        {
            ++count;
            sum += std::fabs(rel);
            if (std::fabs(rel) > worst) {
                worst = std::fabs(rel);
                where = what;
            }
        }
    };
    md << "\n## Between the grid points (leave one out)\n\n"
       << "Each interior grid point is left out and predicted by the model's interpolation from the rest: "
          "along u at its n (leave one μ out) and linearly in n between the neighbouring n (leave one n out: "
          "a gap twice the model's). |Δμ|/μ where u > 0.02 mm.\n\n"
       << "| reduction | one μ out: points | mean % | max % (at) | one n out: points | mean % | max % (at) |\n"
       << "|---|---|---|---|---|---|---|\n";
    Stat allMu, allN;
    for (int k = 6; k <= 12; ++k) {
        const double red = k * 0.05;
        const PointGrid pts = basePoints(rows, red);
        if (pts.empty()) continue;
        std::map<double, std::vector<const Point *>> byN; // μ order within each n (map order)
        for (const auto &[key, p] : pts) byN[p.n].push_back(&p);
        auto muAt = [](const std::vector<const Point *> &line, size_t skip, double u, bool *outside) {
            double us[friction::kMaxRowPoints], mus[friction::kMaxRowPoints];
            int c = 0;
            for (size_t j = 0; j < line.size() && c < friction::kMaxRowPoints; ++j)
                if (j != skip) {
                    us[c] = line[j]->u;
                    mus[c] = line[j]->mu;
                    ++c;
                }
            return friction::feMuAlongU(us, mus, c, u, outside);
        };
        Stat sMu, sN;
        char what[80];
        for (const auto &[n, line] : byN)
            for (size_t j = 1; j + 1 < line.size(); ++j) {
                if (line[j]->u <= 0.02) continue;
                bool out = false;
                const double mu = muAt(line, j, line[j]->u, &out);
                if (out) continue;
                std::snprintf(what, sizeof what, "n %g, μ %g", n, line[j]->mu);
                const double rel = (mu - line[j]->mu) / line[j]->mu;
                sMu.add(rel, what);
                allMu.add(rel, what);
            }
        std::vector<double> ns;
        for (const auto &[n, line] : byN) ns.push_back(n);
        for (size_t i = 1; i + 1 < ns.size(); ++i)
            for (const Point *p : byN[ns[i]]) {
                if (p->u <= 0.02) continue;
                bool out0 = false, out1 = false;
                const double m0 = muAt(byN[ns[i - 1]], size_t(-1), p->u, &out0);
                const double m1 = muAt(byN[ns[i + 1]], size_t(-1), p->u, &out1);
                if (out0 || out1) continue;
                const double w = (ns[i] - ns[i - 1]) / (ns[i + 1] - ns[i - 1]);
                const double rel = ((1 - w) * m0 + w * m1 - p->mu) / p->mu;
                std::snprintf(what, sizeof what, "n %g, μ %g", p->n, p->mu);
                sN.add(rel, what);
                allN.add(rel, what);
            }
        char b[300];
        std::snprintf(b, sizeof b, "| %ld %% | %d | %.1f | %.1f (%s) | %d | %.1f | %.1f (%s) |\n",
                      std::lround(100 * red), sMu.count, sMu.count ? 100 * sMu.sum / sMu.count : 0.0, 100 * sMu.worst,
                      sMu.where.c_str(), sN.count, sN.count ? 100 * sN.sum / sN.count : 0.0, 100 * sN.worst,
                      sN.where.c_str());
        md << b;
    }
    char b[300];
    std::snprintf(b, sizeof b,
                  "\nAll reductions: one μ out %d points, mean %.1f %%, max %.1f %%; one n out %d points, "
                  "mean %.1f %%, max %.1f %%.\n",
                  allMu.count, allMu.count ? 100 * allMu.sum / allMu.count : 0.0, 100 * allMu.worst, allN.count,
                  allN.count ? 100 * allN.sum / allN.count : 0.0, 100 * allN.worst);
    md << b;
}

// The model against every run it averages (each K of the factorial on its own): μ read back
// at each run's u along its n, through the model's interpolation of the averaged points. At a
// grid point the model is the mean over K, so this is the K spread seen in μ.
void writeRunResiduals(std::ostream &md, const std::vector<FeRow> &rows)
{
    md << "\n## The model against each run it averages\n\n";
    if (const BaseChoice b = chooseBase(rows, 0.5); b.kAveraged.size() <= 1) {
        char b1[400];
        const KCarry c = kCarry(rows, 0.5, b);
        std::snprintf(b1, sizeof b1,
                      "The base is one K (K %g MPa on %s): the model is its runs at the grid points. "
                      "The spread over K is in data/fe/studies/factorial.md; %s.\n",
                      b.kMpa, b.mesh.c_str(),
                      c.found ? ("the model carries it (u and the radii at K minus at the base's K, from " + c.mesh +
                                 ", K " + std::to_string(int(c.k.front())) + "-" + std::to_string(int(c.k.back())) +
                                 " MPa; KCarry in fe_rows.h)")
                                    .c_str()
                              : "no family covers the grid at several K: the model is the same at every K");
        md << b1;
        return;
    }
    md << "μ read back at each run's own u (each K separately) through the model's interpolation of the "
          "averaged points, where the run's u > 0.1 mm.\n\n"
       << "| reduction | runs | within 1 % | within 2 % | mean % | max % (at) |\n|---|---|---|---|---|---|\n";
    int all = 0, all1 = 0, all2 = 0;
    for (int k = 6; k <= 12; ++k) {
        const double red = k * 0.05;
        const BaseChoice base = chooseBase(rows, red);
        const PointGrid pts = basePoints(rows, red, base);
        if (pts.empty()) continue;
        std::map<double, std::pair<std::vector<double>, std::vector<double>>> line; // n → (u, μ) in μ order
        for (const auto &[key, p] : pts) {
            line[p.n].first.push_back(p.u);
            line[p.n].second.push_back(p.mu);
        }
        int count = 0, in1 = 0, in2 = 0;
        double sum = 0, worst = 0;
        std::string where;
        for (const auto &r : rows) {
            if (!reachedSnapshot(r, red) || !isPaperSpecimen(r) || meshKey(r) != base.mesh || !base.hasK(r.kMpa) ||
                r.uBest() <= 0.1)
                continue;
            const auto &[us, mus] = line[r.n];
            bool out = false;
            const double mu = friction::feMuAlongU(us.data(), mus.data(), int(us.size()), r.uBest(), &out);
            if (out) continue;
            const double rel = std::fabs(mu - r.mu) / r.mu;
            ++count;
            in1 += rel <= 0.01;
            in2 += rel <= 0.02;
            sum += rel;
            if (rel > worst) {
                worst = rel;
                char w[80];
                std::snprintf(w, sizeof w, "K %g, n %g, μ %g", r.kMpa, r.n, r.mu);
                where = w;
            }
        }
        all += count;
        all1 += in1;
        all2 += in2;
        char b[240];
        std::snprintf(b, sizeof b, "| %ld %% | %d | %d | %d | %.1f | %.1f (%s) |\n", std::lround(100 * red), count, in1,
                      in2, count ? 100 * sum / count : 0.0, 100 * worst, where.c_str());
        md << b;
    }
    md << "\nAll reductions: " << all << " runs, " << all1 << " within 1 %, " << all2 << " within 2 %.\n";
}
} // namespace icacam::host::fe
