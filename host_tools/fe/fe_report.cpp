#include "fe_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include "fe_rows.h"
#include "vision/fe_model.h"
#include "vision/paper_model.h"

namespace icacam::host::fe {

namespace fs = std::filesystem;

namespace {
// Least-squares polynomial of degree `deg` through (x, y): coefficients highest power first,
// or empty when there are too few points (normal equations, Gaussian elimination).
std::vector<double> polyFit(const std::vector<double> &x, const std::vector<double> &y, int deg)
{
    const int m = deg + 1;
    if (int(x.size()) < m) return {};
    std::vector<std::vector<double>> a(size_t(m), std::vector<double>(size_t(m + 1), 0.0));
    for (size_t k = 0; k < x.size(); ++k)
        for (int i = 0; i < m; ++i) {
            for (int j = 0; j < m; ++j) a[size_t(i)][size_t(j)] += std::pow(x[k], 2 * deg - i - j);
            a[size_t(i)][size_t(m)] += y[k] * std::pow(x[k], deg - i);
        }
    for (int c = 0; c < m; ++c) {
        int piv = c;
        for (int r = c + 1; r < m; ++r)
            if (std::fabs(a[size_t(r)][size_t(c)]) > std::fabs(a[size_t(piv)][size_t(c)])) piv = r;
        std::swap(a[size_t(c)], a[size_t(piv)]);
        if (std::fabs(a[size_t(c)][size_t(c)]) < 1e-300) return {};
        for (int r = 0; r < m; ++r) {
            if (r == c) continue;
            const double f = a[size_t(r)][size_t(c)] / a[size_t(c)][size_t(c)];
            for (int j = c; j <= m; ++j) a[size_t(r)][size_t(j)] -= f * a[size_t(c)][size_t(j)];
        }
    }
    std::vector<double> out(static_cast<size_t>(m), 0.0);
    for (int i = 0; i < m; ++i) out[size_t(i)] = a[size_t(i)][size_t(m)] / a[size_t(i)][size_t(i)];
    return out;
}
double polyAt(const std::vector<double> &c, double x)
{
    double v = 0;
    for (double k : c) v = v * x + k;
    return v;
}

// The paper's form on our data: per n a cubic μ(u) (Eq. 2, Table 1) through the FE points
// with u > 0 (where μ is resolved), each coefficient a cubic in n (Eq. 3), the fit's error
// against the FE points, and a Fig. 4-like plot of the coefficients over n.
void writeTable1Form(std::ostream &md, const fs::path &svgPath, const PointGrid &pts)
{
    std::map<double, std::pair<std::vector<double>, std::vector<double>>> byN; // n → (u, μ)
    for (const auto &[k, p] : pts)
        if (p.u > 0.02) { byN[p.n].first.push_back(p.u); byN[p.n].second.push_back(p.mu); }
    md << "\n## The paper's form on our data (Eq. 2 / Table 1, Eq. 3 / Fig. 4)\n\n"
       << "Per n, μ = a u³ + b u² + c u + d by least squares through the FE points with u > 0.02 mm "
          "(at least 4 needed; with exactly 4 the cubic interpolates). Paper: Table 1 (Eq. 3 with d's constant −0.00788).\n\n"
       << "| n | points | a | b | c | d | paper a | paper b | paper c | paper d | max abs. dev. μ | mean abs. dev. μ |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<double> nFit;
    std::vector<std::vector<double>> coef(4);
    double worst = 0, sumDev = 0;
    int devCount = 0;
    for (const auto &[n, uv] : byN) {
        const auto c = polyFit(uv.first, uv.second, 3);
        const auto pc = vision::PaperModel::coefficients(n);
        char b[400];
        if (c.empty()) {
            std::snprintf(b, sizeof b, "| %g | %zu | (too few) | | | | %.4f | %.4f | %.4f | %.4f | | |\n", n, uv.first.size(),
                          pc.a, pc.b, pc.c, pc.d);
            md << b;
            continue;
        }
        double mx = 0, sum = 0;
        for (size_t k = 0; k < uv.first.size(); ++k) {
            const double dev = std::fabs(polyAt(c, uv.first[k]) - uv.second[k]);
            mx = std::max(mx, dev);
            sum += dev;
        }
        worst = std::max(worst, mx);
        sumDev += sum;
        devCount += int(uv.first.size());
        std::snprintf(b, sizeof b, "| %g | %zu | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", n,
                      uv.first.size(), c[0], c[1], c[2], c[3], pc.a, pc.b, pc.c, pc.d, mx, sum / double(uv.first.size()));
        md << b;
        nFit.push_back(n);
        for (int i = 0; i < 4; ++i) coef[size_t(i)].push_back(c[size_t(i)]);
    }
    if (devCount > 0) {
        char b[200];
        std::snprintf(b, sizeof b, "\nPer-n cubics against their FE points: max |Δμ| %.4f, mean %.4f.\n", worst, sumDev / devCount);
        md << b;
    }
    // Eq. 3: each coefficient as a cubic in n (needs 4 n with a per-n cubic).
    const char *names[4] = {"a", "b", "c", "d"};
    std::vector<std::vector<double>> eq3(4);
    if (nFit.size() >= 4) {
        md << "\nEq. 3 form (coefficient = p3 n³ + p2 n² + p1 n + p0) through the " << nFit.size() << " per-n cubics:\n\n"
           << "| coefficient | p3 | p2 | p1 | p0 |\n|---|---|---|---|---|\n";
        for (int i = 0; i < 4; ++i) {
            eq3[size_t(i)] = polyFit(nFit, coef[size_t(i)], 3);
            char b[200];
            std::snprintf(b, sizeof b, "| %s | %.5f | %.5f | %.5f | %.5f |\n", names[i], eq3[size_t(i)][0], eq3[size_t(i)][1],
                          eq3[size_t(i)][2], eq3[size_t(i)][3]);
            md << b;
        }
        double mx = 0, sum = 0;
        int cnt = 0;
        for (const auto &[n, uv] : byN)
            for (size_t k = 0; k < uv.first.size(); ++k) {
                std::vector<double> c(4);
                for (int i = 0; i < 4; ++i) c[size_t(i)] = polyAt(eq3[size_t(i)], n);
                const double dev = std::fabs(polyAt(c, uv.first[k]) - uv.second[k]);
                mx = std::max(mx, dev);
                sum += dev;
                ++cnt;
            }
        char b[200];
        std::snprintf(b, sizeof b, "\nEq. 2/3 form against all %d FE points: max |Δμ| %.4f, mean %.4f.\n", cnt, mx, sum / cnt);
        md << b;
    } else {
        md << "\nEq. 3 form: needs per-n cubics at 4 or more n (have " << nFit.size() << ").\n";
    }
    // Fig. 4-like: the four coefficients over n, ours (dots) and the paper's Eq. 3 (lines).
    std::ofstream svg(svgPath);
    const double W = 760, H = 560, pw = 330, ph = 220;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "'>\n"
        << "<rect width='100%' height='100%' fill='white'/>\n";
    for (int i = 0; i < 4; ++i) {
        const double ox = 50 + (i % 2) * (pw + 50), oy = 30 + (i / 2) * (ph + 50);
        double lo = 1e9, hi = -1e9;
        for (int k = 0; k <= 40; ++k) {
            const auto pc = vision::PaperModel::coefficients(0.05 + 0.45 * k / 40);
            const double v[4] = {pc.a, pc.b, pc.c, pc.d};
            lo = std::min(lo, v[i]); hi = std::max(hi, v[i]);
        }
        for (double v : coef[size_t(i)]) { lo = std::min(lo, v); hi = std::max(hi, v); }
        if (hi - lo < 1e-9) hi = lo + 1;
        const double pad = 0.1 * (hi - lo);
        lo -= pad; hi += pad;
        auto X = [&](double n) { return ox + (n - 0.0) / 0.55 * pw; };
        auto Y = [&](double v) { return oy + ph - (v - lo) / (hi - lo) * ph; };
        svg << "<rect x='" << ox << "' y='" << oy << "' width='" << pw << "' height='" << ph << "' fill='none' stroke='black'/>\n"
            << "<text x='" << ox + 5 << "' y='" << oy + 15 << "'>" << names[i] << "(n)</text>\n";
        char lab[64];
        std::snprintf(lab, sizeof lab, "%.3g", hi);
        svg << "<text x='" << ox - 45 << "' y='" << oy + 10 << "' font-size='10'>" << lab << "</text>\n";
        std::snprintf(lab, sizeof lab, "%.3g", lo);
        svg << "<text x='" << ox - 45 << "' y='" << oy + ph << "' font-size='10'>" << lab << "</text>\n";
        for (double n : {0.05, 0.25, 0.5}) svg << "<text x='" << X(n) - 8 << "' y='" << oy + ph + 14 << "' font-size='10'>" << n << "</text>\n";
        std::string path;
        for (int k = 0; k <= 40; ++k) {
            const double n = 0.05 + 0.45 * k / 40;
            const auto pc = vision::PaperModel::coefficients(n);
            const double v[4] = {pc.a, pc.b, pc.c, pc.d};
            char b[64];
            std::snprintf(b, sizeof b, "%s%.1f,%.1f ", k ? "L" : "M", X(n), Y(v[i]));
            path += b;
        }
        svg << "<path d='" << path << "' fill='none' stroke='#888' stroke-dasharray='4,3'/>\n";
        if (!eq3[size_t(i)].empty()) {
            path.clear();
            for (int k = 0; k <= 40; ++k) {
                const double n = 0.05 + 0.45 * k / 40;
                char b[64];
                std::snprintf(b, sizeof b, "%s%.1f,%.1f ", k ? "L" : "M", X(n), Y(polyAt(eq3[size_t(i)], n)));
                path += b;
            }
            svg << "<path d='" << path << "' fill='none' stroke='#1f77b4'/>\n";
        }
        for (size_t k = 0; k < nFit.size(); ++k)
            svg << "<circle cx='" << X(nFit[k]) << "' cy='" << Y(coef[size_t(i)][k]) << "' r='4' fill='#1f77b4'/>\n";
    }
    svg << "<text x='50' y='" << H - 8 << "' font-size='11'>dots: per-n cubics through our FE points; line: our Eq. 3 form; "
           "dashed: the paper's Eq. 3</text>\n</svg>\n";
}

// The generated model between its grid points: each interior grid point left out in turn and
// predicted by the model's own interpolation (vision::feMuAlongU) from the rest — along u at
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
            if (std::fabs(rel) > worst) { worst = std::fabs(rel); where = what; }
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
            double us[vision::kMaxRowPoints], mus[vision::kMaxRowPoints];
            int c = 0;
            for (size_t j = 0; j < line.size() && c < vision::kMaxRowPoints; ++j)
                if (j != skip) { us[c] = line[j]->u; mus[c] = line[j]->mu; ++c; }
            return vision::feMuAlongU(us, mus, c, u, outside);
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
        std::snprintf(b, sizeof b, "| %ld %% | %d | %.1f | %.1f (%s) | %d | %.1f | %.1f (%s) |\n", std::lround(100 * red),
                      sMu.count, sMu.count ? 100 * sMu.sum / sMu.count : 0.0, 100 * sMu.worst, sMu.where.c_str(), sN.count,
                      sN.count ? 100 * sN.sum / sN.count : 0.0, 100 * sN.worst, sN.where.c_str());
        md << b;
    }
    char b[300];
    std::snprintf(b, sizeof b, "\nAll reductions: one μ out %d points, mean %.1f %%, max %.1f %%; one n out %d points, "
                  "mean %.1f %%, max %.1f %%.\n", allMu.count, allMu.count ? 100 * allMu.sum / allMu.count : 0.0,
                  100 * allMu.worst, allN.count, allN.count ? 100 * allN.sum / allN.count : 0.0, 100 * allN.worst);
    md << b;
}

// The model against every run it averages (each K of the factorial on its own): μ read back
// at each run's u along its n, through the model's interpolation of the averaged points. At a
// grid point the model is the mean over K, so this is the K spread seen in μ.
void writeRunResiduals(std::ostream &md, const std::vector<FeRow> &rows)
{
    md << "\n## The model against each run it averages\n\n"
       << "μ read back at each run's own u (each K separately) through the model's interpolation of the "
          "averaged points, where the run's u > 0.1 mm.\n\n"
       << "| reduction | runs | within 1 % | within 2 % | mean % | max % (at) |\n|---|---|---|---|---|---|\n";
    int all = 0, all1 = 0, all2 = 0;
    for (int k = 6; k <= 12; ++k) {
        const double red = k * 0.05;
        const BaseChoice base = chooseBase(rows, red);
        const PointGrid pts = basePoints(rows, red);
        if (pts.empty()) continue;
        std::map<double, std::pair<std::vector<double>, std::vector<double>>> line; // n → (u, μ) in μ order
        for (const auto &[key, p] : pts) { line[p.n].first.push_back(p.u); line[p.n].second.push_back(p.mu); }
        int count = 0, in1 = 0, in2 = 0;
        double sum = 0, worst = 0;
        std::string where;
        for (const auto &r : rows) {
            if (!reachedSnapshot(r, red) || !isPaperSpecimen(r) || meshKey(r) != base.mesh || !base.hasK(r.kMpa) ||
                r.uBest() <= 0.1)
                continue;
            const auto &[us, mus] = line[r.n];
            bool out = false;
            const double mu = vision::feMuAlongU(us.data(), mus.data(), int(us.size()), r.uBest(), &out);
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
        all += count; all1 += in1; all2 += in2;
        char b[240];
        std::snprintf(b, sizeof b, "| %ld %% | %d | %d | %d | %.1f | %.1f (%s) |\n", std::lround(100 * red), count, in1, in2,
                      count ? 100 * sum / count : 0.0, 100 * worst, where.c_str());
        md << b;
    }
    md << "\nAll reductions: " << all << " runs, " << all1 << " within 1 %, " << all2 << " within 2 %.\n";
}
} // namespace

int reportCommand(const std::vector<std::string> &in, const std::string &outDir, double reduction)
{
    const std::vector<FeRow> rows = readSweepCsvs(in);
    const auto pts = basePoints(rows, reduction);
    fs::create_directories(outDir);
    vision::PaperModel paper;
    std::ofstream md(fs::path(outDir) / "comparison.md");
    md << "# FE (CalculiX) against Duran & Karadogan (2016)\n\n"
       << "Generated by `icacam fe report`. u: our FE (interpolated contact edge), u_paper: the u at which the\n"
       << "paper's corrected Eq. 2/3 gives this μ, μ_paper(u): the paper's μ at our u.\n\n"
       << "| n | μ | u FE (mm) | u paper (mm) | Δu % | μ_paper(u_FE) | R_i | R_o | R_max | F/K (kN/MPa) |\n"
       << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto &[k, p] : pts) {
        // Invert the paper's cubic at this n by bisection over u ∈ [0, 1.4].
        double lo = 0, hi = 1.4;
        vision::ModelInputs mi;
        mi.n = p.n;
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            mi.uMm = mid;
            (paper.estimate(mi).mu < p.mu ? lo : hi) = mid;
        }
        const double uPaper = 0.5 * (lo + hi);
        mi.uMm = p.u;
        char b[400];
        std::snprintf(b, sizeof b, "| %g | %g | %.4f | %.4f | %+.1f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", p.n,
                      p.mu, p.u, uPaper, uPaper > 0 ? 100 * (p.u - uPaper) / uPaper : 0.0,
                      paper.estimate(mi).mu, p.ri, p.ro, p.rMax, p.force);
        md << b;
    }
    // Beyond the paper: u over the reduction range the snapshots cover (30–60 %).
    std::vector<double> reds;
    std::map<std::pair<double, double>, std::map<double, double>> uByRed;
    for (int k = 6; k <= 12; ++k) {
        const double red = k * 0.05;
        const auto at = basePoints(rows, red);
        if (at.empty()) continue;
        reds.push_back(red);
        for (const auto &[key, p] : at) uByRed[key][red] = p.u;
    }
    md << "\n## u (mm) over the height reduction\n\n| n | μ |";
    for (double r : reds) md << " " << std::lround(100 * r) << " % |";
    md << "\n|---|---|";
    for (size_t k = 0; k < reds.size(); ++k) md << "---|";
    md << "\n";
    for (const auto &[key, byRed] : uByRed) {
        md << "| " << key.first << " | " << key.second << " |";
        for (double r : reds) {
            const auto it = byRed.find(r);
            char b[32] = " – |";
            if (it != byRed.end()) std::snprintf(b, sizeof b, " %.3f |", it->second);
            md << b;
        }
        md << "\n";
    }
    // Fig. 3-like plot: μ over u, one colour per n, FE points and the paper's curves.
    std::ofstream svg(fs::path(outDir) / "mu_vs_u.svg");
    const double W = 640, H = 420, x0 = 60, y0 = 380, sx = 500 / 1.4, sy = 340 / 0.35;
    const char *colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "'>\n"
        << "<rect width='100%' height='100%' fill='white'/>\n"
        << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 + 500 << "' y2='" << y0 << "' stroke='black'/>\n"
        << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 << "' y2='" << y0 - 340 << "' stroke='black'/>\n"
        << "<text x='" << x0 + 220 << "' y='" << H - 5 << "'>u (mm)</text><text x='5' y='30'>mu</text>\n";
    for (int t = 0; t <= 7; ++t)
        svg << "<text x='" << x0 + t * 0.2 * sx - 8 << "' y='" << y0 + 15 << "' font-size='11'>" << t * 0.2 << "</text>\n";
    for (int t = 0; t <= 7; ++t)
        svg << "<text x='20' y='" << y0 - t * 0.05 * sy + 4 << "' font-size='11'>" << t * 0.05 << "</text>\n";
    std::set<double> ns;
    for (const auto &[k, p] : pts) ns.insert(p.n);
    int ci = 0;
    for (double n : ns) {
        const char *col = colours[ci++ % 6];
        std::string path;
        vision::ModelInputs mi;
        mi.n = n;
        for (int i = 0; i <= 70; ++i) {
            mi.uMm = 1.25 * i / 70;
            const double mu = paper.estimate(mi).mu;
            char b[64];
            std::snprintf(b, sizeof b, "%s%.1f,%.1f ", i ? "L" : "M", x0 + mi.uMm * sx, y0 - mu * sy);
            path += b;
        }
        svg << "<path d='" << path << "' fill='none' stroke='" << col << "' stroke-dasharray='4,3'/>\n";
        for (const auto &[k, p] : pts)
            if (p.n == n)
                svg << "<circle cx='" << x0 + p.u * sx << "' cy='" << y0 - p.mu * sy << "' r='4' fill='" << col << "'/>\n";
        svg << "<text x='" << x0 + 420 << "' y='" << 40 + ci * 16 << "' fill='" << col << "'>n = " << n << "</text>\n";
    }
    svg << "<text x='" << x0 + 300 << "' y='" << 40 << "' font-size='11'>dots: FE, dashed: paper Eq. 2/3</text>\n</svg>\n";
    writeTable1Form(md, fs::path(outDir) / "coefficients_vs_n.svg", pts);
    writeLeaveOneOut(md, rows);
    writeRunResiduals(md, rows);
    std::cout << "report: " << pts.size() << " points -> " << outDir << "/comparison.md, mu_vs_u.svg, coefficients_vs_n.svg\n";
    return 0;
}

} // namespace icacam::host::fe
