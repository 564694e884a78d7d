#pragma once
// Finding the two boundaries of the immigrated contact area about a known centre:
// the mean radial profile names the edges (contact edge, silhouette, original face), the
// fine rays locate them per angle, and a robust closed curve is fitted to each.
#include <cstdint>

#include "vision/end_face_geometry.h"
#include "vision/fixed_point.h"
#include "vision/luma_view.h"
#include "vision/ray_capacity.h"

namespace icacam::vision {

constexpr int kMaxRayTable = 256;

struct RingSearch {
    const LumaView *frame;
    double r0;     // initial specimen radius, pixels
    double cx, cy; // refined centre
    uint16_t *coarse;
    uint16_t *fine;
    int16_t *deriv;
    int32_t *meanProfile;
    int32_t *meanDeriv;
    EdgeSample *innerPts;
    EdgeSample *outerPts;
    // The analyzer found the end face's own centre off the strongest edges': the camera sees
    // the barrel on one side only, and the contact edge's ramp is judged arc by arc
    // (contactEdgeAtKneeBySector).
    bool obliqueView = false;
    // The frame's tone curve (FaceSearch::toneGamma): the two edges are moved to where the
    // optics drew them in linear light (undoToneCurve).
    double toneGamma = 1;

    ErrorCode run(EndFaceGeometry *m);
    // The search where run() (and the analyzer's search about the end face's own centre)
    // found no original face's edge: the ring about the profile's step back beyond the edge
    // the mean profile names (stepBack), a ring too narrow for the coarse step darker, or
    // lighter, than both the face and the barrel's shoulder.
    ErrorCode runBeyondDrop(EndFaceGeometry *m);

    // Internal steps (public only so that RingSearch stays an aggregate).

    struct MeanEdges {
        double rOuter = 0; // contact edge radius (pixels)
        int signOuter = -1;
        int32_t strengthOuter = 0; // in fine derivative units
        double rMax = 0;           // silhouette, 0 if not found
        // Half the distance to the profile's next edge of its sign inside the contact edge
        // (pixels; 0: none named): where a search for the contact edge must stop.
        double reachInPx = 0;
        // Where the zones named it, the profile's next edge beyond it steps the other way (a
        // lit shoulder's far flank) and the one after that the same way, more than twice as
        // strong (the outline): how far outside the contact edge the next edge's flank ends
        // (pixels; 0: no such edges), where a search for the contact edge must stop.
        double reachOutPx = 0;
        bool found = false;
        bool namedByZones = false; // else by the largest drop (the zones did not tell)
        // The zones named the contact edge where the profile cannot tell it from a band on
        // the barrel (profile_zones.h, opensBand): the reading must not be taken on trust.
        bool undecided = false;
        // Where the largest drop named it: the profile's next edge beyond it, inside the
        // outline (0: none), and that edge's sign and strength. A face much brighter than
        // the ring drops more onto the ring than the ring onto the barrel, and where the
        // zones are too narrow to tell, the drop names the original face's edge.
        double rNext = 0;
        int signNext = 0;
        int32_t strengthNext = 0;
        // Where the largest drop named it: the profile's edges of the other sign beyond it,
        // inside the outline, nearest first (the step back onto a shoulder or fold may lie
        // beyond a turned ring's grooves, which step both ways).
        static constexpr int kMaxBacks = 8;
        double rBack[kMaxBacks] = {};
        int32_t strengthBack[kMaxBacks] = {};
        int backs = 0;
        // The same for the profile's outermost edge beyond it, taken for the outline (0: none).
        double rOutline = 0;
        int signOutline = 0;
        int32_t strengthOutline = 0;
        // The ring is searched as an oblique view's, the contact edge's ramp judged arc by arc.
        bool seenObliquely = false;
        // The edge named is where a level ends at the top of a ramp, no step: the centring,
        // which follows the strongest step about it, would walk down the ramp onto the
        // outline; the coarse centre and the radius named stand.
        bool kneeOnRamp = false;
    };
    // The fine rays' directions for the ring's size, and the mean profile's edges.
    MeanEdges castRays();
    MeanEdges meanProfileEdges();
    // The mean of the coarse rays' directions sampled again, count samples from fromPx at
    // stepPx (kOutsideFrame where under a quarter of the rays saw the frame); count ≤
    // kMaxFineSamples. Uses the fine rows as scratch.
    void finerMeanProfile(double fromPx, double stepPx, int count, uint16_t *mean);
    // Both boundaries and the silhouette about the contact edge `me` names. With profileFit
    // false, where no ray saw the original face's edge the profile's two-step fit is not
    // tried: *deferred is set and InnerEdgeNotFound returned (the fit is then a last resort).
    ErrorCode ringAbout(const MeanEdges &me, EndFaceGeometry *m, bool profileFit = true, bool *deferred = nullptr);
    // Where the profile about the coarse centre, read at the fine step beyond the
    // contact edge `me` names, steps straight back the other way and then again the named
    // edge's way (a ring a few pixels wide darker, or lighter, than both the face and the
    // barrel's shoulder, the outline beyond): that step back, as the contact edge to search
    // about (false: none). Undecided (back->undecided) where the turn beyond it is only half
    // as steep or the ring 6–9 px wide.
    bool stepBack(const MeanEdges &me, MeanEdges *back);
    // Whether the mean profile's next step beyond the drop `me` names steps back from the
    // level between them by more than a ripple's share of the drop: a ring between the
    // original face's edge and a fold brighter (or darker) than it, not a highlight line
    // across a barrel band. Reads the profile at the fine step (the fine rows as scratch).
    bool stepsBackBeyond(const MeanEdges &me);
    // Where the drop `me` names is the outline at the foot of a barrel that falls away from
    // the ring as a long ramp (a side flatter about its widest section than a band, turning
    // from the light over tens of pixels): the end of the ring's level inside it, as the
    // contact edge to search about, the drop as the outline (false: no level ends a ramp
    // there). Reads the profile at the fine step (the fine rows as scratch).
    bool levelEndInsideDrop(const MeanEdges &me, MeanEdges *knee);
    // Moves (cx, cy) to the contact edge's own centre and returns its mean radius there
    // (me.rOuter when no fit is possible).
    double centreOnContactEdge(const MeanEdges &me);
    // Per ray, the strongest edge of `sign` between loPx[i] and hiPx[i]; then the fit.
    // pts == nullptr: a first pass on every other ray, only the fitted curve at every ray
    // (pts and contrast left alone). fallbackSign ≠ 0: a ray without an edge of `sign`
    // takes its strongest edge of fallbackSign instead.
    bool locateOnRays(int sign, int fallbackSign, const double *loPx, const double *hiPx, int32_t minStrength,
                      EdgeSample *pts, bool interior, double reachPx, BoundaryFit *fit, double *curveOut,
                      double *contrastOut);
    // The profile across the ring following the contact edge: the mean of every
    // kAlignStride-th fine ray (those with a contact-edge point) sampled at fixed offsets from
    // the fitted curve outerR; false when the widest ring searched does not fit the buffer.
    struct AlignedProfile;
    // onInner: the same about the original face's fitted curve, on the rays that located it;
    // halfSpan > 0: only that many samples either side of the curve.
    // sector ≥ 0: every ray of that arc of the ring (kRampSectors arcs) instead.
    bool alignedProfile(const double *outerR, AlignedProfile *p, bool onInner = false, int halfSpan = 0,
                        int sector = -1) const;
    // The contact edge's blur (Gaussian σ, pixels) from the aligned profile; −1 if none shows.
    double contactEdgeWidth(const AlignedProfile &p, int signOuter) const;
    // The blur of the step at the aligned radius, its derivative's moments taken within
    // reachPx either side; −1 if none shows.
    double stepWidth(const AlignedProfile &p, int sign, double reachPx) const;
    // Where the barrel's shading ramps away beyond the contact edge (rampPx beyond
    // kContactRampPx), the derivative peaks where it falls fastest, outside the edge; where the
    // edge rises onto a lit shoulder, the shoulder's fall pulls the peak inside. Moves `outer`
    // (and the rays' points) to where the ring's level ends, the step and the fall beyond it
    // fitted across the aligned profile with the optics' blur blurPx (contact_knee.h), on a
    // ring ringPx wide; left alone where neither shows or no knee is found.
    // Returns whether it moved the edge.
    bool contactEdgeAtKnee(const AlignedProfile &p, int signOuter, double blurPx, double rampPx, double ringPx,
                           BoundaryFit *outer);
    // Where the ring's level ends relative to the aligned profile's edge sample (pixels,
    // negative: inside), the fit contactEdgeAtKnee makes: on a ramp (onRamp, the search twice
    // rampPx deep and at least twice kContactRampPx) or beside a lit shoulder (signOuter > 0);
    // false where neither applies or no knee is found.
    bool kneeOffset(const AlignedProfile &p, int signOuter, double blurPx, double rampPx, double ringPx, bool onRamp,
                    double *offsetPx) const;
    // The same, seen obliquely: the ramp measured and the knee located on each of kRampSectors
    // arcs of the ring, the rays' points moved by their arc's offset (interpolated between
    // the arcs' middles) and the contact edge fitted again through them. Returns the widest
    // arc's ramp (pixels): the contact edge's, where part of it lies on the barrel's ramp.
    // *moved: whether any arc's knee moved the edge.
    double contactEdgeAtKneeBySector(const double *outerR, int signOuter, double blurPx, double reachPx, double ringPx,
                                     BoundaryFit *outer, bool *moved);
    // A tone curve (toneGamma > 1) draws each edge's derivative peak towards its dark side
    // (vision/tone_curve.h): the original face's edge, located on atInner, and the contact
    // edge, located on atOuter where no knee moved it (outerAtKnee), are moved back by that
    // shift for their levels either side and the optics' blur blurPx, read within reachPx.
    void undoToneCurve(const AlignedProfile &atInner, const AlignedProfile &atOuter, double blurPx, double reachPx,
                       bool outerAtKnee, BoundaryFit *inner, BoundaryFit *outer);
    // Moves a fitted boundary and its rays' points outwards by offsetPx.
    void shiftBoundary(double offsetPx, BoundaryFit *fit, EdgeSample *pts) const;
    // The original face's edge as the aligned profile names it: the strongest derivative
    // extremum inside the contact edge that separates two levels (sign 0: none).
    struct OriginalFaceName {
        int k = 0;            // its sample offset from the contact edge (negative: inside)
        int sign = 0;         // rising (+1) or falling (−1) going outwards
        int32_t strength = 0; // its derivative, in the fine derivative rows' units
        // Where the contact edge's own hump of the derivative ends walking in (sample offset,
        // ≤ 0): the profile inside it is the ring's level, beyond it the contact edge's fall.
        int flank = 0;
    };
    OriginalFaceName nameOriginalFace(const AlignedProfile &p) const;
    // The named edge on every fine ray, in a window following the contact edge, and its fit
    // (inner, its curve innerR at every fine ray, its contrast); false where it is not found.
    bool originalFaceOnRays(OriginalFaceName name, const AlignedProfile &p, const double *outerR, EndFaceGeometry *m,
                            BoundaryFit *inner, double *innerR, double *contrast);
    // Whether the coarse mean profile steps across the original face read (inside rInnerPx,
    // clear of its edge's blur innerBlurPx) by a share of that edge's own contrast
    // (contrastInner, grey levels): the face holds an edge of its own.
    bool faceHoldsEdge(double rInnerPx, double contrastInner, double innerBlurPx) const;
    // Whether the profile across the ring (aligned on the contact edge) steps inside the
    // original face read, at sample innerAt, clear of its edge's blur innerBlurPx, by a share
    // of that edge's own contrast (contrastInner, grey levels): the face holds an edge.
    static bool faceHoldsEdge(const AlignedProfile &p, double innerAt, double contrastInner, double innerBlurPx);
    // A ring too narrow for the per-ray search: both edges from the aligned profile's
    // two-step fit (narrow_ring.h), the original face's edge following the contact edge's
    // shape at the fitted width. startWidthPx: the rays' width to start from (0: none).
    bool narrowRingFromProfile(const AlignedProfile &p, int signOuter, double startWidthPx, BoundaryFit *outer,
                               BoundaryFit *inner, double *contrastInner);
    // Samples every fine ray from start[i] (pixels) and fills the smoothed derivative rows.
    // boxHalf > 0: the rows hold a box step detector of that half-width instead.
    void sampleWindow(const double *start, double step, int count, int boxHalf, EndFaceGeometry *m);
    // What the coarse rays' outline search saw besides the fit it returns.
    struct OutlineRaysSeen {
        // The barrel is seen obliquely, so no silhouette is a circle about the axis.
        bool lopsided = false;
        // No outline because too few rays cleared the step detector's noise for a fit (not a
        // lopsided band, not a step at the search's bound).
        bool faint = false;
        // Some rays' step is a bright line's outer flank (left out of the fit where they are
        // under half the rays).
        bool linesSeen = false;
        // Rays searched beyond the contact edge (inside the frame, room for the detector), and
        // those of them that showed a step.
        int searched = 0, stepped = 0;
    };
    // Silhouette R_max from the coarse rays, outside the fitted contact edge; 0 if unclear.
    // The per-ray fit's coverage, scatter and centre go to m.
    // outlineR: the fitted outline's radius at each coarse ray about the coarse centre
    // (kCoarseRays of them; written where the fit is returned).
    double silhouetteFromRays(const double *outerR, double blurPx, EndFaceGeometry *m, double *outlineR,
                              OutlineRaysSeen *seen);
    // A faint outline the mean profile shows at rMeanPx, located on kOutlineSectors sectors'
    // pooled rays about it; 0 unless half the sectors show it on one circle (coverage, scatter
    // and centre to m, outlineR as silhouetteFromRays).
    double silhouetteFromSectors(double rMeanPx, EndFaceGeometry *m, double *outlineR) const;
    // One coarse ray's silhouette between samples lo and hi: the outermost clear step of a
    // detector w samples a side, located by one a quarter as wide (*atSample: its sample
    // position, sub-sample); false when no step stands out of the ray's noise. The detector's
    // inside reads no sample before barrelFrom (the contact edge's blur ends there). The
    // ray's noise is judged over its outer quarter up to hi; the step is searched for from
    // searchHi (≤ hi) inwards. *onBound: the step still rose at lo, where the search ends
    // (the outline lies there, or the barrel's shading falls off from the contact edge on).
    bool silhouetteOnRay(const uint16_t *row, int lo, int hi, int searchHi, int w, int barrelFrom, double *atSample,
                         bool *onBound) const;
    // The coarse rays' outline search: per ray the outline found (radius, pixels; valid) and
    // what silhouetteOnRay read it with (lo, the first sample searched; barrelFrom, the first
    // the detector's inside reads), and the detector's half-width w and last sample hi.
    struct OutlineRays {
        double radius[kCoarseRays];
        bool valid[kCoarseRays], onBound[kCoarseRays];
        int lo[kCoarseRays], barrelFrom[kCoarseRays];
        int w, hi;
    };
    // Rays whose outermost step lies far beyond the outline most rays agree on (the fixture's
    // shadow): searched again inside it, or left out.
    void outlineInsideRivals(OutlineRays *rays) const;
    // Whether the mean profile's step at rPx (w coarse samples a side) falls from a bright
    // band: the level inside it rose from farther in by at least half the step (a highlight
    // line on the barrel, its outer flank a step like the outline's).
    bool highlightsOuterFlank(double rPx, int w) const;
    // The outline found on a highlight line's outer flank (isLine), and the barrel's own
    // outline beyond it: found, shiftPx outwards from the fitted one.
    struct HighlightOutline {
        bool isLine, found;
        double shiftPx;
    };
    HighlightOutline outlineBeyondHighlight(const double *outerR, const double *outlineR, double blurPx) const;
    // The silhouette taken: the rays' (or the sectors') fit perRay, read beyond a highlight
    // line where onLineSuspected, else the mean profile's (me.rMax) unless the band is
    // lopsided or the drop is a ramp's foot. Sets m->rMaxPx; returns perRay as settled (0
    // where the fit was a line's with nothing beyond it).
    double settleOutline(const MeanEdges &me, const double *outerR, double blurPx, bool lopsided, bool onLineSuspected,
                         double perRay, double *outlineR, EndFaceGeometry *m) const;
    // Whether the mean profile shows a second step of the outline's sign, as strong, just
    // outside it (the fixture's shadow edge): then the outline cannot be told from it.
    bool outlineRivalled(double rMaxPx) const;
    // The same on the coarse rays aligned on the fitted outline (outlineR: its radius at each
    // coarse ray about the coarse centre).
    bool outlineRivalledAlong(const double *outlineR) const;
    // The coarse rays' mean with each ray aligned on outlineR (its radius at each coarse ray
    // about the coarse centre): mean[k] at from + k coarse steps from it, interpolated; −1
    // where under a quarter of the rays hold both samples.
    void outlineAlignedMean(const double *outlineR, int from, int n, double *mean) const;
    // Whether the barrel band outside the contact edge (radius − the contact edge, per coarse
    // ray) swings by more than half its mean width around the ring: an oblique view.
    bool barrelBandLopsided(const double *radius, const bool *valid, const double *outerR) const;

    double coarseCx_ = 0, coarseCy_ = 0; // the centre the coarse rays were cast from
    double centredRadius_ = 0;           // the contact edge's radius the centring settled on
    double fineStart_[kMaxRayTable] = {}, fineStep_ = 1;
    // How many fine rays this search casts (a divisor of 256, scaled to the ring's size in
    // pixels); fine ray i points along angle 2πi/rays_, its direction from the shared
    // AngleTable.
    int rays_ = 0;
    double rayCosBuf_[kMaxRayTable] = {}, raySinBuf_[kMaxRayTable] = {};
    Q2_14 rayCosQBuf_[kMaxRayTable] = {}, raySinQBuf_[kMaxRayTable] = {};
    const Q2_14 *rayCosQ_ = nullptr, *raySinQ_ = nullptr;
    const double *rayCos_ = nullptr, *raySin_ = nullptr;
    uint32_t samplesInside_ = 0, samplesSaturated_ = 0;
    int fineCount_ = 0;
};

} // namespace icacam::vision
