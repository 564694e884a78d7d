#include "vision/normal_cdf.h"

#include <cmath>

namespace icacam::vision {

NormalTable::NormalTable()
{
    for (int i = 0; i <= 2 * kHalf + 1; ++i) {
        const double z = double(i - kHalf) / kPerUnit;
        cdf[i] = 0.5 * std::erfc(-z * 0.7071067811865476);
        pdf[i] = 0.3989422804014327 * std::exp(-0.5 * z * z);
    }
}

const NormalTable kNormalTable;

} // namespace icacam::vision
