#pragma once
// Setting the camera up at the press: a focus score, a hint in words, and the live picture
// for the 128 × 64 display with the found end face drawn over it. Pure functions on a luma
// view and the vision library's measurement; nothing here captures or allocates.
#include <string_view>

#include "hal/display.h"
#include "reading/reading.h"
#include "vision/luma_view.h"

namespace icacam::fw {

struct AimReading {
    double focus = 0;   // the steepest edges' gradient, grey levels per pixel (higher: sharper)
    bool found = false; // the end face's boundaries were found
    double centreX = 0, centreY = 0, rOuterPx = 0, rInnerPx = 0, rMaxPx = 0;
    double edgeSigmaPx = 0; // blur of the contact edge the pipeline measured (0: not found)
    const char *hint = "";  // what to do next, in a few words
};

// The mean of the strongest 2 % of Sobel gradients on a grid of at most 160 × 160 points:
// inside the specimen's silhouette when found, else over the middle half of the frame. The
// edges' steepness: turning the focus ring towards sharp raises it; the light and the
// specimen's contrast change it too, so compare readings of one set-up.
double focusScore(const vision::LumaView &v, const reading::Reading &m);

// Reading and hint from a measurement: "no specimen: centre it", "move left/right/up/down"
// (the specimen's way to the frame's centre), "closer" / "farther" (the barrel's silhouette
// should span 40-95 % of the frame's height: large, but whole), "focus" (edges blurred), "ok".
AimReading aimReading(const vision::LumaView &v, const reading::Reading &m);

// The picture: the frame scaled to fit 128 × 64 on the left (ordered dither after a
// min/max stretch), the end face's two boundaries drawn inverted over it, and the focus
// score and the hint in the columns to its right.
void drawAim(hal::MonoBitmap *bmp, const vision::LumaView &v, const AimReading &r);

} // namespace icacam::fw
