#include "vision/normal_cdf.h"

#include <cmath>

namespace icacam::vision {

namespace {

struct NormalTable {
    static constexpr int kPerUnit = 64, kHalf = 8 * kPerUnit;
    double cdf[2 * kHalf + 2];
    double pdf[2 * kHalf + 2];
    NormalTable()
    {
        for (int i = 0; i <= 2 * kHalf + 1; ++i) {
            const double z = double(i - kHalf) / kPerUnit;
            cdf[i] = 0.5 * std::erfc(-z * 0.7071067811865476);
            pdf[i] = 0.3989422804014327 * std::exp(-0.5 * z * z);
        }
    }
};
const NormalTable table;

double lookUp(const double *v, double z, double below, double above)
{
    const double t = z * NormalTable::kPerUnit + NormalTable::kHalf;
    if (t <= 0) return below;
    if (t >= 2 * NormalTable::kHalf) return above;
    const int i = int(t);
    const double f = t - i;
    return v[i] + f * (v[i + 1] - v[i]);
}

} // namespace

double normalCdf(double z)
{
    return lookUp(table.cdf, z, 0.0, 1.0);
}

double normalPdf(double z)
{
    return lookUp(table.pdf, z, 0.0, 0.0);
}

} // namespace icacam::vision
