#pragma once
// Φ and φ, the standard normal distribution and density, for the blurred-edge fits: a Gaussian
// blur turns a step into Φ and a ramp into z·Φ + φ. Tabulated when the program starts (1/64
// steps over ±8, linear between, off by under 1e-5), so that a fit evaluating them thousands
// of times per frame costs a table look-up each, and gives the same bits on every target.
// The look-up is inline: the narrow-ring fit's cost is these evaluations, and a call per
// evaluation would double it.
// Pure C++20: no heap, no OS calls, no exceptions.

namespace icacam::vision {

struct NormalTable {
    static constexpr int kPerUnit = 64, kHalf = 8 * kPerUnit;
    double cdf[2 * kHalf + 2];
    double pdf[2 * kHalf + 2];
    NormalTable();

    // Linear interpolation in v; `below` and `above` beyond the table's reach.
    static double lookUp(const double *v, double z, double below, double above)
    {
        const double t = z * kPerUnit + kHalf;
        if (t <= 0) return below;
        if (t >= 2 * kHalf) return above;
        const int i = int(t);
        const double f = t - i;
        return v[i] + f * (v[i + 1] - v[i]);
    }
};

// Filled before main() (a constant-initialised table would need constexpr erfc and exp).
extern const NormalTable kNormalTable;

inline double normalCdf(double z)
{
    return NormalTable::lookUp(kNormalTable.cdf, z, 0.0, 1.0);
}

inline double normalPdf(double z)
{
    return NormalTable::lookUp(kNormalTable.pdf, z, 0.0, 0.0);
}

} // namespace icacam::vision
