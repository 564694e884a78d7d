#include "vision/contact_knee.h"

#include <cmath>
#include <utility>

#include "vision/normal_cdf.h"

namespace icacam::vision {

namespace {

constexpr int kMaxPoints = 40;
// The knee is searched on a coarse grid, then refined about the best coarse trial.
constexpr double kCoarseStepPx = 0.25, kFineStepPx = 0.05;
constexpr int kBases = 3; // level, step, fall

struct KneeTrial {
    double sse = 0;
    double step = 0, slope = 0;
    bool ok = false;
};

// Solves the normal equations a·x = b in place (Gaussian elimination, partial pivoting);
// false when they are singular.
bool solve(double a[kBases][kBases], double *b)
{
    const int n = kBases;
    for (int c = 0; c < n; ++c) {
        int piv = c;
        for (int r = c + 1; r < n; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
        if (!(std::fabs(a[piv][c]) > 1e-12)) return false;
        for (int k = 0; k < n; ++k) std::swap(a[c][k], a[piv][k]);
        std::swap(b[c], b[piv]);
        for (int r = c + 1; r < n; ++r) {
            const double f = a[r][c] / a[c][c];
            for (int k = c; k < n; ++k) a[r][k] -= f * a[c][k];
            b[r] -= f * b[c];
        }
    }
    for (int c = n - 1; c >= 0; --c) {
        for (int k = c + 1; k < n; ++k) b[c] -= a[c][k] * b[k];
        b[c] /= a[c][c];
    }
    return true;
}

// Least squares of p on 1, Φ(z) and σ(z·Φ(z) + φ(z)), z = (x − t)/σ: a level, a step at t and
// a straight fall from t, each convolved with the blur (the Gaussian of a unit step and of a
// unit ramp beyond t). A fall that steepens (a parabola beyond t) fits the rendered
// photographs worse: the shading bends back within the window.
KneeTrial fitAt(const double *x, const double *p, int n, double t, double blur)
{
    double f[kBases][kMaxPoints];
    double a[kBases][kBases] = {}, b[kBases] = {};
    for (int i = 0; i < n; ++i) {
        const double z = (x[i] - t) / blur;
        const double c = normalCdf(z);
        f[0][i] = 1, f[1][i] = c, f[2][i] = blur * (z * c + normalPdf(z));
        for (int r = 0; r < kBases; ++r) {
            for (int k = 0; k < kBases; ++k) a[r][k] += f[r][i] * f[k][i];
            b[r] += f[r][i] * p[i];
        }
    }
    KneeTrial tr;
    if (!solve(a, b)) return tr;
    for (int i = 0; i < n; ++i) {
        double e = p[i];
        for (int r = 0; r < kBases; ++r) e -= b[r] * f[r][i];
        tr.sse += e * e;
    }
    tr.step = b[1], tr.slope = b[2], tr.ok = true;
    return tr;
}

} // namespace

ContactKnee locateContactKnee(const int32_t *level, int count, int at, int sign, const ContactKneeWindow &w)
{
    ContactKnee out;
    const int lo = at - w.insideSamples, hi = at + w.outsideSamples;
    if (lo < 0 || hi >= count || hi - lo + 1 > kMaxPoints || hi - lo < 4 || !(w.blurPx > 0)) return out;
    double x[kMaxPoints], p[kMaxPoints];
    int n = 0;
    double mean = 0;
    for (int k = lo; k <= hi; ++k) {
        if (level[k] <= 0) return out; // a sample off the frame: no profile to fit
        x[n] = (k - at) * w.samplePx;
        p[n] = level[k];
        mean += p[n++];
    }
    mean /= n;
    for (int i = 0; i < n; ++i) p[i] -= mean; // the sums stay well conditioned
    const int coarse = int(std::floor((w.searchInPx + w.searchOutPx) / kCoarseStepPx + 1e-9));
    int best = -1;
    KneeTrial bestTrial;
    for (int j = 0; j <= coarse; ++j) {
        const KneeTrial tr = fitAt(x, p, n, -w.searchInPx + j * kCoarseStepPx, w.blurPx);
        if (tr.ok && (best < 0 || tr.sse < bestTrial.sse)) best = j, bestTrial = tr;
    }
    // A knee on the search's bound is one the window does not hold.
    if (best <= 0 || best >= coarse) return out;
    const double centre = -w.searchInPx + best * kCoarseStepPx;
    const int fineHalf = int(kCoarseStepPx / kFineStepPx + 0.5);
    static_assert(kCoarseStepPx / kFineStepPx < 5.5, "the fine trials fit their buffer");
    KneeTrial fine[2 * 5 + 1];
    double sse[2 * 5 + 1];
    int fineBest = fineHalf; // the coarse trial itself
    for (int j = 0; j <= 2 * fineHalf; ++j) {
        fine[j] = fitAt(x, p, n, centre + (j - fineHalf) * kFineStepPx, w.blurPx);
        sse[j] = fine[j].ok ? fine[j].sse : HUGE_VAL;
    }
    for (int j = 0; j <= 2 * fineHalf; ++j)
        if (sse[j] < sse[fineBest]) fineBest = j;
    if (fine[fineBest].ok) bestTrial = fine[fineBest];
    double t = centre + (fineBest - fineHalf) * kFineStepPx;
    if (fineBest > 0 && fineBest < 2 * fineHalf) {
        // The parabola through the best fine trial and its neighbours.
        const double sm = sse[fineBest - 1], s0 = sse[fineBest], sp = sse[fineBest + 1];
        const double den = sm - 2 * s0 + sp;
        if (den > 0) t += 0.5 * kFineStepPx * (sm - sp) / den;
    }
    // The fall beyond the knee goes `sign`'s way, or the fit found none.
    const bool stepHolds =
        w.stepAlone && sign * bestTrial.step > 0 && sign * (bestTrial.step + 2 * w.blurPx * bestTrial.slope) > 0;
    if (!(sign * bestTrial.slope > 0) && !stepHolds) return out;
    out.offsetPx = t;
    out.stepLevel = bestTrial.step;
    out.slope = bestTrial.slope;
    out.residual = std::sqrt(bestTrial.sse / n);
    out.found = true;
    return out;
}

} // namespace icacam::vision
