// A barrel that falls away from the ring as a long ramp, not a band: the drop the mean profile
// takes for the contact edge is the outline at the ramp's foot, and the contact edge is where
// the ring's level ends inside it.
#include "vision/ring_search.h"

#include <algorithm>
#include <cmath>

#include "vision/profile_zones.h"
#include "vision/radial_profile.h"
#include "vision/ring_search_detail.h"

namespace icacam::vision {

using namespace ring_search_detail;

namespace {
// The profile's slope (grey per pixel, Q8) under which it counts as a level: a ring's flat
// face is even to well under a grey per pixel; a barrel turning away from the light falls by
// several (the bench's flat-sided barrels: 2–9 per pixel over 15–25 px).
constexpr int32_t kLevelSlopeQ8 = 256 / 2;
// How far a level's samples stray from its mean (Q8): a grey and a half.
constexpr int32_t kLevelRippleQ8 = 3 * 256 / 2;
// The ramp must carry a quarter of the fall from the ring to the background at least: a
// drawn band's edge has none, and a highlight's flank a few per cent.
constexpr double kRampShareOfFall = 0.25;
} // namespace

bool RingSearch::levelEndInsideDrop(const MeanEdges &me, MeanEdges *knee)
{
    // From well inside any ring the search accepts to just beyond the drop, at 1 px.
    const double span = (kWidestRingOfR0 + 0.2) * r0;
    const double fromPx = me.rOuter - span;
    const int n = std::min(kMaxFine, int(span) + 4);
    if (fromPx <= 0 || n < 16) return false;
    uint16_t mean[kMaxFine];
    finerMeanProfile(fromPx, kFineStepPx, n, mean);
    for (int j = 0; j < n; ++j)
        if (mean[j] == kOutsideFrame) return false;
    const int s = me.signOuter;
    const int drop = int(me.rOuter - fromPx + 0.5);
    // The slope along the descent over two pixels either side: positive where the profile
    // goes the drop's way outwards.
    auto slope = [&](int j) { return s * (int32_t(mean[j + 2]) - int32_t(mean[j - 2])) / 4; };
    // The ramp: inwards from the drop while the profile still descends, then across the
    // shoulder its top may make (the fold, facing the light, a little brighter than the ring);
    // its inner end, where a level of kLevelSlopeQ8 begins and holds for a few pixels, is the
    // knee.
    const int hold = std::max(4, int(0.03 * r0));
    int j = drop - 2;
    while (j - hold > 2 && slope(j) > kLevelSlopeQ8) --j;
    const int top = j;
    while (j - hold > 2 && slope(j) < -kLevelSlopeQ8) --j;
    int flat = 0;
    for (int k = j; k > 2 && std::abs(slope(k)) <= kLevelSlopeQ8; --k) ++flat;
    if (flat < hold) return false;
    // The slope's window reaches two pixels either side: the level itself ends where the
    // profile first leaves it by more than a ripple, at most two pixels on.
    int64_t sum = 0;
    for (int k = j - flat + 1; k <= j; ++k) sum += mean[k];
    const int32_t level = int32_t(sum / flat);
    int kneeAt = j;
    while (kneeAt < j + 2 && kneeAt < top && std::abs(int32_t(mean[kneeAt + 1]) - level) <= kLevelRippleQ8) ++kneeAt;
    // The ramp beyond the knee is the barrel's, not the drop's own blurred flank (a few
    // pixels): longer than that, and carrying its share of the fall.
    const int rampPx = drop - kneeAt;
    if (rampPx < std::max(6.0, 0.05 * r0)) return false;
    // The fall is the ramp's, from its top (the ring's level, or the fold above it).
    const int32_t start = mean[top], foot = mean[std::min(n - 1, drop + 2)];
    const int32_t mid = mean[std::max(top, drop - 3)];
    const int32_t fall = s * (foot - start), rampFall = s * (mid - start);
    if (fall < kMinZoneStep || rampFall < kRampShareOfFall * fall) return false;
    *knee = me;
    knee->rOuter = fromPx + kneeAt * kFineStepPx;
    int32_t kneeSlope = slope(kneeAt + 2);
    // Across a shoulder the ring's level ends in a step up onto it, the other way: the
    // contact edge is that step, where it is steepest.
    if (-s * (int32_t(mean[top]) - int32_t(mean[kneeAt])) >= kMinZoneStep) {
        int steepest = kneeAt + 1;
        for (int k = kneeAt + 1; k < top; ++k)
            if (slope(k) < slope(steepest)) steepest = k;
        knee->rOuter = fromPx + steepest * kFineStepPx;
        knee->signOuter = -s;
        kneeSlope = -slope(steepest);
    }
    knee->strengthOuter =
        std::max<int32_t>(1, int32_t(int64_t(me.strengthOuter) * kneeSlope / std::max<int32_t>(1, slope(drop))));
    knee->reachInPx = 0.5 * flat;
    knee->reachOutPx = 0.5 * rampPx;
    knee->rMax = me.rOuter;
    knee->namedByZones = true;
    knee->kneeOnRamp = knee->signOuter == s; // a step up onto a fold is centred on as any step
    knee->undecided = false;
    knee->rNext = knee->rOutline = 0;
    return true;
}

} // namespace icacam::vision
