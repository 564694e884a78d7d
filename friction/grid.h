#pragma once
// The one lookup every generated table is read with: multilinear interpolation on a
// rectangular grid of D axes, each end of each axis with its own stated rule.
//
// - Between grid values: linear along every axis (the 2^D corners of the cell around x,
//   weighted by the product of the axes' weights). On a grid value the weight of the next
//   one is exactly 0, so a grid point is returned exactly.
// - Beyond an end (Beyond): Hold the end value, Extend the end cell's line, or give Nothing.
//   A one-value axis holds whatever the rule.
// - A grid point without data is kNoData (NaN); a lookup that puts weight on one is NaN,
//   one that puts none on it (x on a neighbouring grid value) is not affected.
// Models that are not a lookup (the FE model's monotone cubic along u) build on the same
// corners: locateOnGrid, then forEachCorner with their own value at each corner.
// Pure C++20: no heap, no OS calls, no exceptions.
#include <array>
#include <cstddef>
#include <limits>

namespace icacam::friction {

inline constexpr double kNoData = std::numeric_limits<double>::quiet_NaN();

enum class Beyond : unsigned char {
    Hold,    // the end value: the table says nothing beyond, the caller flags the range
    Extend,  // the end cell's line continued
    Nothing, // no value (NaN)
};

struct GridAxis {
    const double *values = nullptr; // strictly rising
    int count = 0;
    Beyond below = Beyond::Hold;
    Beyond above = Beyond::Hold;
};

// x on one axis: the cell [i, i + 1] and the weight w of values[i + 1] (outside [0, 1] when
// extended); none: the rule beyond this end gives no value.
struct AxisSpot {
    int i = 0;
    double w = 0;
    bool none = false;
};

constexpr AxisSpot locateOnAxis(const GridAxis &a, double x)
{
    AxisSpot s;
    if (a.count <= 1) return s;
    const double *v = a.values;
    if (!(x >= v[0])) { // below (NaN too: held at the first value, flagged by the caller)
        if (a.below == Beyond::Nothing)
            s.none = true;
        else if (a.below == Beyond::Extend && x == x)
            s.w = (x - v[0]) / (v[1] - v[0]);
        return s;
    }
    if (x >= v[a.count - 1]) {
        s.i = a.count - 2;
        s.w = 1;
        if (x == v[a.count - 1]) return s;
        if (a.above == Beyond::Nothing)
            s.none = true;
        else if (a.above == Beyond::Extend)
            s.w = (x - v[s.i]) / (v[s.i + 1] - v[s.i]);
        return s;
    }
    while (s.i < a.count - 2 && x >= v[s.i + 1]) ++s.i;
    s.w = (x - v[s.i]) / (v[s.i + 1] - v[s.i]);
    return s;
}

template <std::size_t D> struct GridSpot {
    std::array<AxisSpot, D> axis{};
    bool none = false; // some axis gives no value here
};

template <std::size_t D>
constexpr GridSpot<D> locateOnGrid(const std::array<GridAxis, D> &axes, const std::array<double, D> &x)
{
    GridSpot<D> s;
    for (std::size_t d = 0; d < D; ++d) {
        s.axis[d] = locateOnAxis(axes[d], x[d]);
        s.none = s.none || s.axis[d].none;
    }
    return s;
}

// visit(index, weight) for each corner of the cell with a weight other than 0; index[d] is
// the grid index along axis d. Nothing is visited when the spot has no value.
template <std::size_t D, class Visit> constexpr void forEachCorner(const GridSpot<D> &s, Visit &&visit)
{
    if (s.none) return;
    for (unsigned corner = 0; corner < (1u << D); ++corner) {
        std::array<int, D> index{};
        double w = 1;
        for (std::size_t d = 0; d < D; ++d) {
            const bool upper = (corner >> d) & 1u;
            w *= upper ? s.axis[d].w : 1 - s.axis[d].w;
            index[d] = s.axis[d].i + (upper ? 1 : 0);
        }
        if (w != 0) visit(index, w);
    }
}

// Σ weight × node(index) over the corners; NaN when the spot has no value or a weighted
// corner's node is NaN.
template <std::size_t D, class Node> constexpr double blendCorners(const GridSpot<D> &s, Node &&node)
{
    if (s.none) return kNoData;
    double sum = 0;
    forEachCorner(s, [&](const std::array<int, D> &index, double w) { sum += w * node(index); });
    return sum;
}

// A table stored row-major in the axes' order (the last axis fastest), e.g. the first
// element of a generated `double t[A][B][C]`, at x.
template <std::size_t D, class T>
constexpr double gridValue(const T *table, const std::array<GridAxis, D> &axes, const std::array<double, D> &x)
{
    return blendCorners(locateOnGrid(axes, x), [&](const std::array<int, D> &index) {
        std::size_t flat = 0;
        for (std::size_t d = 0; d < D; ++d) flat = flat * std::size_t(axes[d].count) + std::size_t(index[d]);
        return double(table[flat]);
    });
}

} // namespace icacam::friction
