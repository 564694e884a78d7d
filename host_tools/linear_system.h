#pragma once
// A small dense linear system, solved by Gaussian elimination with partial pivoting: the
// least-squares fits of the host tools (the loop's candidate models, the FE du/dr surface)
// are a few unknowns each.
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace icacam::host {

// Solves A x = b (A row-major, n×n). False when A is singular to working precision.
inline bool solveLinearSystem(std::vector<double> a, std::vector<double> b, std::vector<double> *x)
{
    const size_t n = b.size();
    for (size_t c = 0; c < n; ++c) {
        size_t p = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::fabs(a[r * n + c]) > std::fabs(a[p * n + c])) p = r;
        if (std::fabs(a[p * n + c]) < 1e-14) return false;
        if (p != c) {
            for (size_t k = 0; k < n; ++k) std::swap(a[p * n + k], a[c * n + k]);
            std::swap(b[p], b[c]);
        }
        for (size_t r = c + 1; r < n; ++r) {
            const double f = a[r * n + c] / a[c * n + c];
            for (size_t k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
            b[r] -= f * b[c];
        }
    }
    x->assign(n, 0);
    for (size_t c = n; c-- > 0;) {
        double s = b[c];
        for (size_t k = c + 1; k < n; ++k) s -= a[c * n + k] * (*x)[k];
        (*x)[c] = s / a[c * n + c];
    }
    return true;
}

} // namespace icacam::host
