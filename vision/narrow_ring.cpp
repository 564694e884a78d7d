#include "vision/narrow_ring.h"

#include <algorithm>
#include <cmath>

#include "vision/normal_cdf.h"

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
// A turn back beyond the contact edge: a sample 2 grey levels against the step's way (the
// aligned mean profile's noise is a fraction of a level), from 4 samples out, beyond the
// fall of an edge blurred by up to 1.5 px.
constexpr int32_t kTurnBack = 2 * 256;
constexpr int kTurnFrom = 4;
// A turn straight out of the fall is the outline where the level it reaches holds for 3
// samples (within a third of the rise).
constexpr int kShoulderReach = 3;

double phi(double z)
{
    return normalCdf(z);
}

struct Profile {
    double x[kMaxPoints], p[kMaxPoints];
    int n = 0;
    double mean = 0, sumP2 = 0; // p is kept about its mean (the sums stay well conditioned)
    double count = 0, sumP = 0; // n and Σ p, as the normal equations use them
};

// One blurred step at x over the profile's points, with the sums the normal equations take
// of it alone (Σ f, Σ f², Σ f·p): a trial that keeps a step keeps its sums, and only the
// cross term Σ f1·f2 is summed per trial. Each sum runs over the points in order, so it
// holds the same bits however the sums are grouped.
struct StepBasis {
    double f[kMaxPoints];
    double s = 0, ss = 0, sp = 0;
};

void stepBasis(const Profile &pr, double x, double blur, StepBasis *b)
{
    double s = 0, ss = 0, sp = 0;
    for (int i = 0; i < pr.n; ++i) {
        const double a = phi((pr.x[i] - x) / blur);
        b->f[i] = a;
        s += a, ss += a * a, sp += a * pr.p[i];
    }
    b->s = s, b->ss = ss, b->sp = sp;
}

// Least squares of p on the basis 1, f1 and (if given) f2: the residual sum of squares, and
// the coefficients (1e300 for a singular basis).
double solve(const Profile &pr, const StepBasis &f1, const StepBasis *f2, double coef[3])
{
    const double n = pr.count, s1 = f1.s, s11 = f1.ss, r0 = pr.sumP, r1 = f1.sp;
    if (!f2) {
        const double det = n * s11 - s1 * s1;
        if (std::fabs(det) < 1e-9) return 1e300;
        coef[0] = (r0 * s11 - s1 * r1) / det;
        coef[1] = (n * r1 - s1 * r0) / det;
        coef[2] = 0;
        const double ssr = std::max(0.0, pr.sumP2 - coef[0] * r0 - coef[1] * r1);
        coef[0] += pr.mean;
        return ssr;
    }
    const double s2 = f2->s, s22 = f2->ss, r2 = f2->sp;
    double s12 = 0;
    for (int i = 0; i < pr.n; ++i) s12 += f1.f[i] * f2->f[i];
    // The symmetric 3 × 3 system by Cramer's rule.
    const double c00 = s11 * s22 - s12 * s12, c01 = s2 * s12 - s1 * s22, c02 = s1 * s12 - s2 * s11;
    const double det = n * c00 + s1 * c01 + s2 * c02;
    if (std::fabs(det) < 1e-9) return 1e300;
    const double c11 = n * s22 - s2 * s2, c12 = s1 * s2 - n * s12, c22 = n * s11 - s1 * s1;
    coef[0] = (c00 * r0 + c01 * r1 + c02 * r2) / det;
    coef[1] = (c01 * r0 + c11 * r1 + c12 * r2) / det;
    coef[2] = (c02 * r0 + c12 * r1 + c22 * r2) / det;
    const double ssr = std::max(0.0, pr.sumP2 - coef[0] * r0 - coef[1] * r1 - coef[2] * r2);
    coef[0] += pr.mean;
    return ssr;
}

struct TwoStep {
    double xi = 0, xo = 0, s = 1, ssr = 1e300, coef[3] = {};
};

TwoStep evaluate(const Profile &pr, double xi, double xo, double s)
{
    StepBasis f1, f2;
    stepBasis(pr, xi, s, &f1);
    stepBasis(pr, xo, s, &f2);
    TwoStep t;
    t.xi = xi, t.xo = xo, t.s = s;
    t.ssr = solve(pr, f1, &f2, t.coef);
    return t;
}

// Whether the profile, turned back at sample k against the edge's step, rises (or falls) to
// a level it holds: the outline onto the fixture. A lit shoulder beyond a dark ring turns
// back again within a few samples of its top.
bool holdsAfterTurn(const int32_t *profile, int count, int k, int outerSign)
{
    int top = k;
    while (top + 1 < count && outerSign * (profile[top + 1] - profile[top]) < -kTurnBack) ++top;
    const int32_t rise = -outerSign * (profile[top] - profile[k - 1]);
    for (int j = top + 1; j <= std::min(count - 1, top + kShoulderReach); ++j)
        if (3 * outerSign * (profile[j] - profile[top]) > rise) return false;
    return top + kShoulderReach < count;
}

// The profile around the contact edge, its mean taken out; false where it is clipped or
// too short to fit. Where the profile turns back against the edge's step (outerSign) beyond
// the edge's own fall, it ends before the turn: a barrel band narrower than the reach rises
// again to the outline there, which three levels and two steps do not model, and whose
// residual would leave the one-step model as good as the two. A turn within kTurnFrom
// samples of the edge, straight out of its fall, may be the ring's own far edge (a dark ring
// rising onto a lit shoulder, whose fall was the original face's edge): the profile is then
// taken whole unless the level the turn reaches holds (holdsAfterTurn).
bool profileAround(const int32_t *profile, int count, int edgeIndex, int outerSign, Profile *pr)
{
    int last = std::min(count - 1, edgeIndex + kOutside);
    for (int k = edgeIndex + 1; k <= last; ++k)
        if (outerSign * (profile[k] - profile[k - 1]) < -kTurnBack) {
            if (k >= edgeIndex + kTurnFrom || holdsAfterTurn(profile, count, k, outerSign)) last = k - 1;
            break;
        }
    for (int k = std::max(0, edgeIndex - kInside); k <= last; ++k) {
        if (profile[k] >= kClipped) return false;
        pr->x[pr->n] = k - edgeIndex;
        pr->p[pr->n] = profile[k];
        pr->mean += profile[k];
        ++pr->n;
    }
    if (pr->n < 12) return false;
    pr->mean /= pr->n;
    for (int i = 0; i < pr->n; ++i) {
        pr->p[i] -= pr->mean;
        pr->sumP2 += pr->p[i] * pr->p[i];
    }
    for (int i = 0; i < pr->n; ++i) pr->count += 1, pr->sumP += pr->p[i];
    return true;
}

// One step, the model the second must beat: a pattern search over its place and blur from
// two blurs; the smaller residual.
double singleStepSsr(const Profile &pr)
{
    double single = 1e300;
    constexpr double kSingleBlurs[] = {0.8, 1.8};
    for (double blur : kSingleBlurs) {
        double xo = 0, bl = blur, h = 0.5, hs = 0.15;
        auto ssrAt = [&](double x, double b) {
            StepBasis f1;
            double coef[3];
            stepBasis(pr, x, b, &f1);
            return solve(pr, f1, nullptr, coef);
        };
        double cur = ssrAt(xo, bl);
        for (int iteration = 0; h > 0.01 && iteration < 100; ++iteration) {
            bool moved = false;
            const double trial[4][2] = {{h, 0}, {-h, 0}, {0, hs}, {0, -hs}};
            for (const auto &dv : trial) {
                const double b = bl * (1 + dv[1]);
                if (b < 0.3) continue;
                const double c = ssrAt(xo + dv[0], b);
                if (c < cur) cur = c, xo += dv[0], bl = b, moved = true;
            }
            if (!moved) h *= 0.5, hs *= 0.5;
        }
        single = std::min(single, cur);
    }
    return single;
}

constexpr int kMaxStarts = 4 * 3;

// The coarse grid's step positions: multiples of half a pixel from the innermost inner step
// (x_o −2, width 8) to the outermost outer step (x_o +2).
constexpr double kGridStep = 0.5, kGridFirst = -10.0;
constexpr int kGridPositions = 25;

// Where the two-step search starts (on a narrow ring blur, width and step heights trade
// against each other: one start can end in the wrong valley). With a width from the per-ray
// search, two starts at it; without, the best of a coarse grid for each of four blurs and
// three width ranges. Returns the number of starts.
int twoStepStarts(const Profile &pr, double startWidthPx, int outerSign, TwoStep *start)
{
    constexpr double kGridBlurs[] = {0.6, 0.9, 1.3, 1.9};
    constexpr double kWidthBuckets[] = {1.0, 2.5, 4.5, kMaxWidthPx + 0.5}; // bounds
    int starts = 0;
    if (startWidthPx > 0) {
        for (double s0 : {0.9, 1.6}) start[starts++] = evaluate(pr, -startWidthPx, 0.0, s0);
        return starts;
    }
    // Every grid point's steps lie on the half-pixel grid: each blur's step bases are
    // computed once per position (the same values evaluate() would compute for each pair).
    StepBasis basis[kGridPositions];
    auto at = [&](double x) -> const StepBasis & { return basis[int((x - kGridFirst) / kGridStep + 0.5)]; };
    for (double s0 : kGridBlurs) {
        for (int k = 0; k < kGridPositions; ++k) stepBasis(pr, kGridFirst + k * kGridStep, s0, &basis[k]);
        for (int bucket = 0; bucket < 3; ++bucket) {
            TwoStep &b = start[starts++];
            for (double xo = -2; xo <= 2.001; xo += kGridStep)
                for (double w = kWidthBuckets[bucket]; w < kWidthBuckets[bucket + 1] - 0.001; w += kGridStep) {
                    TwoStep t;
                    t.xi = xo - w, t.xo = xo, t.s = s0;
                    t.ssr = solve(pr, at(t.xi), &at(xo), t.coef);
                    if (t.ssr < b.ssr && t.coef[2] * outerSign > 0) b = t;
                }
        }
    }
    return starts;
}

// A pattern search over (x_i, x_o, s) from one start: at most 25 steps where the per-ray
// search saw the edge (the fit only places it), 100 otherwise.
TwoStep refineTwoStep(const Profile &pr, TwoStep t, bool seen)
{
    // The current point's two step bases: a trial that moves one step alone reuses the
    // other's (two thirds of the trials; the fit's cost is these normal-distribution
    // evaluations). An accepted trial's bases swap in for the current ones.
    StepBasis buf[4];
    StepBasis *f1 = &buf[0], *f2 = &buf[1], *g1 = &buf[2], *g2 = &buf[3];
    stepBasis(pr, t.xi, t.s, f1);
    stepBasis(pr, t.xo, t.s, f2);
    double hx = 0.25, hs = 0.08;
    for (int iteration = 0; hx > (seen ? 0.02 : 0.01) && iteration < (seen ? 25 : 100); ++iteration) {
        bool moved = false;
        const double trial[6][3] = {{hx, 0, 0}, {-hx, 0, 0}, {0, hx, 0}, {0, -hx, 0}, {0, 0, hs}, {0, 0, -hs}};
        for (const auto &dv : trial) {
            const double xi = t.xi + dv[0], xo = t.xo + dv[1], bl = t.s * (1 + dv[2]);
            if (xo - xi < 0.5 || bl < 0.3) continue;
            const bool movesInner = dv[0] != 0 || dv[2] != 0, movesOuter = dv[1] != 0 || dv[2] != 0;
            if (movesInner) stepBasis(pr, xi, bl, g1);
            if (movesOuter) stepBasis(pr, xo, bl, g2);
            TwoStep c;
            c.xi = xi, c.xo = xo, c.s = bl;
            c.ssr = solve(pr, movesInner ? *g1 : *f1, movesOuter ? g2 : f2, c.coef);
            if (c.ssr < t.ssr) {
                t = c;
                moved = true;
                if (movesInner) std::swap(f1, g1);
                if (movesOuter) std::swap(f2, g2);
            }
        }
        if (!moved) hx *= 0.5, hs *= 0.5;
    }
    return t;
}

// Inside the inner step lies the original face: its level all the way in must be the fit's
// innermost one. On a wide ring the fit's inner step is a mark on the ICA, and farther in,
// past the real edge, the face's level differs.
bool faceLevelHolds(const int32_t *profile, int edgeIndex, const TwoStep &best)
{
    int windows = 0;
    for (int from = 0; from + kFaceWindow <= edgeIndex - kFaceFrom; from += kFaceWindow / 2) {
        double face = 0;
        for (int k = from; k < from + kFaceWindow; ++k) face += profile[k];
        face /= kFaceWindow;
        if (std::fabs(face - best.coef[0]) > 0.3 * std::fabs(best.coef[1])) return false;
        ++windows;
    }
    return windows > 0;
}

// The width's statistical error from the curvature of the residual profile along it: at
// each trial width the contact edge's place and the blur are refitted (on a narrow ring
// width, blur and step heights trade against each other).
double widthStatError(const Profile &pr, const TwoStep &best, bool seen, double dof)
{
    const int reach = seen ? 1 : 2;
    auto profileAt = [&](double w) {
        double m = 1e300;
        for (int i = -reach; i <= reach; ++i)
            for (int j = 1 - reach; j <= reach - 1; ++j) {
                const double xo = best.xo + 0.1 * i, bl = best.s * (1 + 0.06 * j);
                m = std::min(m, evaluate(pr, xo - w, xo, bl).ssr);
            }
        return m;
    };
    const double d = 0.25, w0 = best.xo - best.xi;
    const double curv = (profileAt(w0 + d) + profileAt(std::max(0.25, w0 - d)) - 2 * best.ssr) / (d * d);
    return curv > 0 ? std::sqrt(2 * best.ssr / dof / curv) : w0;
}

} // namespace

NarrowRingFit fitNarrowRing(const int32_t *profile, int count, int edgeIndex, int outerSign, double startWidthPx)
{
    NarrowRingFit out;
    Profile pr;
    if (!profileAround(profile, count, edgeIndex, outerSign, &pr)) return out;
    // Where the per-ray search saw the face's edge the profile only places it, and the
    // one-step model need not be beaten.
    const bool seen = startWidthPx > 0;
    const double single = seen ? 1e300 : singleStepSsr(pr);

    TwoStep start[kMaxStarts];
    const int starts = twoStepStarts(pr, startWidthPx, outerSign, start);
    TwoStep best;
    for (int k = 0; k < starts; ++k) {
        if (start[k].ssr >= 1e299) continue;
        const TwoStep t = refineTwoStep(pr, start[k], seen);
        if (t.ssr < best.ssr && t.coef[2] * outerSign > 0) best = t;
    }
    if (best.ssr >= 1e299) return out;

    // The second step must earn its place, and stand well above the noise.
    const double dof = std::max(1, pr.n - 6);
    const double resid = std::sqrt(best.ssr / dof);
    if (!(single >= 4 * best.ssr) || std::fabs(best.coef[1]) < std::max(4 * resid, kMinInnerStep)) return out;
    // Two steps closer than their blur are one edge of another shape, not a ring.
    if (best.xo - best.xi > kMaxWidthPx || best.xo - best.xi < best.s) return out;
    if (!faceLevelHolds(profile, edgeIndex, best)) return out;

    out.found = true;
    out.innerPx = best.xi;
    out.outerPx = best.xo;
    out.blurPx = best.s;
    out.innerStep = best.coef[1];
    // The width's statistical error and the model's.
    out.sigmaWidthPx = std::hypot(widthStatError(pr, best, seen, dof), kModelWidthPx);
    return out;
}

} // namespace icacam::vision
