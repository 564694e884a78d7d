#pragma once
// A camera's tone curve moves a blurred edge's derivative peak. The optics blur the scene in
// linear light; the camera then encodes each pixel through its tone curve (about level^(1/γ),
// γ ≈ 2.2 for sRGB-like curves), which stretches the dark side of the edge and squeezes the
// bright side: the encoded profile's steepest point, where the rays locate the edge, lies on
// the dark side of the edge the optics drew (by 0.3–0.7 px at a blur of 1.5 px and the
// contrasts of rendered photographs). Pure C++20: no heap, no OS calls, no exceptions.

namespace icacam::vision {

// How far (pixels, ≥ 0) the derivative peak of a step between the encoded levels darkLevel
// and brightLevel (any common unit of the encoded values), blurred by a Gaussian of σ blurPx
// in linear light, lies towards the step's dark side, for a tone curve level^(1/gamma), as a
// locator that smooths the encoded profile by a Gaussian of variance smoothPx2 (its
// derivative kernel and sampling) finds it. 0 where gamma ≤ 1, a level is not positive or
// blurPx is not.
double toneEdgeShiftPx(double darkLevel, double brightLevel, double blurPx, double gamma, double smoothPx2 = 0);

} // namespace icacam::vision
