#pragma once
// Where each segment of a ring lit in turn lights the specimen from, read off its frames.
//
// The tilt (vision/contact_tilt.h) weighs segment k by cos(θ − φ_k), φ_k its azimuth in the
// image as the config gives it (segment 0's, then every 360/N degrees the same way round).
// A ring mounted turned, or its lines listed the other way round, weighs the wrong frames:
// the tilt then finds no step, or a falling one, and the contact edge loses the evidence
// without anyone knowing why. The frames themselves say where each segment is: the barrel
// and the fixture facing a segment return more of its light than the far side does (and the
// specimen's shadow falls away from it), so over the annulus from the contact edge outwards
// segment k's share of the light, I_k / Σ I, has its first angular moment towards φ_k.
// From the N bearings: segment 0's azimuth and the way round, as a fit with its worst
// residual. Pure C++20: no heap, no OS calls, no exceptions.
#include "vision/contact_tilt.h"

namespace icacam::vision {

struct SegmentBearings {
    bool found = false;                              // every segment's moment clear of the noise and the fit consistent
    int count = 0;                                   // segments measured
    double bearingDeg[LitInTurn::kMaxSegments] = {}; // segment k's light comes from here (0 … 360)
    double contrast[LitInTurn::kMaxSegments] = {};   // its moment: the share's swing, 0 … 1
    double segment0Deg = 0;                          // the fit: segment 0's azimuth (0 … 360)
    int way = 0;                                     // +1: k runs the azimuth's way (+x towards +y), −1 the other way
    double worstDeg = 0;                             // the largest residual of a bearing about the fit
    int samples = 0;                                 // annulus samples used
};

// The bearings over the annulus rFromPx … rToPx about (cx, cy); segments must be one size.
SegmentBearings segmentBearings(const LitInTurn &lit, double cx, double cy, double rFromPx, double rToPx);

// How far a configured segment 0 azimuth lies from the bearings' fit (degrees, 0 … 180).
double bearingOffsetDeg(const SegmentBearings &b, double segment0Deg);

} // namespace icacam::vision
