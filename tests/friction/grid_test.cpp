// The grid lookup every generated table is read with (friction/grid.h), against a
// brute-force reference written the other way round: one axis at a time, recursively, in long
// double, with the axis searched by std::upper_bound. Random tables of 1 to 4 axes; exact at
// grid points; the rules beyond the ends (hold, extend, nothing); holes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "friction/grid.h"

using namespace icacam::friction;
using namespace icacam::friction;

namespace {

struct Table {
    std::vector<std::vector<double>> axes;
    std::vector<Beyond> below, above;
    std::vector<double> values; // row-major, the last axis fastest
};

// f at x along axes d.. of the block starting at `offset`: interpolate the two neighbouring
// (D − d − 1)-dimensional lookups along axis d.
// magnitude: Σ |weight × value| instead (the scale of the rounding error an extrapolation
// far beyond the ends amplifies).
long double reference(const Table &t, const std::vector<double> &x, bool magnitude = false, size_t d = 0,
                      size_t offset = 0)
{
    if (d == t.axes.size()) return magnitude ? std::fabs(t.values[offset]) : t.values[offset];
    const std::vector<double> &a = t.axes[d];
    const size_t n = a.size();
    auto at = [&](size_t i) { return reference(t, x, magnitude, d + 1, offset * n + i); };
    if (n == 1) return at(0);
    long double xd = x[d];
    if (xd < a.front() || xd > a.back()) {
        const Beyond rule = xd < a.front() ? t.below[d] : t.above[d];
        if (rule == Beyond::Nothing) return NAN;
        if (rule == Beyond::Hold) xd = xd < a.front() ? a.front() : a.back();
    }
    // The cell: the last grid value <= x (the first or last cell beyond the ends).
    size_t i = size_t(std::upper_bound(a.begin(), a.end(), double(xd)) - a.begin());
    i = std::clamp<size_t>(i == 0 ? 0 : i - 1, 0, n - 2);
    const long double w = (xd - a[i]) / ((long double)a[i + 1] - a[i]);
    long double v = 0;
    const long double w0 = magnitude ? std::fabs(1 - w) : 1 - w, w1 = magnitude ? std::fabs(w) : w;
    if (w != 1) v += w0 * at(i); // a corner of weight 0 is not read (holes stay out)
    if (w != 0) v += w1 * at(i + 1);
    return v;
}

template <size_t D> double lookup(const Table &t, const std::vector<double> &x)
{
    std::array<GridAxis, D> axes;
    std::array<double, D> xs;
    for (size_t d = 0; d < D; ++d) {
        axes[d] = GridAxis{t.axes[d].data(), int(t.axes[d].size()), t.below[d], t.above[d]};
        xs[d] = x[d];
    }
    return gridValue(t.values.data(), axes, xs);
}

double lookupAny(const Table &t, const std::vector<double> &x)
{
    switch (t.axes.size()) {
    case 1: return lookup<1>(t, x);
    case 2: return lookup<2>(t, x);
    case 3: return lookup<3>(t, x);
    default: return lookup<4>(t, x);
    }
}

Table randomTable(std::mt19937 &rng, size_t dims, Beyond rule)
{
    std::uniform_int_distribution<int> count(1, 6);
    std::uniform_real_distribution<double> step(0.05, 1.0), value(-3, 3);
    Table t;
    size_t total = 1;
    for (size_t d = 0; d < dims; ++d) {
        std::vector<double> a{value(rng)};
        for (int k = count(rng); k > 1; --k) a.push_back(a.back() + step(rng));
        total *= a.size();
        t.axes.push_back(a);
        t.below.push_back(rule);
        t.above.push_back(rule);
    }
    for (size_t k = 0; k < total; ++k) t.values.push_back(value(rng));
    return t;
}

// A query: inside the axis mostly, on a grid value sometimes, beyond either end sometimes.
std::vector<double> randomPoint(std::mt19937 &rng, const Table &t)
{
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> x;
    for (const auto &a : t.axes) {
        const double lo = a.front(), hi = a.back(), span = std::max(hi - lo, 0.5), r = u(rng);
        if (r < 0.15)
            x.push_back(a[std::uniform_int_distribution<size_t>(0, a.size() - 1)(rng)]);
        else if (r < 0.3)
            x.push_back(lo - span * u(rng));
        else if (r < 0.45)
            x.push_back(hi + span * u(rng));
        else
            x.push_back(lo + (hi - lo) * u(rng));
    }
    return x;
}

} // namespace

TEST(Grid, MatchesTheBruteForceReferenceUnderEveryRule)
{
    std::mt19937 rng(20261123);
    int checked = 0, none = 0;
    for (Beyond rule : {Beyond::Hold, Beyond::Extend, Beyond::Nothing})
        for (size_t dims = 1; dims <= 4; ++dims)
            for (int table = 0; table < 40; ++table) {
                const Table t = randomTable(rng, dims, rule);
                for (int q = 0; q < 50; ++q) {
                    const std::vector<double> x = randomPoint(rng, t);
                    const long double want = reference(t, x);
                    const double got = lookupAny(t, x);
                    if (std::isnan(double(want))) {
                        EXPECT_TRUE(std::isnan(got));
                        ++none;
                        continue;
                    }
                    EXPECT_NEAR(got, double(want), 1e-14 * double(1 + reference(t, x, true)))
                        << dims << "-d, rule " << int(rule);
                    ++checked;
                }
            }
    EXPECT_GT(checked, 15000);
    EXPECT_GT(none, 500); // the Nothing rule was exercised
}

TEST(Grid, ReturnsEveryGridPointExactly)
{
    std::mt19937 rng(7);
    for (size_t dims = 1; dims <= 4; ++dims) {
        const Table t = randomTable(rng, dims, Beyond::Nothing);
        std::vector<size_t> idx(dims, 0);
        for (size_t flat = 0; flat < t.values.size(); ++flat) {
            std::vector<double> x(dims);
            size_t rest = flat;
            for (size_t d = dims; d-- > 0;) {
                x[d] = t.axes[d][rest % t.axes[d].size()];
                rest /= t.axes[d].size();
            }
            EXPECT_EQ(lookupAny(t, x), t.values[flat]) << dims << "-d point " << flat;
        }
    }
}

TEST(Grid, ExtendReproducesAMultilinearFunctionAnywhere)
{
    // f = Π (a_d + b_d x_d) is multilinear: sampled on the grid, the lookup is f itself, inside
    // and, with Extend, beyond every end.
    const std::vector<double> ax0{0.3, 0.35, 0.4, 0.5, 0.6}, ax1{0.05, 0.125, 0.25}, ax2{250, 500, 1250};
    auto f = [](double x, double y, double z) { return (1 + 2 * x) * (0.5 - 3 * y) * (2 + 0.001 * z); };
    std::vector<double> v;
    for (double x : ax0)
        for (double y : ax1)
            for (double z : ax2) v.push_back(f(x, y, z));
    const std::array<GridAxis, 3> axes{GridAxis{ax0.data(), 5, Beyond::Extend, Beyond::Extend},
                                       GridAxis{ax1.data(), 3, Beyond::Extend, Beyond::Extend},
                                       GridAxis{ax2.data(), 3, Beyond::Extend, Beyond::Extend}};
    for (double x : {0.1, 0.3, 0.37, 0.6, 0.75})
        for (double y : {0.0, 0.05, 0.2, 0.5})
            for (double z : {100.0, 600.0, 2000.0})
                EXPECT_NEAR(gridValue(v.data(), axes, {x, y, z}), f(x, y, z), 1e-12) << x << " " << y << " " << z;
}

TEST(Grid, HoldsAtTheEndsAndGivesNothingWhereAsked)
{
    const double axis[3] = {1, 2, 4};
    const double v[3] = {10, 20, 0};
    const std::array<GridAxis, 1> hold{GridAxis{axis, 3}};
    EXPECT_EQ(gridValue(v, hold, {0.0}), 10);
    EXPECT_EQ(gridValue(v, hold, {9.0}), 0);
    EXPECT_EQ(gridValue(v, hold, {3.0}), 10);
    EXPECT_EQ(gridValue(v, hold, {NAN}), 10); // held at the first value: the caller flags it
    const std::array<GridAxis, 1> mixed{GridAxis{axis, 3, Beyond::Nothing, Beyond::Extend}};
    EXPECT_TRUE(std::isnan(gridValue(v, mixed, {0.5})));
    EXPECT_TRUE(std::isnan(gridValue(v, mixed, {NAN})));
    EXPECT_EQ(gridValue(v, mixed, {1.0}), 10);
    EXPECT_EQ(gridValue(v, mixed, {6.0}), -20); // the last cell (2, 20)-(4, 0) continued
    // A one-value axis holds whatever its rule.
    const std::array<GridAxis, 1> single{GridAxis{axis, 1, Beyond::Nothing, Beyond::Nothing}};
    EXPECT_EQ(gridValue(v, single, {-5.0}), 10);
}

TEST(Grid, AHoleSpoilsOnlyTheLookupsThatWeighIt)
{
    const double ax[3] = {0, 1, 2};
    const double v[3][3] = {{0, 1, 2}, {1, kNoData, 3}, {2, 3, 4}};
    const std::array<GridAxis, 2> axes{GridAxis{ax, 3}, GridAxis{ax, 3}};
    EXPECT_TRUE(std::isnan(gridValue(&v[0][0], axes, {1.0, 1.0})));
    EXPECT_TRUE(std::isnan(gridValue(&v[0][0], axes, {0.5, 0.5})));
    EXPECT_TRUE(std::isnan(gridValue(&v[0][0], axes, {1.5, 1.0})));
    // On the neighbouring grid lines the hole carries no weight.
    EXPECT_EQ(gridValue(&v[0][0], axes, {0.0, 1.0}), 1);
    EXPECT_DOUBLE_EQ(gridValue(&v[0][0], axes, {2.0, 0.5}), 2.5);
    EXPECT_DOUBLE_EQ(gridValue(&v[0][0], axes, {0.5, 2.0}), 2.5);
}

TEST(Grid, VisitsOnlyTheWeightedCornersAndTheirWeightsSumToOne)
{
    const double ax[4] = {0, 1, 2, 3};
    const std::array<GridAxis, 3> axes{GridAxis{ax, 4}, GridAxis{ax, 4, Beyond::Extend, Beyond::Extend},
                                       GridAxis{ax, 2}};
    int corners = 0;
    double sum = 0;
    forEachCorner(locateOnGrid(axes, {1.0, 4.5, 0.25}), [&](const std::array<int, 3> &i, double w) {
        EXPECT_EQ(i[0], 1);
        EXPECT_TRUE(i[1] == 2 || i[1] == 3);
        ++corners;
        sum += w;
    });
    EXPECT_EQ(corners, 4); // axis 0 on a grid value: one side only
    EXPECT_NEAR(sum, 1, 1e-15);
}
