#pragma once
// The outline a camera sees of the upset specimen, against its widest section R_max.
//
// A pinhole camera at working distance W above the end face sees the barrel's free surface
// at z below the face at r(z)·W/(W + z): the widest section, h/2 below the face, is seen
// shrunk by W/(W + h/2), and the outline is the farthest projection of the whole side, max
// over z, which for a close camera comes from a band between the rim and the widest section.
// friction/outline_table.h holds that outline over R_max from the FE's deformed sides over
// (n, μ, reduction, D0/W); a telecentric view (or a drawn image) is D0/W = 0, ratio 1. At
// 45–95 mm the outline lies 3–7 % inside R_max.
// Pure C++20: no heap, no OS calls, no exceptions.

namespace icacam::friction {

// outline / R_max at (n, μ, reduction) seen from d0OverW = D0/W (0: telecentric). The
// table's D0/W runs to 0.25 (40 mm for D0 10 mm); a closer camera continues its last cell.
// n, μ and the reduction are held at the table's ends.
double outlineRatioAt(double n, double mu, double reduction, double d0OverW);

// How far the outline's centre is drawn towards the optical axis, per unit of the end face's
// own distance from the axis, at (n, μ, reduction) from d0OverW (0 at a telecentric view): the
// side below the end face is seen from farther away, so nearer the axis. An image of an end
// face off the axis measures it, and with it the working distance.
double outlineShiftAt(double n, double mu, double reduction, double d0OverW);

// The table's own relative error (the FE side's shape, its mesh).
double outlineRatioRelSigma();

// The closest working distance the table speaks for, as D0/W.
double outlineD0OverWMax();

} // namespace icacam::friction
