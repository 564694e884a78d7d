#include "vision/narrow_ring.h"

#include <algorithm>
#include <cmath>

namespace icacam::vision {

namespace {

// The profile's reach about the contact edge: a ring up to 9 px and the blur on either side.
constexpr int kInside = 13, kOutside = 7;
constexpr int kMaxPoints = kInside + kOutside + 1;
// The width's error beyond the fit's own: the rendered and real steps are not exactly
// Gaussian-blurred steps, and the ICA's level is not flat (rolled-over turning marks).
constexpr double kModelWidthPx = 0.5;
// Widest ring taken: the original face's level needs a few pixels inside its step.
constexpr double kMaxWidthPx = 8.0;
// Where the face's own level is read: from beyond the fit's reach to the profile's start,
// in windows of 8 px every 4 px.
constexpr int kFaceFrom = 16, kFaceWindow = 8;
// The original face's step must be a visible one (as low_contrast asks of any edge: 5 grey
// levels, in the profile's Q8 units), and a clipped sample makes a step no blurred step.
constexpr double kMinInnerStep = 5 * 256;
constexpr int32_t kClipped = 254 * 256;

double phi(double z)
{
    return 0.5 * std::erfc(-z * 0.7071067811865476);
}

struct Profile {
    double x[kMaxPoints], p[kMaxPoints];
    int n = 0;
    double sumP2 = 0;
};

// Least squares of p on the given basis columns (1 plus up to two steps): the residual sum
// of squares, and the coefficients.
double solve(const Profile &pr, const double *f1, const double *f2, double coef[3])
{
    const int k = f2 ? 3 : 2;
    double g[3][3] = {}, r[3] = {};
    for (int i = 0; i < pr.n; ++i) {
        const double f[3] = {1.0, f1[i], f2 ? f2[i] : 0.0};
        for (int a = 0; a < k; ++a) {
            r[a] += f[a] * pr.p[i];
            for (int b = 0; b < k; ++b) g[a][b] += f[a] * f[b];
        }
    }
    // Gaussian elimination with partial pivoting on the k × k system.
    for (int c = 0; c < k; ++c) {
        int piv = c;
        for (int a = c + 1; a < k; ++a)
            if (std::fabs(g[a][c]) > std::fabs(g[piv][c])) piv = a;
        if (std::fabs(g[piv][c]) < 1e-12) return 1e300;
        if (piv != c) {
            for (int b = 0; b < k; ++b) std::swap(g[c][b], g[piv][b]);
            std::swap(r[c], r[piv]);
        }
        for (int a = c + 1; a < k; ++a) {
            const double q = g[a][c] / g[c][c];
            for (int b = c; b < k; ++b) g[a][b] -= q * g[c][b];
            r[a] -= q * r[c];
        }
    }
    double rhs[3] = {r[0], r[1], r[2]};
    for (int c = k - 1; c >= 0; --c) {
        double v = rhs[c];
        for (int b = c + 1; b < k; ++b) v -= g[c][b] * coef[b];
        coef[c] = v / g[c][c];
    }
    if (k == 2) coef[2] = 0;
    double ssr = 0;
    for (int i = 0; i < pr.n; ++i) {
        const double e = pr.p[i] - coef[0] - coef[1] * f1[i] - (f2 ? coef[2] * f2[i] : 0.0);
        ssr += e * e;
    }
    return ssr;
}

struct TwoStep {
    double xi = 0, xo = 0, s = 1, ssr = 1e300, coef[3] = {};
};

TwoStep evaluate(const Profile &pr, double xi, double xo, double s)
{
    double f1[kMaxPoints], f2[kMaxPoints];
    for (int i = 0; i < pr.n; ++i) {
        f1[i] = phi((pr.x[i] - xi) / s);
        f2[i] = phi((pr.x[i] - xo) / s);
    }
    TwoStep t;
    t.xi = xi, t.xo = xo, t.s = s;
    t.ssr = solve(pr, f1, f2, t.coef);
    return t;
}

} // namespace

NarrowRingFit fitNarrowRing(const int32_t *profile, int count, int edgeIndex, int outerSign, double noise)
{
    NarrowRingFit out;
    Profile pr;
    for (int k = std::max(0, edgeIndex - kInside); k <= std::min(count - 1, edgeIndex + kOutside); ++k) {
        pr.x[pr.n] = k - edgeIndex;
        pr.p[pr.n] = profile[k];
        ++pr.n;
    }
    if (pr.n < 12) return out;
    for (int i = 0; i < pr.n; ++i)
        if (pr.p[i] >= kClipped) return out;

    constexpr double kBlurs[] = {0.5, 0.65, 0.8, 1.0, 1.25, 1.55, 1.9, 2.4};
    // One step: the model the second must beat.
    double single = 1e300;
    for (double s : kBlurs)
        for (double xo = -3; xo <= 3.001; xo += 0.25) {
            double f1[kMaxPoints], coef[3];
            for (int i = 0; i < pr.n; ++i) f1[i] = phi((pr.x[i] - xo) / s);
            single = std::min(single, solve(pr, f1, nullptr, coef));
        }
    // Two steps on a coarse grid, the best for each blur kept; each refined by a pattern
    // search (on a narrow ring blur, width and step heights trade against each other, so
    // the coarse grid's best blur need not hold the best fit), the best of them taken.
    constexpr int kBlurCount = int(sizeof(kBlurs) / sizeof(kBlurs[0]));
    TwoStep start[kBlurCount];
    for (int b = 0; b < kBlurCount; ++b)
        for (double xo = -3; xo <= 3.001; xo += 0.25)
            for (double w = 0.75; w <= 9.001; w += 0.25) {
                const TwoStep t = evaluate(pr, xo - w, xo, kBlurs[b]);
                if (t.ssr < start[b].ssr && t.coef[2] * outerSign > 0) start[b] = t;
            }
    TwoStep best;
    for (TwoStep t : start) {
        if (t.ssr >= 1e299) continue;
        double hx = 0.25, hs = 0.08;
        for (int iteration = 0; hx > 0.004 && iteration < 200; ++iteration) {
            bool moved = false;
            const double trial[6][3] = {{hx, 0, 0}, {-hx, 0, 0}, {0, hx, 0}, {0, -hx, 0}, {0, 0, hs}, {0, 0, -hs}};
            for (const auto &dv : trial) {
                const double xi = t.xi + dv[0], xo = t.xo + dv[1], bl = t.s * (1 + dv[2]);
                if (xo - xi < 0.5 || bl < 0.3) continue;
                const TwoStep c = evaluate(pr, xi, xo, bl);
                if (c.ssr < t.ssr && c.coef[2] * outerSign > 0) {
                    t = c;
                    moved = true;
                }
            }
            if (!moved) hx *= 0.5, hs *= 0.5;
        }
        if (t.ssr < best.ssr) best = t;
    }
    if (best.ssr >= 1e299) return out;

    // The second step must earn its place, and stand well above the noise.
    const double dof = std::max(1, pr.n - 6);
    const double resid = std::sqrt(best.ssr / dof);
    const double level = std::max(noise, resid);
    if (!(single >= 4 * best.ssr) || std::fabs(best.coef[1]) < std::max(4 * level, kMinInnerStep)) return out;
    // Two steps closer than their blur are one edge of another shape, not a ring.
    if (best.xo - best.xi > kMaxWidthPx || best.xo - best.xi < best.s) return out;
    // Inside the inner step lies the original face: its level all the way in must be the
    // fit's innermost one. On a wide ring the fit's inner step is a mark on the ICA, and
    // farther in, past the real edge, the face's level differs.
    int windows = 0;
    for (int from = 0; from + kFaceWindow <= edgeIndex - kFaceFrom; from += kFaceWindow / 2) {
        double face = 0;
        for (int k = from; k < from + kFaceWindow; ++k) face += profile[k];
        face /= kFaceWindow;
        if (std::fabs(face - best.coef[0]) > 0.3 * std::fabs(best.coef[1])) return out;
        ++windows;
    }
    if (windows == 0) return out;

    // The width's statistical error from the curvature of the residual profile along it:
    // at each trial width the contact edge's place and the blur are refitted (on a narrow
    // ring width, blur and step heights trade against each other), and the model's error.
    auto profileAt = [&](double w) {
        double m = 1e300;
        for (int i = -6; i <= 6; ++i)
            for (int j = -3; j <= 3; ++j) {
                const double xo = best.xo + 0.05 * i, bl = best.s * (1 + 0.04 * j);
                m = std::min(m, evaluate(pr, xo - w, xo, bl).ssr);
            }
        return m;
    };
    const double d = 0.25, w0 = best.xo - best.xi;
    const double curv = (profileAt(w0 + d) + profileAt(std::max(0.25, w0 - d)) - 2 * best.ssr) / (d * d);
    const double stat = curv > 0 ? std::sqrt(2 * best.ssr / dof / curv) : w0;

    out.found = true;
    out.innerPx = best.xi;
    out.outerPx = best.xo;
    out.blurPx = best.s;
    out.innerStep = best.coef[1];
    out.sigmaWidthPx = std::hypot(stat, kModelWidthPx);
    return out;
}

} // namespace icacam::vision
