#include "firmware/lit_frame.h"

#include <algorithm>
#include <cmath>

namespace icacam::fw {

namespace {

bool optionsValid(const LitFrameOptions &o)
{
    return o.bands >= 2 && o.bands <= LitFrameCheck::kMaxBands && o.minRiseLevels >= 1 && o.darkFraction >= 0 &&
           o.darkFraction < o.litFraction && o.litFraction <= 1.5 && o.partialRatio >= 0 && o.partialRatio < 1 &&
           o.maxSamples >= o.bands && o.edgeStrips >= 0 && o.edgeStrips <= LitFrameCheck::kMaxEdgeStrips;
}

const char *partlyReason(bool litAtTop)
{
    return litAtTop ? "lit at the top only: the LED ring went off before the last rows were exposed"
                    : "lit at the bottom only: the LED ring came on after the first rows were exposed";
}

} // namespace

const char *litVerdictName(LitVerdict v)
{
    switch (v) {
    case LitVerdict::Lit: return "lit";
    case LitVerdict::NotLit: return "not_lit";
    case LitVerdict::PartlyLit: return "partly_lit";
    case LitVerdict::NoReference: return "no_reference";
    }
    return "unknown";
}

LitFrameCheck::LitFrameCheck(const LitFrameOptions &options) : options_(options) {}

// The band means over a grid of at most maxSamples pixels. The grid depends only on the
// region's size, so a frame and its references are sampled at the same pixels.
bool LitFrameCheck::measure(const LumaPlane &p, Bands *out) const
{
    const LitFrameOptions &o = options_;
    if (!optionsValid(o) || !p.data || p.width <= 0 || p.height <= 0 || p.pixelStep < 1 ||
        p.stride < p.width * p.pixelStep)
        return false;
    const int x0 = o.region.width > 0 && o.region.height > 0 ? o.region.x : 0;
    const int y0 = o.region.width > 0 && o.region.height > 0 ? o.region.y : 0;
    const int w = o.region.width > 0 && o.region.height > 0 ? o.region.width : p.width;
    const int h = o.region.width > 0 && o.region.height > 0 ? o.region.height : p.height;
    if (x0 < 0 || y0 < 0 || x0 + w > p.width || y0 + h > p.height || h < o.bands) return false;
    const double area = double(w) * double(h);
    int step = int(std::ceil(std::sqrt(area / double(o.maxSamples))));
    if (step < 1) step = 1;
    for (int b = 0; b < o.bands; ++b) {
        const int top = y0 + int(int64_t(h) * b / o.bands);
        const int bottom = y0 + int(int64_t(h) * (b + 1) / o.bands);
        uint64_t sum = 0, count = 0;
        // At least the band's first row, however coarse the grid.
        for (int y = top; y < bottom; y += step) {
            const uint8_t *row = p.data + size_t(y) * size_t(p.stride) + size_t(x0) * size_t(p.pixelStep);
            for (int x = 0; x < w; x += step) sum += row[size_t(x) * size_t(p.pixelStep)];
            count += uint64_t((w + step - 1) / step);
        }
        out->mean[b] = count ? float(double(sum) / double(count)) : 0.f;
    }
    // The end bands' strips: every row of them, on the grid's columns.
    const int bandRows = h / o.bands;
    const int stripRows = o.edgeStrips > 0 ? std::max(1, bandRows / o.edgeStrips) : 0;
    for (int end = 0; end < 2; ++end)
        for (int k = 0; k < o.edgeStrips; ++k) {
            const int first = end == 0 ? y0 + k * stripRows : y0 + h - (k + 1) * stripRows;
            uint64_t sum = 0, count = 0;
            for (int y = first; y < first + stripRows; ++y) {
                const uint8_t *row = p.data + size_t(y) * size_t(p.stride) + size_t(x0) * size_t(p.pixelStep);
                for (int x = 0; x < w; x += step) sum += row[size_t(x) * size_t(p.pixelStep)];
                count += uint64_t((w + step - 1) / step);
            }
            out->edge[end][k] = count ? float(double(sum) / double(count)) : 0.f;
        }
    out->width = p.width;
    out->height = p.height;
    return true;
}

bool LitFrameCheck::setDarkReference(const LumaPlane &ledOff)
{
    Bands b;
    if (!measure(ledOff, &b)) return false;
    dark_ = b;
    hasDark_ = true;
    return true;
}

bool LitFrameCheck::setLitReference(const LumaPlane &ledOn)
{
    Bands b;
    if (!measure(ledOn, &b)) return false;
    lit_ = b;
    hasLit_ = true;
    return true;
}

LitCheckResult LitFrameCheck::check(const LumaPlane &frame) const
{
    const LitFrameOptions &o = options_;
    LitCheckResult r;
    r.bands = o.bands;
    if (!hasDark_) {
        r.reason = "no LED-off reference";
        return r;
    }
    Bands f;
    if (!measure(frame, &f)) {
        r.reason = "the frame does not fit the region";
        return r;
    }
    if (f.width != dark_.width || f.height != dark_.height) {
        r.reason = "the frame is another size than the LED-off reference";
        return r;
    }
    const int n = o.bands;
    const float minRise = float(o.minRiseLevels);
    for (int b = 0; b < n; ++b) {
        r.mean[b] = f.mean[b];
        r.rise[b] = f.mean[b] - dark_.mean[b];
        r.fraction[b] = -1.f;
    }

    // With the LED-on reference: each band's share of the LED's contribution.
    if (hasLit_ && lit_.width == f.width && lit_.height == f.height) {
        int informative = 0, lit = 0, dark = 0, first = -1, last = -1;
        for (int b = 0; b < n; ++b) {
            const float ledRise = lit_.mean[b] - dark_.mean[b];
            if (ledRise < minRise) continue; // the LED hardly reaches this band: it says nothing
            r.fraction[b] = r.rise[b] / ledRise;
            ++informative;
            if (first < 0) first = b;
            last = b;
            if (r.fraction[b] >= float(o.litFraction))
                ++lit;
            else if (r.fraction[b] <= float(o.darkFraction))
                ++dark;
        }
        if (informative > 0) {
            r.litBands = lit;
            if (lit == informative) {
                r.verdict = LitVerdict::Lit;
                r.reason = "lit top to bottom";
                checkEdges(f, &r);
            } else if (dark == informative) {
                r.verdict = LitVerdict::NotLit;
                r.reason = "not lit: the LED ring is off or does not reach the specimen";
            } else {
                r.verdict = LitVerdict::PartlyLit;
                r.litAtTop = r.fraction[first] > r.fraction[last];
                r.reason = partlyReason(r.litAtTop);
            }
            return r;
        }
    }

    // The LED-off reference alone: each band's rise over it, and the two ends compared.
    int lit = 0;
    for (int b = 0; b < n; ++b) lit += r.rise[b] >= minRise ? 1 : 0;
    r.litBands = lit;
    const float top = r.rise[0], bottom = r.rise[n - 1];
    if (lit == 0) {
        r.verdict = LitVerdict::NotLit;
        r.reason = "not lit: the LED ring is off or does not reach the specimen";
    } else if (lit < n) {
        r.verdict = LitVerdict::PartlyLit;
        r.litAtTop = top > bottom;
        r.reason = partlyReason(r.litAtTop);
    } else if (o.partialRatio > 0 && std::fmin(top, bottom) < float(o.partialRatio) * std::fmax(top, bottom)) {
        r.verdict = LitVerdict::PartlyLit;
        r.litAtTop = top > bottom;
        r.reason = partlyReason(r.litAtTop);
    } else {
        r.verdict = LitVerdict::Lit;
        r.reason = "lit top to bottom";
        checkEdges(f, &r);
    }
    return r;
}

void LitFrameCheck::checkEdges(const Bands &f, LitCheckResult *r) const
{
    const LitFrameOptions &o = options_;
    const bool withLit = hasLit_ && lit_.width == f.width && lit_.height == f.height;
    const float minRise = float(o.minRiseLevels), minOff = minRise / 2;
    for (int end = 0; end < 2; ++end) {
        const int band = end == 0 ? 0 : o.bands - 1;
        const float bandOff = dark_.mean[band];
        const float bandRatio = bandOff >= minOff ? (f.mean[band] - bandOff) / bandOff : 0;
        for (int k = 0; k < o.edgeStrips; ++k) {
            const float off = dark_.edge[end][k], rise = f.edge[end][k] - off;
            bool dark = false;
            if (withLit && lit_.edge[end][k] - off >= minRise)
                dark = rise < float(o.litFraction) * (lit_.edge[end][k] - off);
            else if (!withLit && off >= minOff && bandRatio > 0)
                dark = rise / off < float(o.litFraction) * bandRatio;
            r->darkStrips += dark ? 1 : 0;
            if (dark && r->verdict == LitVerdict::Lit) {
                r->verdict = LitVerdict::PartlyLit;
                r->litAtTop = end == 1;
                r->reason = partlyReason(r->litAtTop);
            }
        }
    }
}

} // namespace icacam::fw
