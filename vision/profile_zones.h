#pragma once
// Naming the contact edge on the mean radial profile from what lies either side of each
// edge, not from which way the brightness steps.
//
// The end face is flat: the original face and the immigrated ring each show as a level
// (grinding grain and turning grooves average out over the rays). The flat face ends at the
// contact edge; beyond it the barrel falls away from the camera, and under a ring light its
// brightness changes across it: a lit shoulder next to the contact edge, a ramp into the
// dark where the surface turns towards the outline. Walking out from the original face, the
// contact edge is therefore the first edge followed by anything but a level, or the second
// when the first is followed by a level (the ring between the original face's edge and
// the contact edge). Whether each edge steps up or down does not enter: face, ring, barrel
// and fixture may take any order of brightness.
//
// A drawing paints the barrel as a level too; where three levels follow each other the
// zones do not tell which edge ends the face, and the caller decides by the steps.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <cstdint>

namespace icacam::vision {

// Below this share of the profile's strongest step an extremum is a groove's or a stain's
// ripple, not a zone's edge.
inline constexpr double kRippleShareOfStep = 0.15;
// A step between two zones changes the level by at least this much (1.5 grey levels, in the
// profile's Q8 units).
inline constexpr int32_t kMinZoneStep = 3 * 256 / 2;

// One step on the profile: the derivative's extremum and the samples over which its own
// derivative stays above a quarter of the peak (the blur and the kernel's reach).
struct ProfileEdge {
    int index = 0;
    int sign = 0;         // +1 rising outwards, −1 falling
    int32_t strength = 0; // |derivative| at the extremum
    int flankLo = 0, flankHi = 0;
};

struct ProfileEdges {
    static constexpr int kCapacity = 48;
    ProfileEdge edge[kCapacity];
    int count = 0;
    bool full = false; // more steps than kCapacity: the outermost were not kept
};

// What lies just beyond an edge, up to a window of samples or the next edge's flank.
enum class ZoneKind : uint8_t {
    Level,   // within the tolerance of one grey level: the original face or the ring
    Varying, // brightness changes across it: the barrel
    Short,   // too few samples before the next edge to tell
};

// The profile: `level` in Q8 grey (kOutsideFrame where the rays left the frame), `deriv`
// its profileDerivative; edges are the extrema within [lo, hi] of at least minStrength,
// innermost first, each a step between two levels (a ridge, a groove or scratch line with
// the same level either side, is not kept).
ProfileEdges findProfileEdges(const uint16_t *level, const int32_t *deriv, int count, int lo, int hi,
                              int32_t minStrength);

// The zone beyond edge k (towards larger radii), over at most `window` samples.
ZoneKind zoneBeyond(const uint16_t *level, int count, const ProfileEdges &edges, int k, int window);

// Which of `edges` is the contact edge by the zones (see above), or −1 when they do not
// tell. window: the samples judged beyond each edge (about the narrowest ring resolved).
int contactEdgeByZones(const uint16_t *level, int count, const ProfileEdges &edges, int window);

// Whether edge k opens a band: the next edge steps back the other way and the level beyond
// it returns to the level before k. A lit shoulder just outside the contact edge makes one,
// and so does a highlight line across the barrel outside it: where the zones name the band's
// first edge for the contact edge with too few samples beyond it to judge (Short), and no
// step inside shows the original face's edge, the band may as well lie on the barrel, and
// the profile does not decide which edge ends the face.
bool opensBand(const uint16_t *level, int count, const ProfileEdges &edges, int k);

} // namespace icacam::vision
