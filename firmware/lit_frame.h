#pragma once
// Is a captured frame lit by the LED ring, top to bottom? A photometric check that does not
// rest on timestamps: an LED, driver transistor or `led.active` fault gives a fresh dark
// frame, and a camera that buffers a frame or blends frames (temporal noise reduction) can
// hand out one lit only in part.
//
// How: the frame's region is cut into horizontal bands, top to bottom, because a rolling
// shutter exposes rows one after the other: an LED that came on late lights the bottom rows
// only, one that went off early the top rows only. Each band's mean luma (a fixed sampling
// grid, the same pixels every frame) is compared with the same band of a reference taken
// with the LED off (at start-up, refreshed by the caller when the scene may have changed)
// and, when one is given, of a reference with the LED on (aim mode, or start-up):
//  * with both references, each band's fraction of the LED's own contribution,
//    (frame − off) / (on − off), which the scene's reflectance cancels out of: a band is lit
//    at `litFraction` or more, dark at `darkFraction` or less, in between it straddled the
//    LED's edge. Bands the LED hardly reaches (on − off below `minRiseLevels`) are left out.
//  * with the LED-off reference only, each band's rise over it: lit at `minRiseLevels` or
//    more. All bands lit but the top and bottom rises more than 1 / `partialRatio` apart is
//    also taken as partly lit (the rows at one end got part of the exposure); a scene whose
//    top and bottom differ that much in reflectance needs the LED-on reference.
// A frame lit but for a few rows at its top or bottom passes the bands (a band is lit while
// the LED adds minRiseLevels to its mean), so the first and the last band are also cut into
// `edgeStrips` thin strips each (down to one row), each judged against its own band: with
// the LED-on reference, a strip with less than litFraction of the LED's light is dark; with
// the LED-off reference alone, by its rise over its luma without the ring, which the
// scene's reflectance cancels out of as long as the room light reaches it: a strip whose
// ratio is below litFraction of its band's is dark. A strip the room light hardly reaches
// (LED-off luma under minRiseLevels / 2) says nothing. A sliver thinner than a strip, or
// with no room light and no LED-on reference, is not seen.
//
// Use (the integrator's call points): configure with the specimen region; at start-up, with
// the ring off, setDarkReference(frame); optionally, with the ring on (aim mode, or the
// first start-up frame after the LED settled), setLitReference(frame); on every capture,
// check(frame): Lit is measured; NotLit and PartlyLit are refused and recaptured, and an
// error "LED ring not lit" raised if that persists. A reference is refused (false) when its
// geometry does not fit the options; a frame of another size than the references is
// NoReference. check() allocates nothing and throws nothing; its cost is one pass over at
// most `maxSamples` pixels.
#include <cstdint>

namespace icacam::fw {

// An 8-bit luma plane as the camera hands it out (not owned): Grey8 and the Y plane of NV12 /
// YUV420 with pixelStep 1, YUYV with pixelStep 2.
struct LumaPlane {
    const uint8_t *data = nullptr;
    int width = 0, height = 0;
    int stride = 0;    // bytes between rows
    int pixelStep = 1; // bytes between neighbouring pixels of a row
};

// The part of the frame that is looked at, in pixels (the specimen's end face and the fixture
// around it); width or height 0: the whole frame.
struct LitRegion {
    int x = 0, y = 0, width = 0, height = 0;
};

struct LitFrameOptions {
    int bands = 8;             // horizontal bands, 2 to LitFrameCheck::kMaxBands
    int minRiseLevels = 12;    // luma levels the LED adds, at least, to a lit band
    double litFraction = 0.7;  // with an LED-on reference: a band this lit or more is lit
    double darkFraction = 0.3; // ... this lit or less is dark; between, it straddled the edge
    // LED-off reference only: top and bottom rises further apart: partly lit (0: not compared,
    // for scenes whose reflectance differs top to bottom; each band is then judged alone).
    double partialRatio = 0.5;
    int maxSamples = 65536; // pixels read per frame (a grid over the region; the strips besides)
    int edgeStrips = 8;     // strips the first and the last band are cut into, 0 to kMaxEdgeStrips
    LitRegion region;
};

enum class LitVerdict : uint8_t {
    Lit,         // every band lit
    NotLit,      // no band lit
    PartlyLit,   // some bands lit, some not (or straddling): the frame crossed the LED's edge
    NoReference, // no LED-off reference, or one of another frame size: nothing decided
};

const char *litVerdictName(LitVerdict v); // "lit", "not_lit", "partly_lit", "no_reference"

struct LitCheckResult {
    static constexpr int kMaxBands = 16;
    static constexpr int kMaxEdgeStrips = 8;
    LitVerdict verdict = LitVerdict::NoReference;
    int bands = 0;
    float mean[kMaxBands] = {};     // the frame's band means (luma levels)
    float rise[kMaxBands] = {};     // band mean − LED-off reference
    float fraction[kMaxBands] = {}; // rise / the LED-on reference's rise; -1 without one, or uninformative
    int litBands = 0;               // bands judged lit
    int darkStrips = 0;             // edge strips judged dark (a sliver the bands did not see)
    // PartlyLit: true when the lit bands are above the dark ones (the LED went off before the
    // last rows' exposure), false when below (it came on after the first rows').
    bool litAtTop = false;
    const char *reason = ""; // words for the log and the error line (static text)
};

class LitFrameCheck {
public:
    static constexpr int kMaxBands = LitCheckResult::kMaxBands;
    static constexpr int kMaxEdgeStrips = LitCheckResult::kMaxEdgeStrips;

    explicit LitFrameCheck(const LitFrameOptions &options = {});

    // The reference frames. False (the reference left as it was): a plane the options'
    // region does not fit, or options out of range.
    bool setDarkReference(const LumaPlane &ledOff);
    bool setLitReference(const LumaPlane &ledOn);
    void clearLitReference() { hasLit_ = false; }
    bool hasDarkReference() const { return hasDark_; }
    bool hasLitReference() const { return hasLit_; }

    LitCheckResult check(const LumaPlane &frame) const;

private:
    struct Bands {
        int width = 0, height = 0; // the plane they were taken from
        float mean[kMaxBands] = {};
        float edge[2][kMaxEdgeStrips] = {}; // the first band's strips top down, the last's bottom up
    };
    // PartlyLit when a strip of the first or last band is dark (only called on a frame whose
    // bands are all lit).
    void checkEdges(const Bands &f, LitCheckResult *r) const;
    bool measure(const LumaPlane &plane, Bands *out) const;

    LitFrameOptions options_;
    Bands dark_, lit_;
    bool hasDark_ = false, hasLit_ = false;
};

} // namespace icacam::fw
