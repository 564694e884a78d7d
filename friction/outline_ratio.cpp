#include "friction/outline_ratio.h"

#include <array>

#include "friction/grid.h"
#include "friction/outline_table.h"

namespace icacam::friction {

namespace t = outline_table;

namespace {

constexpr std::array<GridAxis, 4> kAxes{GridAxis{t::kR, t::kRCount}, GridAxis{t::kN, t::kNCount},
                                        GridAxis{t::kMu, t::kMuCount},
                                        GridAxis{t::kX, t::kXCount, Beyond::Hold, Beyond::Extend}};

} // namespace

double outlineRatioAt(double n, double mu, double reduction, double d0OverW)
{
    if (!(d0OverW > 0)) return 1.0;
    const double v = gridValue(&t::kRatio[0][0][0][0], kAxes, {reduction, n, mu, d0OverW});
    return v == v ? v : 1.0;
}

double outlineShiftAt(double n, double mu, double reduction, double d0OverW)
{
    if (!(d0OverW > 0)) return 0.0;
    const double v = gridValue(&t::kShift[0][0][0][0], kAxes, {reduction, n, mu, d0OverW});
    return v == v ? v : 0.0;
}

double outlineRatioRelSigma()
{
    return t::kRelSigma;
}

double outlineD0OverWMax()
{
    return t::kX[t::kXCount - 1];
}

} // namespace icacam::friction
