#include "host_tools/fe/fe_case.h"
#include "host_tools/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace icacam::host::fe {

std::string FeCase::label() const
{
    char b[200];
    std::snprintf(b, sizeof b, "K%g_n%g_mu%g_E%g_D%g_H%g_r%g_h%g_c%g_cs%g", kMpa, n, mu, eMpa / 1000, d0Mm, h0Mm,
                  reductionMax, elemMm, cornerMm, contactSlope);
    // Settings added later only enter the label when they differ from the first sweeps'
    // defaults, so the labels (the sweep's resume keys) of committed rows stay valid.
    std::string s = b;
    if (element != "CAX4R") s += "_" + element;
    if (platenMm > 0) s += "_p" + numberText("%g", platenMm);
    if (stickSlope != 1e4) s += "_st" + numberText("%g", stickSlope);
    if (incMax != 0.01) s += "_im" + numberText("%g", incMax);
    if (foldZoneMm > 0) s += "_fz" + numberText("%g", foldZoneMm);
    if (trackStep > 0) s += "_tr" + numberText("%g", trackStep);
    if (contact != "node") s += "_s2s";
    if (rateSensitive()) {
        s += "_v" + numberText("%g", pressSpeedMmS) + "_m" + numberText("%g", m);
        if (rate0 != 1) s += "_e0" + numberText("%g", rate0);
        if (creepTol != 1e-2) s += "_ct" + numberText("%g", creepTol);
    }
    return s;
}

double stepTime(const FeCase &c)
{
    return c.rateSensitive() ? c.h0Mm * c.reductionMax / c.pressSpeedMmS : 1.0;
}

namespace {
// The first increment of a *VISCO step, of its step time (at most; incInit if smaller).
constexpr double kViscoIncInit = 1e-4;
// The smallest Norton A the deck writes (below, see makeDeck).
constexpr double kNortonAMin = 1e-18;

// Node positions on [0, len]: uniform `elem`, or graded from `fine` at len to `elem`.
std::vector<double> axisNodes(double len, double elem, double fine, double zone = 0)
{
    std::vector<double> x;
    if (fine <= 0 || fine >= elem) {
        const int n = std::max(2, int(std::lround(len / elem)));
        for (int i = 0; i <= n; ++i) x.push_back(len * i / n);
        return x;
    }
    std::vector<double> sizes; // from the fine end
    double sum = 0, h = fine;
    while (sum + h < len - 1e-9) {
        sizes.push_back(h);
        sum += h;
        if (sum >= zone - 1e-9) h = std::min(elem, h * 1.2);
    }
    // Spread the remainder over the coarse elements so the sizes sum to len.
    const double rest = len - sum;
    if (rest > 0.3 * sizes.back()) {
        sizes.push_back(rest);
        sum += rest;
    } else
        sizes.back() += rest;
    x.push_back(0);
    for (auto it = sizes.rbegin(); it != sizes.rend(); ++it) x.push_back(x.back() + *it);
    x.back() = len;
    return x;
}
} // namespace

FeMesh meshFor(const FeCase &c)
{
    if (c.element != "CAX4R" && c.element != "CAX8R")
        throw std::invalid_argument("fe: element must be CAX4R or CAX8R, not " + c.element);
    if (c.contact != "node" && c.contact != "surface")
        throw std::invalid_argument("fe: contact must be node or surface, not " + c.contact);
    FeMesh m;
    m.q = c.element == "CAX8R" ? 2 : 1;
    m.r = axisNodes(c.d0Mm / 2, c.elemMm, c.cornerMm);
    m.z = axisNodes(c.h0Mm / 2, c.elemMm, c.cornerMm, c.foldZoneMm);
    m.nr = int(m.r.size()) - 1;
    m.nz = int(m.z.size()) - 1;
    auto refine = [&](const std::vector<double> &x) {
        std::vector<double> y;
        for (size_t k = 0; k < x.size(); ++k) {
            if (k > 0 && m.q == 2) y.push_back(0.5 * (x[k - 1] + x[k]));
            y.push_back(x[k]);
        }
        return y;
    };
    m.rn = refine(m.r);
    m.zn = refine(m.z);
    m.platenFirstNode = m.cols() * m.rows() + 1;
    return m;
}

std::string makeDeck(const FeCase &c)
{
    if (!(c.n > 0 && c.kMpa > 0 && c.mu >= 0 && c.elemMm > 0 && c.reductionMax > 0 && c.reductionMax < 0.9 &&
          c.d0Mm > 0 && c.h0Mm > 0))
        throw std::invalid_argument("fe: invalid case inputs");
    if (!(c.pressSpeedMmS >= 0 && c.m >= 0 && c.rate0 > 0 && c.creepTol > 0) || (c.m > 0 && !c.rateSensitive()))
        throw std::invalid_argument("fe: a rate sensitivity m needs a press speed > 0 (and m ≥ 0, ε̇₀ > 0)");
    const FeMesh m = meshFor(c);
    const double r0 = c.d0Mm / 2, z0 = c.h0Mm / 2;
    const double dr = c.platenMm > 0   ? c.platenMm
                      : c.cornerMm > 0 ? std::max(c.cornerMm, 0.5 * c.elemMm)
                                       : r0 / m.nr; // platen spacing
    const double dz = m.z[1] - m.z[0];
    std::ostringstream o;
    o.precision(10);
    o << "** icacam fe: cylinder upsetting, axisymmetric quarter model (generated)\n"
      << "** " << c.label() << "\n*NODE,NSET=NALL\n";
    const int q = m.q;
    for (int j = 0; j < m.rows(); ++j)
        for (int i = 0; i < m.cols(); ++i)
            if (q == 1 || i % 2 == 0 || j % 2 == 0) // quadratic: no node at element centres
                o << m.node(i, j) << ", " << m.rn[i] << ", " << m.zn[j] << "\n";
    // The platen: one row of elements from the axis to 2.2 R0, with the specimen's spacing.
    const int np = int(std::lround(2.2 * r0 / dr));
    const double tp = std::max(dz, 0.5);
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= np; ++i)
            o << m.platenFirstNode + i + j * (np + 1) << ", " << i * dr << ", " << z0 + j * tp << "\n";
    o << "*ELEMENT,TYPE=" << c.element << ",ELSET=SPEC\n";
    int e = 1;
    for (int j = 0; j < m.nz; ++j)
        for (int i = 0; i < m.nr; ++i, ++e) {
            const int a = q * i, b = q * j; // lower-left corner on the node grid
            o << e << ", " << m.node(a, b) << ", " << m.node(a + q, b) << ", " << m.node(a + q, b + q) << ", "
              << m.node(a, b + q);
            if (q == 2) // mid-side nodes: bottom, right, top, left
                o << ", " << m.node(a + 1, b) << ", " << m.node(a + 2, b + 1) << ", " << m.node(a + 1, b + 2) << ", "
                  << m.node(a, b + 1);
            o << "\n";
        }
    const int firstPlatenElem = e;
    o << "*ELEMENT,TYPE=CAX4R,ELSET=PLATEN\n";
    for (int i = 0; i < np; ++i, ++e) {
        const int a = m.platenFirstNode + i;
        o << e << ", " << a << ", " << a + 1 << ", " << a + np + 2 << ", " << a + np + 1 << "\n";
    }
    auto nset = [&](const char *name, auto pred) {
        o << "*NSET,NSET=" << name << "\n";
        int k = 0;
        for (int j = 0; j < m.rows(); ++j)
            for (int i = 0; i < m.cols(); ++i)
                if ((q == 1 || i % 2 == 0 || j % 2 == 0) && pred(i, j)) o << m.node(i, j) << (++k % 8 ? ", " : ",\n");
        if (k % 8) o << "\n";
    };
    nset("AXIS", [](int i, int) { return i == 0; });
    nset("MID", [](int, int j) { return j == 0; });
    o << "*NSET,NSET=PLATENN,GENERATE\n"
      << m.platenFirstNode << ", " << m.platenFirstNode + 2 * (np + 1) - 1 << ", 1\n";
    // Slave: specimen top (S3 of the top row) and lateral surface (S2 of the outer column).
    o << "*SURFACE,NAME=SLAVE\n";
    for (int i = 0; i < m.nr; ++i) o << 1 + i + (m.nz - 1) * m.nr << ", S3\n";
    for (int j = 0; j < m.nz; ++j) o << 1 + (m.nr - 1) + j * m.nr << ", S2\n";
    o << "*SURFACE,NAME=MASTER\n";
    for (int i = 0; i < np; ++i) o << firstPlatenElem + i << ", S1\n";
    o << "*MATERIAL,NAME=WORK\n*ELASTIC\n" << c.eMpa << ", " << c.nu << "\n";
    if (c.rateSensitive()) {
        // σ = K ε^n (ε̇/ε̇₀)^m as Norton time hardening, ε̇ = A σ^N t^M with N = 1/(m + n),
        // M = −n/(m + n), A = (K ε̇₀^(−m))^(−N), in place of *PLASTIC: the only form of ccx 2.20
        // that multiplies the flow stress by the rate term (*PLASTIC + *CREEP adds an
        // overstress instead; *RATE DEPENDENT is not read). Exact where a point's rate has been
        // constant since t = 0 (then ε = ε̇t); elsewhere it hardens with ε̇t, not ε, and starts
        // from zero yield stress (docs/fe.md, "Rate dependence").
        const double N = 1 / (c.m + c.n), A = std::pow(c.kMpa * std::pow(c.rate0, -c.m), -N);
        // Below this A ccx 2.20 integrates the law low without a message (one element at a
        // constant rate: exact at A 1.0e-18, 8.6 % low at 5.3e-20, 53 % at 2.6e-22;
        // data/fe/studies/rate/results.md, small_a): K 500 with ε̇₀ 1 /s needs n + m ≥ 0.15.
        if (A < kNortonAMin)
            throw std::invalid_argument("fe: Norton A " + numberText("%.3g", A) +
                                        " below 1e-18, which ccx 2.20 integrates wrongly: raise n + m or ε̇₀");
        o << "*CREEP,LAW=NORTON\n" << A << ", " << N << ", " << -c.n * N << "\n";
    } else {
        o << "*PLASTIC\n";
        // σ = K (0.002 + ε_p)^n, tabulated geometrically up to ε_p = 5.
        std::vector<double> eps{0.0};
        for (double x = 1e-4; x < 5.0001; x *= 1.35) eps.push_back(x);
        eps.push_back(5.0);
        for (double ep : eps) o << c.kMpa * std::pow(0.002 + ep, c.n) << ", " << ep << "\n";
    }
    o << "*MATERIAL,NAME=TOOL\n*ELASTIC\n"
      << 1e7 << ", 0.3\n"
      << "*SOLID SECTION,ELSET=SPEC,MATERIAL=WORK\n*SOLID SECTION,ELSET=PLATEN,MATERIAL=TOOL\n"
      << "*SURFACE INTERACTION,NAME=SI\n*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=LINEAR\n"
      << c.contactSlope << ", 0.1\n*FRICTION\n"
      << c.mu << ", " << c.stickSlope << "\n"
      << "*CONTACT PAIR,INTERACTION=SI,TYPE=" << (c.contact == "surface" ? "SURFACE" : "NODE")
      << " TO SURFACE\nSLAVE, MASTER\n"
      << "*BOUNDARY\nAXIS, 1, 1\nMID, 2, 2\nPLATENN, 1, 2\n"
      << "*TIME POINTS,NAME=SNAP\n";
    const double t = stepTime(c);
    for (double r : outputReductions(c)) o << numberText("%.10g", r / c.reductionMax * t) << "\n";
    const double stroke = z0 * 2 * c.reductionMax / 2; // quarter model: half the stroke
    if (c.rateSensitive()) {
        // *VISCO applies a boundary without an amplitude in full at its first increment: the
        // stroke runs under a ramp, a constant press speed over the step time. Time hardening's
        // rate A σ^N t^M is singular at t = 0 (M < 0): a first increment of 0.005 of the step
        // diverges as the end face meets the platen, one of kViscoIncInit does not.
        o << "*AMPLITUDE,NAME=PRESS\n0, 0\n"
          << t << ", 1\n"
          << "*STEP,NLGEOM,INC=100000\n*VISCO,CETOL=" << c.creepTol << "\n"
          << std::min(c.incInit, kViscoIncInit) * t << ", " << t << ", " << c.incMin * t << ", " << c.incMax * t << "\n"
          << "*BOUNDARY,AMPLITUDE=PRESS\nPLATENN, 2, 2, " << -stroke << "\n";
    } else
        o << "*STEP,NLGEOM,INC=100000\n*STATIC\n"
          << c.incInit << ", 1.0, " << c.incMin << ", " << c.incMax << "\n"
          << "*BOUNDARY\nPLATENN, 2, 2, " << -stroke << "\n";
    o << "*NODE FILE,TIME POINTS=SNAP\nU\n"
      << "*NODE PRINT,NSET=PLATENN,TOTALS=ONLY\nRF\n"
      << "*END STEP\n";
    return o.str();
}

std::vector<double> outputReductions(const FeCase &c)
{
    std::vector<double> r;
    for (double x : c.reductions)
        if (x <= c.reductionMax + 1e-12) r.push_back(x);
    if (c.trackStep > 0)
        for (int k = 1; k * c.trackStep <= c.reductionMax + 1e-9; ++k)
            r.push_back(std::round(k * c.trackStep * 1e6) / 1e6);
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end(), [](double a, double b) { return std::fabs(a - b) < 1e-9; }), r.end());
    return r;
}

Radii computeRadii(const FeCase &c, const FeMesh &m, const NodeXY &coords, const NodeXY &disp, double reduction,
                   double gapTolMm)
{
    Radii r;
    r.reduction = reduction;
    const double zPlaten = c.h0Mm / 2 * (1 - reduction);
    auto pos = [&](int id) {
        const auto ci = coords.find(id);
        const auto di = disp.find(id);
        if (ci == coords.end() || di == disp.end()) throw std::runtime_error("fe: node missing in results");
        return std::pair<double, double>{ci->second.first + di->second.first, ci->second.second + di->second.second};
    };
    r.riMm = pos(m.cornerNode()).first;
    r.roMm = r.riMm;
    r.roInterpMm = r.riMm;
    // Walk down the former lateral surface from the corner: the nodes still on the platen
    // form the immigrated contact area; the first node off it ends it.
    const int top = m.rows() - 1;
    int last = top;
    for (int j = top - 1; j >= 0; --j) {
        const auto p = pos(m.lateralNode(j));
        if (zPlaten - p.second <= gapTolMm) {
            last = j;
            r.roMm = std::max(r.roMm, p.first);
            ++r.contactNodes;
        } else
            break;
    }
    // Sub-node edge: near a tangent contact edge the gap grows quadratically with distance,
    // so sqrt(gap) is linear in r; extrapolate it to zero from the next two free nodes,
    // clamped to the segment between the last contact node and the first free one.
    if (last >= 2) {
        const auto a = pos(m.lateralNode(last));
        const auto b = pos(m.lateralNode(last - 1));
        const auto cc = pos(m.lateralNode(last - 2));
        const double gb = std::sqrt(std::max(0.0, zPlaten - b.second));
        const double gc = std::sqrt(std::max(0.0, zPlaten - cc.second));
        double edge = a.first;
        if (gc > gb + 1e-12 && b.first != cc.first) {
            // Parametrise along the surface polyline: s from b towards c.
            const double t = -gb / (gc - gb); // ≤ 0: behind b, towards a
            const double s = 1 + t;           // position on a→b (0 at a, 1 at b)
            const double sc = std::clamp(s, 0.0, 1.0);
            edge = a.first + sc * (b.first - a.first);
        }
        r.roInterpMm = std::max(r.roMm, edge);
    }
    for (int j = 0; j <= top; ++j) r.rMaxMm = std::max(r.rMaxMm, pos(m.lateralNode(j)).first);
    return r;
}

} // namespace icacam::host::fe
