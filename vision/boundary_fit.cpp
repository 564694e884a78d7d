#include "boundary_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace icacam::vision {

double BoundaryFit::radiusAt(double theta) const
{
    double r = a0;
    for (int k = 1; k <= harmonics; ++k) r += a[k] * std::cos(k * theta) + b[k] * std::sin(k * theta);
    return r;
}

namespace {

constexpr int kMaxTerms = 2 * BoundaryFit::kMaxHarmonics + 1;
constexpr int kMaxRays = 1024;

// Solves the (2K+1)-term least-squares problem on the kept points by normal equations
// (well conditioned: the basis is near-orthogonal on evenly spaced rays).
bool solve(const double *theta, const double *r, const bool *keep, int n, int K, BoundaryFit *f)
{
    const int m = 2 * K + 1;
    double A[kMaxTerms][kMaxTerms + 1] = {};
    double basis[kMaxTerms];
    for (int i = 0; i < n; ++i) {
        if (!keep[i]) continue;
        basis[0] = 1;
        for (int k = 1; k <= K; ++k) {
            basis[2 * k - 1] = std::cos(k * theta[i]);
            basis[2 * k] = std::sin(k * theta[i]);
        }
        for (int p = 0; p < m; ++p) {
            for (int q = 0; q < m; ++q) A[p][q] += basis[p] * basis[q];
            A[p][m] += basis[p] * r[i];
        }
    }
    for (int c = 0; c < m; ++c) { // Gaussian elimination with partial pivoting
        int piv = c;
        for (int rr = c + 1; rr < m; ++rr)
            if (std::fabs(A[rr][c]) > std::fabs(A[piv][c])) piv = rr;
        if (std::fabs(A[piv][c]) < 1e-9) return false;
        if (piv != c)
            for (int q = 0; q <= m; ++q) std::swap(A[c][q], A[piv][q]);
        for (int rr = 0; rr < m; ++rr) {
            if (rr == c) continue;
            const double g = A[rr][c] / A[c][c];
            for (int q = c; q <= m; ++q) A[rr][q] -= g * A[c][q];
        }
    }
    f->harmonics = K;
    f->a0 = A[0][m] / A[0][0];
    for (int k = 1; k <= BoundaryFit::kMaxHarmonics; ++k) f->a[k] = f->b[k] = 0;
    for (int k = 1; k <= K; ++k) {
        f->a[k] = A[2 * k - 1][m] / A[2 * k - 1][2 * k - 1];
        f->b[k] = A[2 * k][m] / A[2 * k][2 * k];
    }
    return true;
}

double medianOf(double *v, int n)
{
    std::nth_element(v, v + n / 2, v + n);
    return v[n / 2];
}

} // namespace

bool fitBoundary(const EdgeSample *points, const double *radiusPx, const bool *valid, int n,
                 double centreX, double centreY, const FitOptions &opt, BoundaryFit *out)
{
    (void)points;
    if (n > kMaxRays || n < 8) return false;
    double theta[kMaxRays], work[kMaxRays];
    bool keep[kMaxRays];
    int nValid = 0;
    for (int i = 0; i < n; ++i) {
        theta[i] = 2.0 * std::numbers::pi * i / n;
        if (valid[i]) work[nValid++] = radiusPx[i];
    }
    if (nValid < 8) return false;
    // Gross outliers (a stain edge, the other boundary) first: far from the median radius.
    const double med = medianOf(work, nValid);
    for (int i = 0; i < n; ++i) keep[i] = valid[i] && std::fabs(radiusPx[i] - med) < 0.08 * med;

    BoundaryFit f;
    double sigma = 0;
    int used = 0;
    for (int pass = 0; pass < 4; ++pass) {
        used = 0;
        for (int i = 0; i < n; ++i) used += keep[i];
        const int K = std::min({opt.maxHarmonics, BoundaryFit::kMaxHarmonics, pass == 0 ? 2 : 99,
                                std::max(1, used / 8)});
        if (used < 8 || !solve(theta, radiusPx, keep, n, K, &f)) return false;
        int m = 0;
        for (int i = 0; i < n; ++i)
            if (keep[i]) work[m++] = std::fabs(radiusPx[i] - f.radiusAt(theta[i]));
        sigma = 1.4826 * medianOf(work, m);
        const double limit = std::max(opt.minRejectPx, opt.rejectSigma * sigma);
        for (int i = 0; i < n; ++i)
            keep[i] = valid[i] && std::fabs(radiusPx[i] - f.radiusAt(theta[i])) <= limit;
    }
    used = 0;
    double ss = 0;
    for (int i = 0; i < n; ++i) {
        if (!keep[i]) continue;
        const double e = radiusPx[i] - f.radiusAt(theta[i]);
        ss += e * e;
        ++used;
    }
    f.used = used;
    f.scatterPx = std::sqrt(ss / std::max(1, used - (2 * f.harmonics + 1)));
    f.coverage = double(used) / n;
    // Area of the polar curve: ½∮ r² dθ = π (a0² + ½ Σ (a_k² + b_k²)) (Parseval).
    double power = f.a0 * f.a0;
    for (int k = 1; k <= f.harmonics; ++k) power += 0.5 * (f.a[k] * f.a[k] + f.b[k] * f.b[k]);
    f.rEqPx = std::sqrt(power);
    // Adjacent rays share pixels through the angular smoothing: about half are independent.
    f.rEqSigmaPx = f.scatterPx * std::sqrt(2.0 / std::max(1, used));
    // Second harmonic: r ≈ a0 + c2 cos 2(θ − φ); an ellipse of axes a0 ± c2.
    const double c2 = std::hypot(f.a[2], f.b[2]);
    f.ellipticity = f.harmonics >= 2 && f.a0 > 0 ? 2 * c2 / (f.a0 + c2) : 0;
    f.axisDeg = 0.5 * std::atan2(f.b[2], f.a[2]) * 180.0 / std::numbers::pi;
    f.centreX = centreX + f.a[1];
    f.centreY = centreY + f.b[1];
    *out = f;
    return true;
}

} // namespace icacam::vision
