#include "host_tools/photo/barrel_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include "host_tools/fe/fe_results.h"
#include "host_tools/fe/fe_runner.h"
#include "host_tools/manifest.h"

namespace icacam::host::photo {

namespace fs = std::filesystem;

namespace {

// The profile resampled at equal steps of its arc length, normalised as BarrelShape says.
BarrelShape normalisedShape(const BarrelProfile &p)
{
    const size_t m = p.zMm.size();
    if (m < 3) throw std::runtime_error("barrel profile " + p.caseLabel + ": fewer than 3 points");
    const double zTop = p.zMm.back(), rEdge = p.rMm.back();
    const double rMax = *std::max_element(p.rMm.begin(), p.rMm.end());
    if (!(zTop > 0) || !(rMax > rEdge)) throw std::runtime_error("barrel profile " + p.caseLabel + ": degenerate");
    std::vector<double> len(m, 0);
    for (size_t i = 1; i < m; ++i) len[i] = len[i - 1] + std::hypot(p.zMm[i] - p.zMm[i - 1], p.rMm[i] - p.rMm[i - 1]);
    BarrelShape out;
    size_t i = 1;
    for (int k = 0; k < kShapePoints; ++k) {
        const double at = len.back() * k / (kShapePoints - 1);
        while (i < m - 1 && len[i] < at) ++i;
        const double t = len[i] > len[i - 1] ? std::clamp((at - len[i - 1]) / (len[i] - len[i - 1]), 0.0, 1.0) : 0;
        const double z = p.zMm[i - 1] + t * (p.zMm[i] - p.zMm[i - 1]);
        const double r = p.rMm[i - 1] + t * (p.rMm[i] - p.rMm[i - 1]);
        out.zeta.push_back(z / zTop);
        out.s.push_back((r - rEdge) / (rMax - rEdge));
    }
    return out;
}

// The two grid values around x and the weight of the upper one (held at the ends).
void bracket(const std::vector<double> &grid, double x, double *lo, double *hi, double *w)
{
    if (x <= grid.front()) {
        *lo = *hi = grid.front(), *w = 0;
        return;
    }
    if (x >= grid.back()) {
        *lo = *hi = grid.back(), *w = 0;
        return;
    }
    const auto up = std::upper_bound(grid.begin(), grid.end(), x);
    *hi = *up, *lo = *(up - 1);
    *w = (x - *lo) / (*hi - *lo);
}

bool near(double a, double b)
{
    return std::fabs(a - b) < 1e-6;
}

} // namespace

BarrelProfile extractBarrelProfile(const fe::FeCase &c, const fe::NodeXY &coords, const fe::NodeXY &disp,
                                   double reduction)
{
    const fe::FeMesh m = fe::meshFor(c);
    const double zPlaten = c.h0Mm / 2 * (1 - reduction);
    BarrelProfile p;
    p.caseLabel = c.label(), p.n = c.n, p.mu = c.mu, p.kMpa = c.kMpa, p.reduction = reduction;
    std::vector<std::pair<double, double>> side; // (z, r), mid-plane … corner
    for (int j = 0; j < m.rows(); ++j) {
        const int id = m.lateralNode(j);
        const auto ci = coords.find(id), di = disp.find(id);
        if (ci == coords.end() || di == disp.end()) throw std::runtime_error("fe: node missing in results");
        side.push_back({ci->second.second + di->second.second, ci->second.first + di->second.first});
    }
    // The free surface runs up from the mid-plane to the first node on the platen: the
    // contact edge, the outermost node of the immigrated ring. Walked from below, because a
    // quadratic element's mid-side node can hover a micrometre above the platen inside the
    // ring (fe_contact_track.h); on the platen here means within a few micrometres, far below
    // a pixel, and a node pressed into it (the penalty contact) is put on it.
    constexpr double kOnPlatenMm = 0.005;
    size_t edge = 0;
    while (edge + 1 < side.size() && zPlaten - side[edge].first > kOnPlatenMm) ++edge;
    for (size_t j = 0; j < edge; ++j) p.zMm.push_back(side[j].first), p.rMm.push_back(side[j].second);
    p.zMm.push_back(zPlaten);
    p.rMm.push_back(side[edge].second);
    return p;
}

void writeBarrelProfiles(const std::string &path, const std::vector<BarrelProfile> &profiles)
{
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
    out << "case,n,mu,k_mpa,reduction,point,z_mm,r_mm\n";
    char line[256];
    for (const BarrelProfile &p : profiles)
        for (size_t i = 0; i < p.zMm.size(); ++i) {
            std::snprintf(line, sizeof line, "%s,%g,%g,%g,%.4f,%zu,%.5f,%.5f\n", p.caseLabel.c_str(), p.n, p.mu, p.kMpa,
                          p.reduction, i, p.zMm[i], p.rMm[i]);
            out << line;
        }
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

std::vector<BarrelProfile> readBarrelProfiles(const std::string &path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read the barrel profiles '" + path + "'");
    std::string line;
    std::vector<std::string> header, f;
    if (!std::getline(in, line) || !splitCsvLine(line, &header)) throw std::runtime_error(path + ": no header");
    const char *want[] = {"case", "n", "mu", "k_mpa", "reduction", "z_mm", "r_mm"};
    size_t col[7];
    for (size_t k = 0; k < 7; ++k) {
        const auto it = std::find(header.begin(), header.end(), want[k]);
        if (it == header.end()) throw std::runtime_error(path + ": no '" + want[k] + "' column");
        col[k] = size_t(it - header.begin());
    }
    std::vector<BarrelProfile> out;
    std::map<std::pair<std::string, std::string>, size_t> index; // (case, reduction) → profile
    for (int lineNo = 2; std::getline(in, line); ++lineNo) {
        if (line.empty()) continue;
        double v[7] = {};
        bool ok = splitCsvLine(line, &f) && f.size() >= header.size();
        for (size_t k = 1; ok && k < 7; ++k) ok = parseNumber(f[col[k]], &v[k]);
        if (!ok) throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": a malformed profile row");
        const auto key = std::make_pair(f[col[0]], f[col[4]]);
        auto it = index.find(key);
        if (it == index.end()) {
            it = index.emplace(key, out.size()).first;
            out.push_back({f[col[0]], v[1], v[2], v[3], v[4], {}, {}});
        }
        out[it->second].zMm.push_back(v[5]);
        out[it->second].rMm.push_back(v[6]);
    }
    if (out.empty()) throw std::runtime_error(path + ": no barrel profiles");
    return out;
}

BarrelShape barrelShapeAt(const std::vector<BarrelProfile> &table, double n, double mu, double reduction)
{
    std::vector<double> ns, mus, reds;
    for (const BarrelProfile &p : table) ns.push_back(p.n), mus.push_back(p.mu), reds.push_back(p.reduction);
    for (auto *v : {&ns, &mus, &reds}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end(), near), v->end());
    }
    double n0, n1, wn, m0, m1, wm, r0, r1, wr;
    bracket(ns, n, &n0, &n1, &wn);
    bracket(mus, mu, &m0, &m1, &wm);
    bracket(reds, reduction, &r0, &r1, &wr);
    BarrelShape out;
    out.zeta.assign(kShapePoints, 0), out.s.assign(kShapePoints, 0);
    double weightSum = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const double w = (corner & 1 ? wn : 1 - wn) * (corner & 2 ? wm : 1 - wm) * (corner & 4 ? wr : 1 - wr);
        if (w <= 0 && corner != 0) continue;
        const double nc = corner & 1 ? n1 : n0, mc = corner & 2 ? m1 : m0, rc = corner & 4 ? r1 : r0;
        const auto it = std::find_if(table.begin(), table.end(), [&](const BarrelProfile &p) {
            return near(p.n, nc) && near(p.mu, mc) && near(p.reduction, rc);
        });
        if (it == table.end()) {
            char b[160];
            std::snprintf(b, sizeof b, "barrel profiles: no profile at n %g, mu %g, reduction %g", nc, mc, rc);
            throw std::runtime_error(b);
        }
        const BarrelShape s = normalisedShape(*it);
        for (int k = 0; k < kShapePoints; ++k)
            out.zeta[size_t(k)] += w * s.zeta[size_t(k)], out.s[size_t(k)] += w * s.s[size_t(k)];
        weightSum += w;
    }
    for (int k = 0; k < kShapePoints; ++k) out.zeta[size_t(k)] /= weightSum, out.s[size_t(k)] /= weightSum;
    return out;
}

fe::FeCase profileCase(double n, double mu)
{
    // Quadratic elements follow the fold-over at high μ; a 0.2 mm corner and a 0.5 mm far
    // field resolve the side's shape (its nodes 0.2–0.5 mm apart) in about a minute a case.
    fe::FeCase c;
    c.n = n, c.mu = mu;
    c.element = "CAX8R";
    c.elemMm = 0.5;
    c.cornerMm = 0.2;
    c.reductionMax = 0.55;
    return c;
}

const std::vector<double> &profileGridN()
{
    static const std::vector<double> v{0.05, 0.125, 0.25, 0.375, 0.5};
    return v;
}

const std::vector<double> &profileGridMu()
{
    static const std::vector<double> v{0.05, 0.1, 0.15, 0.2, 0.25, 0.3};
    return v;
}

const std::vector<double> &profileReductions()
{
    static const std::vector<double> v{0.45, 0.5, 0.55};
    return v;
}

void makeBarrelProfiles(const std::string &outCsv, const std::string &workDir, const std::string &ccx)
{
    std::vector<BarrelProfile> profiles;
    fe::RunOptions run;
    run.workDir = workDir;
    run.ccx = ccx;
    run.reuse = true;
    for (double n : profileGridN())
        for (double mu : profileGridMu()) {
            fe::FeCase c = profileCase(n, mu);
            const fe::RunResult res = fe::runCase(c, run);
            if (res.status == "error") throw std::runtime_error(c.label() + ": " + res.message);
            const fe::FrdResults frd = fe::readFrd((fs::path(res.dir) / "job.frd").string());
            for (double red : profileReductions()) {
                // Only a snapshot the run reached and converged (its radii row exists).
                if (std::none_of(res.radii.begin(), res.radii.end(),
                                 [&](const fe::Radii &r) { return near(r.reduction, red); }))
                    continue;
                const auto step = std::find_if(frd.steps.begin(), frd.steps.end(), [&](const fe::FrdStep &s) {
                    return near(s.time * c.reductionMax, red);
                });
                if (step == frd.steps.end()) continue;
                profiles.push_back(extractBarrelProfile(c, frd.coords, step->disp, red));
            }
            std::cerr << "icacam synth: barrel profile " << c.label() << " (" << res.status << ")\n";
        }
    writeBarrelProfiles(outCsv, profiles);
}

} // namespace icacam::host::photo
