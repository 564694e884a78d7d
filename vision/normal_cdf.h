#pragma once
// Φ and φ, the standard normal distribution and density, for the blurred-edge fits: a Gaussian
// blur turns a step into Φ and a ramp into z·Φ + φ. Tabulated when the program starts (1/64
// steps over ±8, linear between, off by under 1e-5), so that a fit evaluating them thousands
// of times per frame costs a table look-up each, and gives the same bits on every target.
// Pure C++20: no heap, no OS calls, no exceptions.

namespace icacam::vision {

double normalCdf(double z);
double normalPdf(double z);

} // namespace icacam::vision
