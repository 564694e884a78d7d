#include "host_tools/fe/fe_paper_form.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "friction/paper_model.h"

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

using PointsByN = std::map<double, std::pair<std::vector<double>, std::vector<double>>>; // n → (u, μ)

const char *const kCoefficientNames[4] = {"a", "b", "c", "d"};

// The per-n cubics (Eq. 2, Table 1): at each n its coefficients (highest power first).
struct PerNCubics {
    std::vector<double> n;
    std::vector<std::vector<double>> coef = std::vector<std::vector<double>>(4); // a, b, c, d over n
};

PerNCubics writePerNCubics(std::ostream &md, const PointsByN &byN)
{
    md << "\n## The paper's form on our data (Eq. 2 / Table 1, Eq. 3 / Fig. 4)\n\n"
       << "Per n, μ = a u³ + b u² + c u + d by least squares through the FE points with u > 0.02 mm "
          "(at least 4 needed; with exactly 4 the cubic interpolates). Paper: Table 1 (Eq. 3 with d's constant "
          "−0.00788).\n\n"
       << "| n | points | a | b | c | d | paper a | paper b | paper c | paper d | max abs. dev. μ | mean abs. dev. μ "
          "|\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    PerNCubics fit;
    double worst = 0, sumDev = 0;
    int devCount = 0;
    for (const auto &[n, uv] : byN) {
        const auto c = polyFit(uv.first, uv.second, 3);
        const auto pc = friction::PaperModel::coefficients(n);
        char b[400];
        if (c.empty()) {
            std::snprintf(b, sizeof b, "| %g | %zu | (too few) | | | | %.4f | %.4f | %.4f | %.4f | | |\n", n,
                          uv.first.size(), pc.a, pc.b, pc.c, pc.d);
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
        std::snprintf(
            b, sizeof b, "| %g | %zu | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", n,
            uv.first.size(), c[0], c[1], c[2], c[3], pc.a, pc.b, pc.c, pc.d, mx, sum / double(uv.first.size()));
        md << b;
        fit.n.push_back(n);
        for (int i = 0; i < 4; ++i) fit.coef[size_t(i)].push_back(c[size_t(i)]);
    }
    if (devCount > 0) {
        char b[200];
        std::snprintf(b, sizeof b, "\nPer-n cubics against their FE points: max |Δμ| %.4f, mean %.4f.\n", worst,
                      sumDev / devCount);
        md << b;
    }
    return fit;
}

// Eq. 3: each coefficient as a cubic in n (needs 4 n with a per-n cubic), and the Eq. 2/3
// form's error against every FE point. Empty cubics where it cannot be fitted.
std::vector<std::vector<double>> writeEq3Form(std::ostream &md, const PointsByN &byN, const PerNCubics &fit)
{
    std::vector<std::vector<double>> eq3(4);
    if (fit.n.size() < 4) {
        md << "\nEq. 3 form: needs per-n cubics at 4 or more n (have " << fit.n.size() << ").\n";
        return eq3;
    }
    md << "\nEq. 3 form (coefficient = p3 n³ + p2 n² + p1 n + p0) through the " << fit.n.size() << " per-n cubics:\n\n"
       << "| coefficient | p3 | p2 | p1 | p0 |\n|---|---|---|---|---|\n";
    for (int i = 0; i < 4; ++i) {
        eq3[size_t(i)] = polyFit(fit.n, fit.coef[size_t(i)], 3);
        char b[200];
        std::snprintf(b, sizeof b, "| %s | %.5f | %.5f | %.5f | %.5f |\n", kCoefficientNames[i], eq3[size_t(i)][0],
                      eq3[size_t(i)][1], eq3[size_t(i)][2], eq3[size_t(i)][3]);
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
    std::snprintf(b, sizeof b, "\nEq. 2/3 form against all %d FE points: max |Δμ| %.4f, mean %.4f.\n", cnt, mx,
                  sum / cnt);
    md << b;
    return eq3;
}

// One coefficient's panel of the Fig. 4-like plot: ours (dots), our Eq. 3 form (line) and the
// paper's Eq. 3 (dashed) over n.
void writeCoefficientPanel(std::ostream &svg, int i, const PerNCubics &fit, const std::vector<double> &eq3)
{
    const double pw = 330, ph = 220;
    const double ox = 50 + (i % 2) * (pw + 50), oy = 30 + (i / 2) * (ph + 50);
    double lo = 1e9, hi = -1e9;
    for (int k = 0; k <= 40; ++k) {
        const auto pc = friction::PaperModel::coefficients(0.05 + 0.45 * k / 40);
        const double v[4] = {pc.a, pc.b, pc.c, pc.d};
        lo = std::min(lo, v[i]);
        hi = std::max(hi, v[i]);
    }
    for (double v : fit.coef[size_t(i)]) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (hi - lo < 1e-9) hi = lo + 1;
    const double pad = 0.1 * (hi - lo);
    lo -= pad;
    hi += pad;
    auto X = [&](double n) { return ox + (n - 0.0) / 0.55 * pw; };
    auto Y = [&](double v) { return oy + ph - (v - lo) / (hi - lo) * ph; };
    svg << "<rect x='" << ox << "' y='" << oy << "' width='" << pw << "' height='" << ph
        << "' fill='none' stroke='black'/>\n"
        << "<text x='" << ox + 5 << "' y='" << oy + 15 << "'>" << kCoefficientNames[i] << "(n)</text>\n";
    char lab[64];
    std::snprintf(lab, sizeof lab, "%.3g", hi);
    svg << "<text x='" << ox - 45 << "' y='" << oy + 10 << "' font-size='10'>" << lab << "</text>\n";
    std::snprintf(lab, sizeof lab, "%.3g", lo);
    svg << "<text x='" << ox - 45 << "' y='" << oy + ph << "' font-size='10'>" << lab << "</text>\n";
    for (double n : {0.05, 0.25, 0.5})
        svg << "<text x='" << X(n) - 8 << "' y='" << oy + ph + 14 << "' font-size='10'>" << n << "</text>\n";
    std::string path;
    for (int k = 0; k <= 40; ++k) {
        const double n = 0.05 + 0.45 * k / 40;
        const auto pc = friction::PaperModel::coefficients(n);
        const double v[4] = {pc.a, pc.b, pc.c, pc.d};
        char b[64];
        std::snprintf(b, sizeof b, "%s%.1f,%.1f ", k ? "L" : "M", X(n), Y(v[i]));
        path += b;
    }
    svg << "<path d='" << path << "' fill='none' stroke='#888' stroke-dasharray='4,3'/>\n";
    if (!eq3.empty()) {
        path.clear();
        for (int k = 0; k <= 40; ++k) {
            const double n = 0.05 + 0.45 * k / 40;
            char b[64];
            std::snprintf(b, sizeof b, "%s%.1f,%.1f ", k ? "L" : "M", X(n), Y(polyAt(eq3, n)));
            path += b;
        }
        svg << "<path d='" << path << "' fill='none' stroke='#1f77b4'/>\n";
    }
    for (size_t k = 0; k < fit.n.size(); ++k)
        svg << "<circle cx='" << X(fit.n[k]) << "' cy='" << Y(fit.coef[size_t(i)][k]) << "' r='4' fill='#1f77b4'/>\n";
}

} // namespace

// The paper's form on our data: per n a cubic μ(u) (Eq. 2, Table 1) through the FE points
// with u > 0 (where μ is resolved), each coefficient a cubic in n (Eq. 3), the fit's error
// against the FE points, and a Fig. 4-like plot of the coefficients over n.
void writeTable1Form(std::ostream &md, const fs::path &svgPath, const PointGrid &pts)
{
    PointsByN byN;
    for (const auto &[k, p] : pts)
        if (p.u > 0.02) {
            byN[p.n].first.push_back(p.u);
            byN[p.n].second.push_back(p.mu);
        }
    const PerNCubics fit = writePerNCubics(md, byN);
    const std::vector<std::vector<double>> eq3 = writeEq3Form(md, byN, fit);
    std::ofstream svg(svgPath);
    const double W = 760, H = 560;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "'>\n"
        << "<rect width='100%' height='100%' fill='white'/>\n";
    for (int i = 0; i < 4; ++i) writeCoefficientPanel(svg, i, fit, eq3[size_t(i)]);
    svg << "<text x='50' y='" << H - 8
        << "' font-size='11'>dots: per-n cubics through our FE points; line: our Eq. 3 form; "
           "dashed: the paper's Eq. 3</text>\n</svg>\n";
}

} // namespace icacam::host::fe
