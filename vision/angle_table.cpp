#include "vision/angle_table.h"

#include <cmath>
#include <numbers>

namespace icacam::vision {

namespace {
struct BuiltAngleTable : AngleTable {
    BuiltAngleTable()
    {
        for (int j = 0; j < kSize; ++j) {
            // The same expression rayDirection() and the fits used before the table, so
            // the values are bit-identical (2π·(k·i)/(k·n) rounds as 2π·i/n for k = 2^m).
            const double t = 2.0 * std::numbers::pi * double(j) / double(kSize);
            cos[j] = std::cos(t);
            sin[j] = std::sin(t);
            cosQ[j] = Q2_14::fromDouble(cos[j]);
            sinQ[j] = Q2_14::fromDouble(sin[j]);
        }
    }
};
} // namespace

const AngleTable &angleTable()
{
    static const BuiltAngleTable table;
    return table;
}

} // namespace icacam::vision
