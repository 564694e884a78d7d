#include "vision/plane_calibration.h"

#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <numbers>

namespace icacam::vision {

namespace {

__extension__ typedef __int128 Wide; // GCC and Clang on every 64-bit target we build for

constexpr int kFrac = Q32_32::kFracBits;
constexpr int64_t kOne = int64_t(1) << kFrac;

int64_t saturate(Wide v)
{
    if (v > Wide(INT64_MAX)) return INT64_MAX;
    if (v < Wide(INT64_MIN)) return INT64_MIN;
    return int64_t(v);
}
// a·b and a/b in Q32.32, rounded to nearest, saturated.
int64_t mul(int64_t a, int64_t b)
{
    return saturate((Wide(a) * Wide(b) + (Wide(1) << (kFrac - 1))) >> kFrac);
}
int64_t div(int64_t a, int64_t b)
{
    if (b == 0) return a >= 0 ? INT64_MAX : INT64_MIN;
    Wide n = Wide(a) << kFrac;
    // Round half away from zero.
    const Wide half = (b > 0 ? Wide(b) : -Wide(b)) / 2;
    n += (n >= 0) ? half : -half;
    return saturate(n / Wide(b));
}
int64_t fix(double v)
{
    return Q32_32::fromDouble(v).raw();
}

} // namespace

bool PlaneCalibration::valid() const
{
    auto finite = [](double v) { return std::isfinite(v); };
    for (double v : {fx, fy, cx, cy, k1, k2, p1, p2, k3, t[0], t[1], t[2], heightMm})
        if (!finite(v)) return false;
    for (double v : r)
        if (!finite(v) || std::fabs(v) > 1.0 + 1e-6) return false;
    if (!(fx > 1 && fy > 1 && fx < 1e6 && fy < 1e6)) return false;
    if (std::fabs(cx) > 1e5 || std::fabs(cy) > 1e5) return false;
    // Coefficients beyond these bend the field so far that no measurement lens has them.
    for (double k : {k1, k2, p1, p2, k3})
        if (std::fabs(k) > 1000) return false;
    // R must be a rotation (orthonormal rows) for areas in the plane to be areas.
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double d = r[3 * i] * r[3 * j] + r[3 * i + 1] * r[3 * j + 1] + r[3 * i + 2] * r[3 * j + 2];
            if (std::fabs(d - (i == j ? 1.0 : 0.0)) > 1e-6) return false;
        }
    return std::fabs(t[0]) < 1e6 && std::fabs(t[1]) < 1e6 && t[2] > 0 && t[2] < 1e6 && std::fabs(heightMm) < 1e5;
}

PlaneMapper::PlaneMapper(const PlaneCalibration &cal)
{
    if (!cal.valid()) return;
    fx_ = fix(cal.fx);
    fy_ = fix(cal.fy);
    cx_ = fix(cal.cx);
    cy_ = fix(cal.cy);
    k1_ = fix(cal.k1), k2_ = fix(cal.k2), k3_ = fix(cal.k3), p1_ = fix(cal.p1), p2_ = fix(cal.p2);
    double b[3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            rt_[3 * i + j] = fix(cal.r[3 * j + i]);
            b[i] += cal.r[3 * j + i] * cal.t[j];
        }
    for (int i = 0; i < 3; ++i) b_[i] = fix(b[i]);
    // The camera centre in fixture coordinates is −Rᵀt; "up" is the side it is on.
    const double up = -b[2] >= 0 ? 1.0 : -1.0;
    planeZ_ = fix(up * cal.heightMm);
    valid_ = true;
}

PlanePoint PlaneMapper::map(Q16_16 px, Q16_16 py) const
{
    PlanePoint out;
    if (!valid_) return out;
    // Pixel → distorted normalized coordinates (Q16.16 → Q32.32 is a shift).
    // A quotient, not a product with 1/f: 1/f in Q32.32 would carry a 1e-6 relative error.
    const int64_t xd = div((int64_t(px.raw()) << (kFrac - 16)) - cx_, fx_);
    const int64_t yd = div((int64_t(py.raw()) << (kFrac - 16)) - cy_, fy_);
    if (std::llabs(xd) >= kOne || std::llabs(yd) >= kOne) return out;

    // Undistort by fixed-point iteration (as OpenCV's undistortPoints does): solve
    // x·radial(x) + tangential(x) = x_d for x, starting from x = x_d. It converges where
    // the distortion's slope is gentle, which is everywhere in a measuring lens's field;
    // the distorted residual is checked afterwards, so a field where it does not is
    // reported, not returned.
    auto distort = [&](int64_t x, int64_t y, int64_t *dxOut, int64_t *dyOut, int64_t *radial) {
        const int64_t x2 = mul(x, x), y2 = mul(y, y), xy = mul(x, y);
        const int64_t r2 = x2 + y2, r4 = mul(r2, r2), r6 = mul(r4, r2);
        *radial = kOne + mul(k1_, r2) + mul(k2_, r4) + mul(k3_, r6);
        *dxOut = mul(2 * p1_, xy) + mul(p2_, r2 + 2 * x2);
        *dyOut = mul(p1_, r2 + 2 * y2) + mul(2 * p2_, xy);
    };
    int64_t x = xd, y = yd;
    for (int it = 0; it < kMaxIterations; ++it) {
        int64_t dx, dy, radial;
        distort(x, y, &dx, &dy, &radial);
        if (radial <= kOne / 16) return out; // the radial factor folds over here
        const int64_t nx = div(xd - dx, radial), ny = div(yd - dy, radial);
        const bool done = std::llabs(nx - x) <= 2 && std::llabs(ny - y) <= 2;
        x = nx, y = ny;
        if (std::llabs(x) >= 2 * kOne || std::llabs(y) >= 2 * kOne) return out;
        if (done) break;
    }
    {
        int64_t dx, dy, radial;
        distort(x, y, &dx, &dy, &radial);
        const int64_t ex = mul(x, radial) + dx - xd, ey = mul(y, radial) + dy - yd;
        // 2^-22 in normalized units is under 1/1000 px for any focal length below 4000 px.
        if (std::llabs(ex) > (kOne >> 22) || std::llabs(ey) > (kOne >> 22)) return out;
    }

    // Back-project: the ray (x, y, 1) in camera coordinates is Rᵀ(x, y, 1) in fixture
    // axes from the camera centre −Rᵀt; intersect it with z = planeZ.
    const int64_t ax = mul(rt_[0], x) + mul(rt_[1], y) + rt_[2];
    const int64_t ay = mul(rt_[3], x) + mul(rt_[4], y) + rt_[5];
    const int64_t az = mul(rt_[6], x) + mul(rt_[7], y) + rt_[8];
    if (std::llabs(az) < (kOne >> 12)) return out;   // ray nearly parallel to the plane
    const int64_t lambda = div(planeZ_ + b_[2], az); // distance along the ray, mm
    if (lambda <= 0) return out;                     // plane behind the camera
    out.x = Q32_32::fromRaw(mul(lambda, ax) - b_[0]);
    out.y = Q32_32::fromRaw(mul(lambda, ay) - b_[1]);
    out.valid = true;
    return out;
}

PlanePoint pixelToPlane(const PlaneCalibration &cal, double px, double py)
{
    return PlaneMapper(cal).map(Q16_16::fromDouble(px), Q16_16::fromDouble(py));
}

double planeScaleAt(const PlaneCalibration &cal, double px, double py)
{
    const PlaneMapper m(cal);
    const double h = 8; // pixels: the map is smooth, and Q16.16 steps are far below this
    const PlanePoint a = m.map(Q16_16::fromDouble(px - h), Q16_16::fromDouble(py));
    const PlanePoint b = m.map(Q16_16::fromDouble(px + h), Q16_16::fromDouble(py));
    const PlanePoint c = m.map(Q16_16::fromDouble(px), Q16_16::fromDouble(py - h));
    const PlanePoint d = m.map(Q16_16::fromDouble(px), Q16_16::fromDouble(py + h));
    if (!(a.valid && b.valid && c.valid && d.valid)) return 0;
    const double jxx = (b.x - a.x).toDouble(), jyx = (b.y - a.y).toDouble();
    const double jxy = (d.x - c.x).toDouble(), jyy = (d.y - c.y).toDouble();
    return std::sqrt(std::fabs(jxx * jyy - jxy * jyx)) / (2 * h);
}

PlaneOutline planeOutline(const BoundaryFit &fit, double centreX, double centreY, const PlaneCalibration &cal)
{
    PlaneOutline out;
    const PlaneMapper m(cal);
    if (!m.valid()) return out;
    // cos, sin of the sample angles by the rotation recurrence (no trigonometry per point).
    const double step = 2.0 * std::numbers::pi / kEquivalentRadiusSamples;
    const double cs = std::cos(step), sn = std::sin(step);
    double c = 1, s = 0;
    // Shoelace sums about the first point keep the terms small (Q32.32 → double exact):
    // area, first moments and second moments of the polygon (Green's theorem).
    double area2 = 0, mx = 0, my = 0, mxx = 0, myy = 0, mxy = 0;
    double x0 = 0, y0 = 0, xPrev = 0, yPrev = 0;
    for (int i = 0; i <= kEquivalentRadiusSamples; ++i) {
        double x, y;
        if (i < kEquivalentRadiusSamples) {
            const double r = fit.radiusAt(c, s);
            const PlanePoint p = m.map(Q16_16::fromDouble(centreX + r * c), Q16_16::fromDouble(centreY + r * s));
            if (!p.valid) return out;
            x = p.x.toDouble(), y = p.y.toDouble();
            const double cn = c * cs - s * sn;
            s = s * cs + c * sn;
            c = cn;
        } else {
            x = x0, y = y0; // close the polygon
        }
        if (i == 0) {
            x0 = x, y0 = y;
        } else {
            const double ax = xPrev - x0, ay = yPrev - y0, bx = x - x0, by = y - y0;
            const double cross = ax * by - bx * ay;
            area2 += cross;
            mx += (ax + bx) * cross;
            my += (ay + by) * cross;
            mxx += (ax * ax + ax * bx + bx * bx) * cross;
            myy += (ay * ay + ay * by + by * by) * cross;
            mxy += (2 * ax * ay + ax * by + bx * ay + 2 * bx * by) * cross;
        }
        xPrev = x, yPrev = y;
    }
    if (!(std::fabs(area2) > 0)) return out;
    // An inscribed N-gon has sin(δ)/δ of its circle's area (δ = 2π/N): undo that bias.
    out.rEqMm = std::sqrt(std::fabs(area2) * 0.5 * (step / sn) / std::numbers::pi);
    // Centroid and central second moments (the common factors cancel in the ratios).
    const double gx = mx / (3 * area2), gy = my / (3 * area2);
    const double sxx = mxx / (6 * area2) - gx * gx, syy = myy / (6 * area2) - gy * gy;
    const double sxy = mxy / (12 * area2) - gx * gy;
    out.centroidX = x0 + gx, out.centroidY = y0 + gy;
    const double mean = 0.5 * (sxx + syy), dev = std::hypot(0.5 * (sxx - syy), sxy);
    if (!(mean - dev > 0)) return out;
    out.ellipticity = 1 - std::sqrt((mean - dev) / (mean + dev));
    out.axisDeg = 0.5 * std::atan2(2 * sxy, sxx - syy) * 180.0 / std::numbers::pi;
    out.valid = true;
    return out;
}

double equivalentRadiusMm(const BoundaryFit &fit, double centreX, double centreY, const PlaneCalibration &cal)
{
    const PlaneOutline o = planeOutline(fit, centreX, centreY, cal);
    return o.valid ? o.rEqMm : 0;
}

} // namespace icacam::vision
