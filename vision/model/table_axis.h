#pragma once
// Lookup on the axes of the generated FE tables (fe_model_table.h, aspect_table.h).
// Pure C++20: no heap, no OS calls, no exceptions.

namespace icacam::vision {

// x between axis[i] and axis[i + 1] with weight w for axis[i + 1], clamped to the axis
// (w = 0 below the first value, w = 1 above the last; i = 0, w = 0 on a one-value axis).
inline void bracketAxis(const double *axis, int count, double x, int &i, double &w)
{
    if (count == 1 || x <= axis[0]) { i = 0; w = 0; return; }
    if (x >= axis[count - 1]) { i = count - 2; w = 1; return; }
    i = 0;
    while (i < count - 2 && x > axis[i + 1]) ++i;
    w = (x - axis[i]) / (axis[i + 1] - axis[i]);
}

} // namespace icacam::vision
