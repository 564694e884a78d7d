#include "vision/profile_zones.h"

#include <algorithm>
#include <cstdlib>

#include "vision/radial_profile.h"

namespace icacam::vision {

namespace {
// One grey level in the profile's Q8 units.
constexpr int32_t kGrey = 256;
// A level's two halves may differ by this much (grain, stains, vignetting)…
constexpr int32_t kLevelTolerance = 3 * kGrey;
// …or by this fraction of the step that bounds it, whichever is more.
constexpr double kLevelToleranceOfStep = 0.15;
// A step this many times another's is not its neighbour in the same zone structure.
constexpr double kMuchStronger = 2.5;

bool isExtremum(const int32_t *d, int i)
{
    const int32_t a = std::abs(d[i]);
    return a > 0 && a >= std::abs(d[i - 1]) && a > std::abs(d[i + 1]) && (d[i] > 0) == (d[i - 1] >= 0) &&
           (d[i] > 0) == (d[i + 1] >= 0);
}

bool usable(const uint16_t *level, int count, int i)
{
    return i >= 0 && i < count && level[i] != kOutsideFrame;
}
} // namespace

ProfileEdges findProfileEdges(const uint16_t *level, const int32_t *deriv, int count, int lo, int hi,
                              int32_t minStrength)
{
    ProfileEdges out;
    lo = std::max(lo, 1);
    hi = std::min(hi, count - 2);
    // The ripple a groove or a stain leaves scales with the light on the specimen, not with
    // the fixture's: the share is taken of the strongest step inside the outline (the
    // outermost step at least half as strong as the profile's strongest), whose other side
    // may be a fixture far brighter or darker than anything on the specimen. Where a clear
    // step (one the profile's strongest would keep) still lies beyond that step, it is not
    // the outline but the specimen's own contact edge, with a faint outline beyond it: the
    // share is then of it, or a turned ring's grooves would pass for zones' edges.
    int32_t strongest = 0;
    for (int i = lo; i <= hi; ++i)
        if (isExtremum(deriv, i)) strongest = std::max(strongest, std::abs(deriv[i]));
    const int32_t clear = int32_t(kRippleShareOfStep * strongest);
    int outline = hi;
    while (outline > lo && !(isExtremum(deriv, outline) && 2 * std::abs(deriv[outline]) >= strongest)) --outline;
    bool beyond = false;
    for (int i = outline + 1; i <= hi; ++i) beyond = beyond || (isExtremum(deriv, i) && std::abs(deriv[i]) >= clear);
    int32_t strongestInside = 0;
    for (int i = lo; i < outline && !beyond; ++i)
        if (isExtremum(deriv, i)) strongestInside = std::max(strongestInside, std::abs(deriv[i]));
    const int32_t floor =
        std::max(minStrength, int32_t(kRippleShareOfStep * (strongestInside > 0 ? strongestInside : strongest)));
    for (int i = lo; i <= hi; ++i) {
        if (!isExtremum(deriv, i) || std::abs(deriv[i]) < floor) continue;
        ProfileEdge e;
        e.index = i;
        e.sign = deriv[i] > 0 ? 1 : -1;
        e.strength = std::abs(deriv[i]);
        e.flankLo = e.flankHi = i;
        while (e.flankLo - 1 >= 0 && 4 * e.sign * deriv[e.flankLo - 1] >= e.strength) --e.flankLo;
        while (e.flankHi + 1 < count && 4 * e.sign * deriv[e.flankHi + 1] >= e.strength) ++e.flankHi;
        // An extremum on the flank of a stronger one of the same sign is its shoulder.
        if (out.count > 0) {
            ProfileEdge &prev = out.edge[out.count - 1];
            if (prev.sign == e.sign && prev.flankHi >= e.index) {
                if (prev.strength >= e.strength) continue;
                --out.count;
            }
        }
        const int a = e.flankLo - 1, b = e.flankHi + 1;
        if (!usable(level, count, a) || !usable(level, count, b)) continue;
        if (e.sign * (int32_t(level[b]) - int32_t(level[a])) < kMinZoneStep) continue;
        if (out.count == ProfileEdges::kCapacity) {
            out.full = true;
            break;
        }
        out.edge[out.count++] = e;
    }
    return out;
}

ZoneKind zoneBeyond(const uint16_t *level, int count, const ProfileEdges &edges, int k, int window)
{
    const ProfileEdge &e = edges.edge[k];
    const int a = e.flankHi + 1;
    int b = std::min(count - 1, e.flankHi + window);
    if (k + 1 < edges.count) b = std::min(b, edges.edge[k + 1].flankLo - 1);
    const int n = b - a + 1;
    if (n < 2) return ZoneKind::Short;
    // The trend across the window, half against half: turning grooves are concentric, so
    // the rays' mean keeps their ridges, but a ridge adds as much to either half.
    int64_t first = 0, second = 0;
    for (int j = a; j <= b; ++j) {
        if (level[j] == kOutsideFrame) return ZoneKind::Short;
        (j < a + n / 2 ? first : second) += level[j];
    }
    const int32_t trend = int32_t(std::abs(second / (n - n / 2) - first / (n / 2)));
    const int32_t step = usable(level, count, e.flankLo - 1) ? std::abs(int32_t(level[a]) - level[e.flankLo - 1]) : 0;
    const int32_t tolerance = std::max(kLevelTolerance, int32_t(kLevelToleranceOfStep * step));
    return trend <= tolerance ? ZoneKind::Level : ZoneKind::Varying;
}

int contactEdgeByZones(const uint16_t *level, int count, const ProfileEdges &edges, int window)
{
    if (edges.count == 0) return -1;
    const ProfileEdge *e = edges.edge;
    // The first edge followed by anything but a level ends the flat face (no ring resolved
    // before it: a narrow one, or one of the original face's grey), unless a far stronger
    // step follows (the first is then a mark on a ring whose turning grooves vary it).
    const ZoneKind first = zoneBeyond(level, count, edges, 0, window);
    if (first == ZoneKind::Varying) return edges.count > 1 && e[1].strength > kMuchStronger * e[0].strength ? -1 : 0;
    if (first == ZoneKind::Short || edges.count < 2) return -1;
    // A level beyond the first edge: the ring, ended by the contact edge, unless a level
    // follows that too (a drawn barrel band: the zones do not tell) or the second edge is
    // weak beside the first (a highlight line on a drawn barrel, a groove on the ring).
    if (kMuchStronger * e[1].strength < e[0].strength) return -1;
    // The optics blur a step alike on either side, so its derivative falls off as fast
    // outside its peak as inside. Where the second edge's flank runs on well beyond its
    // peak on the outside, the brightness keeps changing there: the barrel turning away into
    // the dark, its outline close behind, one descent with the step. (Not asked of the first
    // edge: the mean profile is taken about the centre, and an original face's edge that is
    // no circle about it, R_i varying by a percent or so around the face, spreads its step
    // over its radii unevenly, several pixels at full resolution; its zone is judged by the
    // levels alone.)
    if (e[1].flankHi - e[1].index > 2 * (e[1].index - e[1].flankLo) + 1) return 1;
    return zoneBeyond(level, count, edges, 1, window) == ZoneKind::Level ? -1 : 1;
}

bool opensBand(const uint16_t *level, int count, const ProfileEdges &edges, int k)
{
    if (k < 0 || k + 1 >= edges.count) return false;
    const ProfileEdge &open = edges.edge[k], &close = edges.edge[k + 1];
    const int before = open.flankLo - 1, top = open.flankHi + 1, after = close.flankHi + 1;
    if (close.sign == open.sign || !usable(level, count, before) || !usable(level, count, top) ||
        !usable(level, count, after))
        return false;
    const int32_t height = std::abs(int32_t(level[top]) - level[before]);
    const int32_t tolerance = std::max(kLevelTolerance, int32_t(kLevelToleranceOfStep * height));
    return std::abs(int32_t(level[after]) - level[before]) <= tolerance;
}

} // namespace icacam::vision
