#include "host_tools/fe/fe_contact_track.h"

#include <algorithm>
#include <cmath>

namespace icacam::host::fe {

namespace {
// Where a gap that closes as c·(t* − t)^p reaches tol, from samples (t, gap) with t < 0 … 0.
// p = 1 is a side meeting the platen at an angle (the FE runs at high μ: the gap closes
// linearly), p = 2 one leaving it tangentially (gap ∝ distance² from the edge).
double crossingForPower(const double *t, const double *g, double p, double tolMm)
{
    const double y0 = std::pow(g[0], 1 / p), y1 = std::pow(g[1], 1 / p), yt = std::pow(tolMm, 1 / p);
    const double rate = (y1 - y0) / (t[0] - t[1]); // closing per unit reduction
    return rate > 0 ? (y0 - yt) / rate : -1;
}
// How far g^(1/p) is from a straight line through the three samples (its slope change).
double bend(const double *t, const double *g, double p)
{
    const double y0 = std::pow(g[0], 1 / p), y1 = std::pow(g[1], 1 / p), y2 = std::pow(g[2], 1 / p);
    return (y0 - y1) / (t[0] - t[1]) - (y1 - y2) / (t[1] - t[2]);
}

// When node j's gap, still free (> tol) at frame `last`, reaches tol: the power p ∈ [1, 2]
// that makes its last three free gaps lie on c·(t* − t)^p, then that curve's crossing; with
// only two free frames, the mean of the angled and the tangent crossings (they bracket it).
// -1 when the gap does not close.
double predictedTouchdown(const std::vector<SideFrame> &frames, std::size_t j, std::size_t last, double tolMm)
{
    double t[3], g[3];
    int m = 0;
    for (std::size_t f = last + 1; f-- > 0 && m < 3;) {
        const double gap = frames[f].gapMm[j];
        if (!(gap > tolMm)) break;
        t[m] = frames[f].reduction - frames[last].reduction; // 0, then earlier (< 0)
        g[m] = gap;
        ++m;
    }
    double at = -1;
    if (m >= 3) {
        double lo = 1, hi = 2;
        const double bLo = bend(t, g, lo), bHi = bend(t, g, hi);
        double p = std::fabs(bLo) <= std::fabs(bHi) ? lo : hi;
        if ((bLo < 0) != (bHi < 0)) {
            for (int it = 0; it < 40; ++it) {
                const double mid = 0.5 * (lo + hi);
                if ((bend(t, g, mid) < 0) == (bLo < 0))
                    lo = mid;
                else
                    hi = mid;
            }
            p = 0.5 * (lo + hi);
        }
        at = crossingForPower(t, g, p, tolMm);
    } else if (m == 2) {
        const double a1 = crossingForPower(t, g, 1, tolMm), a2 = crossingForPower(t, g, 2, tolMm);
        at = a1 >= 0 && a2 >= 0 ? 0.5 * (a1 + a2) : -1;
    }
    return at < 0 ? -1 : frames[last].reduction + at;
}
} // namespace

namespace {
// The lowest node of the contact zone that grows down from the corner (the last index).
int zoneBottom(const SideFrame &frame, double tolMm)
{
    int low = int(frame.gapMm.size()) - 1;
    while (low > 0 && frame.gapMm[size_t(low - 1)] <= tolMm) --low;
    return low;
}
} // namespace

bool contactZoneBroken(const SideFrame &frame, double tolMm)
{
    const int low = zoneBottom(frame, tolMm);
    for (int j = low - 2; j >= 0; --j)
        if (frame.gapMm[size_t(j)] <= tolMm) return true;
    return false;
}

std::vector<double> touchdownReductions(const std::vector<SideFrame> &frames, double tolMm)
{
    if (frames.empty()) return {};
    const int top = int(frames.front().gapMm.size()) - 1;
    std::vector<double> td(size_t(top + 1), -1.0);
    if (top < 0) return td;
    td[size_t(top)] = 0; // the corner is on the platen from the start
    int reached = top;   // lowest node of the contiguous contact zone so far
    for (size_t f = 0; f < frames.size(); ++f) {
        const SideFrame &fr = frames[f];
        const int low = zoneBottom(fr, tolMm);
        for (int j = reached - 1; j >= low; --j) {
            // Joined between frame f-1 and f: where its gap, followed from the free frames
            // before, reaches tol. Not by interpolating to frame f: there the node already
            // sinks into the penalty contact, so its gap no longer follows the approach.
            double at = fr.reduction;
            if (f > 0) {
                const SideFrame &pv = frames[f - 1];
                double p = predictedTouchdown(frames, size_t(j), f - 1, tolMm);
                if (p < 0) {
                    const double g0 = pv.gapMm[size_t(j)], g1 = std::max(fr.gapMm[size_t(j)], -g0);
                    p = g0 > tolMm && g0 > g1 ? pv.reduction + (fr.reduction - pv.reduction) * (g0 - tolMm) / (g0 - g1)
                                              : fr.reduction;
                }
                at = std::clamp(p, pv.reduction, fr.reduction);
            }
            td[size_t(j)] = at;
        }
        reached = std::min(reached, low);
    }
    // Monotone from the corner down: a later-indexed (higher) node touched no later.
    for (int j = top - 1; j >= 0; --j)
        if (td[size_t(j)] >= 0) td[size_t(j)] = std::max(td[size_t(j)], td[size_t(j + 1)]);
    return td;
}

namespace {
// The edge along one sequence of nodes: `seq` runs from the corner down the side; the edge's
// material position goes from the last node down (a) to the next one (b) linearly in
// reduction between their touchdowns, and its radius is taken at that fraction of the
// deformed segment a–b.
double edgeAlong(const std::vector<SideFrame> &frames, const std::vector<double> &touchdown, std::size_t k,
                 double tolMm, const std::vector<int> &seq)
{
    const SideFrame &fr = frames[k];
    const double red = fr.reduction;
    std::size_t ia = 0;
    while (ia + 1 < seq.size() && touchdown[size_t(seq[ia + 1])] >= 0 && touchdown[size_t(seq[ia + 1])] <= red + 1e-12)
        ++ia;
    const int a = seq[ia];
    if (ia + 1 == seq.size()) return fr.rMm[size_t(a)];
    const int b = seq[ia + 1];
    double tb = touchdown[size_t(b)];
    if (tb < 0) {
        // b has not touched within the frames: predict it from its gap so far.
        tb = predictedTouchdown(frames, size_t(b), k, tolMm);
        if (tb < red) return fr.rMm[size_t(a)];
    }
    const double ta = touchdown[size_t(a)];
    const double phi = tb > ta ? std::clamp((red - ta) / (tb - ta), 0.0, 1.0) : 0.0;
    return fr.rMm[size_t(a)] + phi * (fr.rMm[size_t(b)] - fr.rMm[size_t(a)]);
}
} // namespace

double trackedContactEdge(const std::vector<SideFrame> &frames, const std::vector<double> &touchdown, std::size_t k,
                          double tolMm)
{
    const SideFrame &fr = frames[k];
    const int top = int(fr.rMm.size()) - 1;
    const double red = fr.reduction;
    int a = top; // lowest node touched by now
    while (a > 0 && touchdown[size_t(a - 1)] >= 0 && touchdown[size_t(a - 1)] <= red + 1e-12) --a;
    if (a == top || a == 0) return fr.rMm[size_t(a)]; // no fold yet, or the whole side is down
    const int stride = std::max(1, fr.nodesPerEdge);
    // Quadratic elements: the corner and the mid-side nodes of the side carry different shares
    // of the contact, so their touchdowns alternate early and late (the FE runs show it) and an
    // edge through all nodes jitters by a node's share. Each kind of node alone follows a
    // smooth edge; their mean cancels the alternation. Each sequence starts at the corner.
    double sum = 0;
    for (int cls = 0; cls < stride; ++cls) {
        std::vector<int> seq{top};
        for (int j = top - 1; j >= 0; --j)
            if ((top - j) % stride == cls) seq.push_back(j);
        sum += edgeAlong(frames, touchdown, k, tolMm, seq);
    }
    return sum / stride;
}

} // namespace icacam::host::fe
