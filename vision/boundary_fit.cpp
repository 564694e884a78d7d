#include "vision/boundary_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vision/angle_table.h"

namespace icacam::vision {

double BoundaryFit::radiusAt(double theta) const
{
    return radiusAt(std::cos(theta), std::sin(theta));
}

double BoundaryFit::radiusAt(double c1, double s1) const
{
    // cos kθ and sin kθ by the angle-addition recurrence from cos θ, sin θ.
    double r = a0, ck = 1, sk = 0;
    for (int k = 1; k <= harmonics; ++k) {
        const double c = ck * c1 - sk * s1;
        sk = sk * c1 + ck * s1;
        ck = c;
        r += a[k] * ck + b[k] * sk;
    }
    return r;
}

void radiiAt(const BoundaryFit &fit, const double *cosT, const double *sinT, int n, double *out)
{
    constexpr int kChunk = 64;
    double ck[kChunk], sk[kChunk];
    for (int base = 0; base < n; base += kChunk) {
        const int m = std::min(kChunk, n - base);
        const double *c1 = cosT + base, *s1 = sinT + base;
        double *r = out + base;
        for (int i = 0; i < m; ++i) r[i] = fit.a0, ck[i] = 1, sk[i] = 0;
        for (int k = 1; k <= fit.harmonics; ++k) {
            const double ak = fit.a[k], bk = fit.b[k];
            for (int i = 0; i < m; ++i) {
                const double c = ck[i] * c1[i] - sk[i] * s1[i];
                sk[i] = sk[i] * c1[i] + ck[i] * s1[i];
                ck[i] = c;
                r[i] += ak * ck[i] + bk * sk[i];
            }
        }
    }
}

namespace {

constexpr int kMaxRays = 1024;

constexpr int kTable = AngleTable::kSize;

double medianOf(double *v, int n)
{
    std::nth_element(v, v + n / 2, v + n);
    return v[n / 2];
}

} // namespace

bool fitBoundary(const double *radiusPx, const bool *valid, int n, double centreX, double centreY,
                 const FitOptions &opt, BoundaryFit *out, double *curveOut)
{
    if (n > kMaxRays || n < 8) return false;
    // The rays are evenly spaced, so the least-squares Fourier fit with some rays missing is
    // found by imputation: fill the missing rays with the current curve and take the DFT
    // (an EM iteration that converges to the least-squares solution). O(n·K) per pass.
    if (kTable % n != 0) return false; // ray counts must divide the table (32, 64, 256 …)
    const AngleTable &T = angleTable();
    const int stride = kTable / n;
    double work[kMaxRays], filled[kMaxRays], pairSum[kMaxRays / 2], pairDiff[kMaxRays / 2];
    bool keep[kMaxRays];
    int nValid = 0;
    for (int i = 0; i < n; ++i)
        if (valid[i]) work[nValid++] = radiusPx[i];
    if (nValid < 8) return false;
    // Gross outliers (a stain edge, the other boundary) first: far from the median radius.
    const double med = medianOf(work, nValid);
    for (int i = 0; i < n; ++i) keep[i] = valid[i] && std::fabs(radiusPx[i] - med) < 0.08 * med;
    if (opt.medianRejectSigma > 0) {
        int m = 0;
        for (int i = 0; i < n; ++i)
            if (keep[i]) work[m++] = std::fabs(radiusPx[i] - med);
        if (m < 8) return false;
        const double limit = std::max(opt.minRejectPx, opt.medianRejectSigma * 1.4826 * medianOf(work, m));
        for (int i = 0; i < n; ++i) keep[i] = keep[i] && std::fabs(radiusPx[i] - med) <= limit;
    }

    BoundaryFit f;
    f.a0 = med;
    double curve[kMaxRays]; // the current curve at every ray
    for (int i = 0; i < n; ++i) curve[i] = med;
    // r at ray i: a0 + Σ a_k cos(kθ_i) + b_k sin(kθ_i), with kθ_i looked up mod 2π. Rays i
    // and n − i lie at ±θ (n is a power of two): they share cos kθ and have opposite
    // sin kθ, so each table pair serves two rays. cos kθ_i and sin kθ_i for i ≤ n/2 are
    // gathered once per fit (the table's own values, so every sum is as before): the sweeps
    // then read them in order, and the curve's update vectorises.
    const int half = n / 2;
    const int maxK = std::min({opt.maxHarmonics, BoundaryFit::kMaxHarmonics, (n - 1) / 2});
    double cosK[BoundaryFit::kMaxHarmonics + 1][kTable / 2 + 1], sinK[BoundaryFit::kMaxHarmonics + 1][kTable / 2 + 1];
    for (int k = 1; k <= maxK; ++k) {
        const int dj = k * stride;
        for (int i = 0, j = 0; i <= half; ++i, j = (j + dj) & (kTable - 1)) {
            cosK[k][i] = T.cos[j];
            sinK[k][i] = T.sin[j];
        }
    }
    double upper[kMaxRays / 2]; // curve[n − i] for 1 ≤ i < n/2, in the order of i
    auto updateCurve = [&]() {
        for (int i = 0; i <= half; ++i) curve[i] = f.a0;
        for (int i = 1; i < half; ++i) upper[i] = f.a0;
        for (int k = 1; k <= f.harmonics; ++k) {
            const double ak = f.a[k], bk = f.b[k];
            const double *ck = cosK[k], *sk = sinK[k];
            curve[0] += ak * ck[0] + bk * sk[0];
            curve[half] += ak * ck[half] + bk * sk[half];
            for (int i = 1; i < half; ++i) {
                const double c = ak * ck[i], sn = bk * sk[i];
                curve[i] += c + sn;
                upper[i] += c - sn;
            }
        }
        for (int i = 1; i < half; ++i) curve[n - i] = upper[i];
    };
    int used = 0;
    for (int pass = 0; pass < 3; ++pass) {
        used = 0;
        for (int i = 0; i < n; ++i) used += keep[i];
        const int K = std::min(
            {opt.maxHarmonics, BoundaryFit::kMaxHarmonics, pass == 0 ? 2 : 99, std::max(1, used / 8), (n - 1) / 2});
        if (used < 8) return false;
        // A few imputation sweeps per pass; more where many rays are missing.
        const int sweeps = used == n ? 1 : (pass == 2 ? 2 : 1);
        for (int sweep = 0; sweep < sweeps; ++sweep) {
            for (int i = 0; i < n; ++i) filled[i] = keep[i] ? radiusPx[i] : curve[i];
            BoundaryFit g;
            g.harmonics = K;
            double sum = 0;
            for (int i = 0; i < n; ++i) sum += filled[i];
            g.a0 = sum / n;
            for (int i = 1; i < half; ++i) { // even and odd parts of the ±θ pairs
                pairSum[i] = filled[i] + filled[n - i];
                pairDiff[i] = filled[i] - filled[n - i];
            }
            for (int k = 1; k <= K; ++k) {
                const double *ck = cosK[k], *sk = sinK[k];
                double sa = filled[0] * ck[0] + filled[half] * ck[half];
                double sb = filled[0] * sk[0] + filled[half] * sk[half];
                for (int i = 1; i < half; ++i) {
                    sa += pairSum[i] * ck[i];
                    sb += pairDiff[i] * sk[i];
                }
                g.a[k] = sa * (2.0 / n);
                g.b[k] = sb * (2.0 / n);
            }
            f = g;
            updateCurve();
        }
        // The residuals' robust σ (1.4826 × their median) sets the rejection limit unless the
        // floor minRejectPx is larger. Its term grows with the residual, so the floor holds
        // exactly where half the residuals or more give a term within it: counted on the way,
        // the median is then not needed (on a clean edge, nearly always).
        int m = 0, withinFloor = 0;
        for (int i = 0; i < n; ++i)
            if (keep[i]) {
                const double e = std::fabs(radiusPx[i] - curve[i]);
                work[m++] = e;
                withinFloor += opt.rejectSigma * (1.4826 * e) <= opt.minRejectPx;
            }
        const double limit = withinFloor >= m / 2 + 1
                                 ? opt.minRejectPx
                                 : std::max(opt.minRejectPx, opt.rejectSigma * (1.4826 * medianOf(work, m)));
        for (int i = 0; i < n; ++i) keep[i] = valid[i] && std::fabs(radiusPx[i] - curve[i]) <= limit;
    }
    used = 0;
    double ss = 0;
    for (int i = 0; i < n; ++i) {
        if (!keep[i]) continue;
        const double e = radiusPx[i] - curve[i];
        ss += e * e;
        ++used;
    }
    if (used < 8) return false;
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
    if (curveOut)
        for (int i = 0; i < n; ++i) curveOut[i] = curve[i];
    return true;
}

} // namespace icacam::vision
