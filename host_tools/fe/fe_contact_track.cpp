#include "fe_contact_track.h"

#include <algorithm>
#include <cmath>

namespace icacam::host::fe {

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
        int low = top;
        while (low > 0 && fr.gapMm[size_t(low - 1)] <= tolMm) --low;
        for (int j = reached - 1; j >= low; --j) {
            // Joined between frame f-1 and f. The side leaves the platen tangentially, so a
            // node's gap grows with the square of its distance from the edge, and √gap closes
            // about linearly in reduction: interpolate that to √tol.
            double at = fr.reduction;
            if (f > 0) {
                const SideFrame &pv = frames[f - 1];
                const double x0 = std::sqrt(std::max(0.0, pv.gapMm[size_t(j)]));
                const double x1 = std::sqrt(std::max(0.0, fr.gapMm[size_t(j)]));
                const double xt = std::sqrt(tolMm);
                if (x0 > xt && x0 > x1)
                    at = pv.reduction + (fr.reduction - pv.reduction) * std::clamp((x0 - xt) / (x0 - x1), 0.0, 1.0);
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

double trackedContactEdge(const std::vector<SideFrame> &frames, const std::vector<double> &touchdown, std::size_t k)
{
    const SideFrame &fr = frames[k];
    const int top = int(fr.rMm.size()) - 1;
    const double red = fr.reduction;
    // a: lowest node touched by now; b: the next one down.
    int a = top;
    while (a > 0 && touchdown[size_t(a - 1)] >= 0 && touchdown[size_t(a - 1)] <= red + 1e-12) --a;
    if (a == top || a == 0) return fr.rMm[size_t(a)]; // no fold yet, or the whole side is down
    const int b = a - 1;
    double tb = touchdown[size_t(b)];
    if (tb < 0) {
        // b has not touched within the frames: extrapolate its gap's closing rate.
        if (k == 0) return fr.rMm[size_t(a)];
        const SideFrame &pv = frames[k - 1];
        const double x0 = std::sqrt(std::max(0.0, pv.gapMm[size_t(b)]));
        const double x1 = std::sqrt(std::max(0.0, fr.gapMm[size_t(b)]));
        const double rate = (x0 - x1) / (red - pv.reduction); // √gap, as in touchdownReductions
        if (!(rate > 0)) return fr.rMm[size_t(a)];
        tb = red + x1 / rate;
    }
    const double ta = touchdown[size_t(a)];
    const double phi = tb > ta ? std::clamp((red - ta) / (tb - ta), 0.0, 1.0) : 0.0;
    return fr.rMm[size_t(a)] + phi * (fr.rMm[size_t(b)] - fr.rMm[size_t(a)]);
}

} // namespace icacam::host::fe
