#include "vision/specimen_locator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace icacam::vision {

namespace {

// Integer square root (floor) for the gradient norm.
uint32_t isqrt(uint32_t v)
{
    uint32_t r = 0, bit = 1u << 30;
    while (bit > v) bit >>= 2;
    while (bit) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else
            r >>= 1;
        bit >>= 2;
    }
    return r;
}

// Whether any of the four 16-bit values from p reaches t (t ≤ 2^15): a lane's top bit, or
// the top bit of its low 15 bits + 2^15 − t, which borrows from no neighbouring lane. Four
// cells per test where most cells are skipped (weak gradients, empty accumulator cells).
bool anyOfFourReaches(const uint16_t *p, uint32_t t)
{
    if (t > 0x8000) return true; // beyond the trick's range: the caller tests each cell
    constexpr uint64_t kTop = 0x8000800080008000ull;
    uint64_t m;
    std::memcpy(&m, p, sizeof m);
    const uint64_t t4 = uint64_t(t) * 0x0001000100010001ull;
    return ((m | (((m & ~kTop) | kTop) - t4)) & kTop) != 0;
}

// The decimated frame's geometry: D×D pixel cells, W × H of them, and where in a cell its
// four samples lie.
struct Cells {
    int D, W, H, off, step2;
};

// Decimate: mean of 4 pixels spread over each D×D cell, at a quarter and three quarters of
// its width and height. Spread (not a 2×2 block at the centre) so that an edge crossing the
// cell shades it in proportion: point samples would turn the circles into staircases whose
// Sobel directions scatter the votes by a cell or two.
void decimate(const LumaView &v, const Cells &c, uint8_t *dec)
{
    // For D ≥ 2 the second pixel (off + D/2 < D) stays inside the cell and so inside the
    // frame (W·D ≤ width): no clamping; for D = 1 the "block" is the pixel itself.
    const size_t ps = size_t(v.pixelStep);
    const size_t colStep = size_t(c.D) * ps, pairStep = size_t(c.step2) * ps;
    for (int y = 0; y < c.H; ++y) {
        const uint8_t *r0 = v.data + size_t(y * c.D + c.off) * size_t(v.stride) + size_t(c.off) * ps;
        const uint8_t *r1 = r0 + size_t(c.step2) * size_t(v.stride);
        uint8_t *out = dec + y * c.W;
        for (int x = 0; x < c.W; ++x, r0 += colStep, r1 += colStep)
            out[x] = uint8_t((r0[0] + r0[pairStep] + r1[0] + r1[pairStep] + 2) >> 2);
    }
}

// Sobel L1 magnitudes into mag, and the voters' threshold: the 96th percentile, so that the
// voters are the strongest edges whatever the exposure (and at least 16).
int gradientThreshold(const uint8_t *dec, int W, int H, uint16_t *mag)
{
    uint32_t hist[1024] = {};
    for (int y = 1; y < H - 1; ++y) {
        // One row of magnitudes in a loop the compiler can vectorise, then its histogram.
        const uint8_t *a = dec + (y - 1) * W, *b = dec + y * W, *c = dec + (y + 1) * W;
        uint16_t *m = mag + y * W;
        for (int x = 1; x < W - 1; ++x) {
            const int gx = (a[x + 1] + 2 * b[x + 1] + c[x + 1]) - (a[x - 1] + 2 * b[x - 1] + c[x - 1]);
            const int gy = (c[x - 1] + 2 * c[x] + c[x + 1]) - (a[x - 1] + 2 * a[x] + a[x + 1]);
            m[x] = uint16_t(std::min(1023, (std::abs(gx) + std::abs(gy)) >> 1));
        }
        for (int x = 1; x < W - 1; ++x) hist[m[x]]++;
    }
    const uint32_t total = uint32_t(W - 2) * uint32_t(H - 2);
    uint32_t above = 0;
    int thr = 1023;
    while (thr > 0 && above + hist[thr] < total / 25) above += hist[thr--];
    return std::max(thr, 16);
}

// Every voter above the threshold votes along its gradient, both ways, at radii rLo … rHi.
void vote(const uint8_t *dec, const uint16_t *mag, int thr, int W, int H, int rLo, int rHi, uint16_t *acc)
{
    auto sobel = [&](int x, int y, int *gx, int *gy) {
        const uint8_t *p = dec + y * W + x;
        *gx = (p[-W + 1] + 2 * p[1] + p[W + 1]) - (p[-W - 1] + 2 * p[-1] + p[W - 1]);
        *gy = (p[W - 1] + 2 * p[W] + p[W + 1]) - (p[-W - 1] + 2 * p[-W] + p[-W + 1]);
    };
    for (int y = 1; y < H - 1; ++y)
        for (int x = 1; x < W - 1; ++x) {
            if (x + 4 <= W - 1 && !anyOfFourReaches(mag + y * W + x, uint32_t(thr))) {
                x += 3;
                continue;
            }
            if (mag[y * W + x] < thr) continue;
            int gx, gy;
            sobel(x, y, &gx, &gy);
            const int norm = int(isqrt(uint32_t(gx * gx + gy * gy)));
            if (norm == 0) continue;
            // Unit vector in Q2.14; vote along both directions (either edge polarity).
            const int ux = gx * 16384 / norm, uy = gy * 16384 / norm;
            // Every other radius, alternating with the cell's parity: a circle's votes still
            // land within the 3×3 peak sum, and neighbouring voters cover the radii between,
            // at half the votes.
            for (int r = rLo + ((x + y) & 1); r <= rHi; r += 2) {
                const int dx = (r * ux + 8192) >> 14, dy = (r * uy + 8192) >> 14;
                // One unsigned comparison covers both ends of each axis.
                unsigned cx = unsigned(x + dx), cy = unsigned(y + dy);
                if (cx < unsigned(W) && cy < unsigned(H) && acc[cy * W + cx] < 65535) acc[cy * W + cx]++;
                cx = unsigned(x - dx);
                cy = unsigned(y - dy);
                if (cx < unsigned(W) && cy < unsigned(H) && acc[cy * W + cx] < 65535) acc[cy * W + cx]++;
            }
        }
}

// Peak of the 3×3 sums, then the vote-weighted centroid around it. A cell below a quarter of
// the highest single cell cannot hold the best 3×3 sum's centre in practice (the peak's cell
// carries the most votes of its block), so it is skipped.
CentreEstimate peakOf(const uint16_t *acc, const Cells &c)
{
    const int W = c.W, H = c.H;
    CentreEstimate est;
    uint64_t sum = 0;
    uint16_t top = 0;
    for (int y = 1; y < H - 1; ++y)
        for (int x = 1; x < W - 1; ++x) {
            sum += acc[y * W + x];
            top = std::max(top, acc[y * W + x]);
        }
    int best = -1, bx = 0, by = 0;
    const uint32_t quarter = (uint32_t(top) + 3) / 4; // a · 4 < top ⇔ a < ⌈top / 4⌉
    for (int y = 1; y < H - 1; ++y)
        for (int x = 1; x < W - 1; ++x) {
            const uint16_t *a = acc + y * W + x;
            if (x + 4 <= W - 1 && !anyOfFourReaches(a, quarter)) {
                x += 3;
                continue;
            }
            if (a[0] * 4 < top) continue;
            const int s = a[-W - 1] + a[-W] + a[-W + 1] + a[-1] + a[0] + a[1] + a[W - 1] + a[W] + a[W + 1];
            if (s > best) {
                best = s;
                bx = x;
                by = y;
            }
        }
    if (best <= 0) return est;
    double sx = 0, sy = 0, sw = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const double w = acc[(by + dy) * W + bx + dx];
            sx += w * dx;
            sy += w * dy;
            sw += w;
        }
    est.x = (bx + sx / sw) * c.D + c.off + 0.5 * c.step2;
    est.y = (by + sy / sw) * c.D + c.off + 0.5 * c.step2;
    est.votes = best;
    est.background = int(sum * 900 / std::max<uint64_t>(1, uint64_t(W - 2) * (H - 2)));
    est.found = true;
    return est;
}

} // namespace

CentreEstimate SpecimenLocator::locate(const LumaView &v, double rMinPx, double rMaxPx)
{
    const int maxDim = std::max(v.width, v.height);
    Cells c;
    c.D = std::max(1, (maxDim + kMaxCells - 1) / kMaxCells);
    c.W = v.width / c.D, c.H = v.height / c.D;
    if (c.W < 8 || c.H < 8) return CentreEstimate{};
    c.off = c.D >= 2 ? c.D / 4 : 0;
    c.step2 = c.D >= 2 ? c.D / 2 : 0;

    uint8_t *dec = work_;                                                                    // W × H luma
    uint16_t *acc = reinterpret_cast<uint16_t *>(work_ + size_t(kMaxCells) * kMaxCells * 3); // votes
    // L1 gradient magnitudes, kept for the voting pass (the second part of the work area).
    uint16_t *mag = reinterpret_cast<uint16_t *>(work_ + size_t(kMaxCells) * kMaxCells);
    std::fill(acc, acc + size_t(c.W) * c.H, uint16_t(0));
    decimate(v, c, dec);
    const int thr = gradientThreshold(dec, c.W, c.H, mag);
    const int rLo = std::max(2, int(rMinPx / c.D));
    const int rHi = std::max(rLo + 1, int(rMaxPx / c.D + 1));
    vote(dec, mag, thr, c.W, c.H, rLo, rHi, acc);
    return peakOf(acc, c);
}

} // namespace icacam::vision
