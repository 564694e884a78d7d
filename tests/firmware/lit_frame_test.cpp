// The photometric lit-frame check on synthetic frames: an end face (a bright disc with a
// darker contact ring) on a fixture, lit by ambient light and the LED ring, read out by a
// rolling shutter: each row is exposed for kExposureRows row-times, starting one row-time
// after the row above it, so an LED that switches during the frame lights some rows fully,
// some in part and some not at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "firmware/lit_frame.h"
#include "tests/support/allocation_counter.h"

namespace {

using namespace icacam;
using fw::LitVerdict;

constexpr int W = 320, H = 240;
constexpr double kExposureRows = 30; // the exposure, in row-times

double reflectance(int x, int y)
{
    const double dx = x - W / 2.0, dy = y - H / 2.0, r = std::sqrt(dx * dx + dy * dy);
    if (r < 60) return 0.75;   // the original end face
    if (r < 70) return 0.25;   // the contact ring
    return 0.35 + 0.1 * x / W; // the fixture, a little brighter to the right
}

// Light on the specimen: ambient plus the LED's share of each row's exposure.
struct Scene {
    double ambient = 40;    // luma levels on a white surface
    double led = 200;       // what the LED ring adds on a white surface, fully exposed
    double ledOnRow = -1e9; // the row whose exposure starts as the LED comes on
    double ledOffRow = 1e9; // ... as it goes off
    double (*reflect)(int, int) = reflectance;
};

double litShare(const Scene &s, int y)
{
    // Row y is exposed over [y, y + kExposureRows) in row-times; the LED is on over [on, off).
    const double from = std::max<double>(y, s.ledOnRow), to = std::min<double>(y + kExposureRows, s.ledOffRow);
    return std::clamp((to - from) / kExposureRows, 0.0, 1.0);
}

std::vector<uint8_t> render(const Scene &s, int step = 1, uint8_t filler = 0)
{
    std::vector<uint8_t> px(size_t(W) * H * size_t(step), filler);
    uint32_t noise = 12345;
    for (int y = 0; y < H; ++y) {
        const double share = litShare(s, y);
        for (int x = 0; x < W; ++x) {
            noise = noise * 1664525u + 1013904223u; // a fixed +-2 level sensor noise
            const double v = s.reflect(x, y) * (s.ambient + s.led * share) + double(noise >> 30) - 1.5;
            px[(size_t(y) * W + size_t(x)) * size_t(step)] = uint8_t(std::clamp(std::lround(v), 0L, 255L));
        }
    }
    return px;
}

fw::LumaPlane plane(const std::vector<uint8_t> &px, int step = 1)
{
    return {px.data(), W, H, W * step, step};
}

Scene off()
{
    Scene s;
    s.ledOnRow = 1e9; // never on
    return s;
}

Scene on()
{
    return Scene{};
}

// The LED comes on as row `row` starts its exposure: rows above row - kExposureRows see none.
Scene lateLed(double row)
{
    Scene s;
    s.ledOnRow = row;
    return s;
}

class LitFrame : public ::testing::TestWithParam<bool> { // with or without the LED-on reference
protected:
    void SetUp() override
    {
        dark_ = render(off());
        lit_ = render(on());
        ASSERT_TRUE(check_.setDarkReference(plane(dark_)));
        if (GetParam()) { ASSERT_TRUE(check_.setLitReference(plane(lit_))); }
    }
    fw::LitCheckResult run(const Scene &s)
    {
        frame_ = render(s);
        return check_.check(plane(frame_));
    }
    fw::LitFrameCheck check_;
    std::vector<uint8_t> dark_, lit_, frame_;
};

TEST_P(LitFrame, AFullyLitFrameIsLit)
{
    const auto r = run(on());
    EXPECT_EQ(r.verdict, LitVerdict::Lit) << r.reason;
    EXPECT_EQ(r.litBands, 8);
    for (int b = 0; b < r.bands; ++b) EXPECT_GT(r.rise[b], 50) << b;
}

TEST_P(LitFrame, ADarkFrameIsNotLitEvenWithTheAmbientLightAlittleUp)
{
    Scene s = off();
    s.ambient = 44; // a door opened
    const auto r = run(s);
    EXPECT_EQ(r.verdict, LitVerdict::NotLit) << r.reason;
    EXPECT_EQ(r.litBands, 0);
}

TEST_P(LitFrame, ALateLedLightsTheBottomOnlyAndIsRefused)
{
    // On as row 150 starts: rows 0-120 dark, 120-150 in part, 150-239 fully lit.
    const auto r = run(lateLed(150));
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    EXPECT_FALSE(r.litAtTop);
    EXPECT_NE(std::string(r.reason).find("came on"), std::string::npos) << r.reason;
    EXPECT_GE(r.litBands, 2);
    EXPECT_LT(r.litBands, 8);
}

TEST_P(LitFrame, AnLedThatWentOffEarlyLightsTheTopOnlyAndIsRefused)
{
    Scene s;
    s.ledOffRow = 100;
    const auto r = run(s);
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    EXPECT_TRUE(r.litAtTop);
    EXPECT_NE(std::string(r.reason).find("went off"), std::string::npos) << r.reason;
}

TEST_P(LitFrame, AFrameWhoseTopBandGotAThirdOfTheLightIsPartlyLit)
{
    // On as row 35 starts: row 5 gets none, row 29 most; every band has some light, the
    // top one about a third, the rest all of it.
    const auto r = run(lateLed(35));
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    EXPECT_FALSE(r.litAtTop);
    EXPECT_LT(r.rise[0], 0.5 * r.rise[7]);
}

TEST_P(LitFrame, OneLateRowOfTheFirstBandIsNotEnoughToRefuse)
{
    // The LED came on as row 1 started: row 0 lost 1/30 of its light.
    const auto r = run(lateLed(1));
    EXPECT_EQ(r.verdict, LitVerdict::Lit) << r.reason;
}

TEST_P(LitFrame, ADarkSliverThinnerThanABandAtTheBottomIsRefused)
{
    // The last three rows of 240 saw only the room light (a short exposure read out as the
    // ring went off): the last band keeps 90 % of its light, its strips do not.
    std::vector<uint8_t> px = render(on());
    std::copy(dark_.begin() + ptrdiff_t(W * (H - 3)), dark_.end(), px.begin() + ptrdiff_t(W * (H - 3)));
    const auto r = check_.check(plane(px));
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    EXPECT_TRUE(r.litAtTop);
    EXPECT_GE(r.darkStrips, 1);
    EXPECT_EQ(r.litBands, 8); // every band, on its own, lit
}

TEST_P(LitFrame, ADarkSliverAtTheTopIsRefusedToo)
{
    std::vector<uint8_t> px = render(on());
    std::copy(dark_.begin(), dark_.begin() + ptrdiff_t(W * 2), px.begin());
    const auto r = check_.check(plane(px));
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    EXPECT_FALSE(r.litAtTop);
}

INSTANTIATE_TEST_SUITE_P(References, LitFrame, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool> &p) { return p.param ? "LedOnToo" : "LedOffOnly"; });

double darkTopBrightBottom(int, int y)
{
    return y < H / 2 ? 0.15 : 0.8;
}

TEST(LitFrameReference, TheLedOnReferenceCancelsAScenesOwnTopToBottomContrast)
{
    Scene offScene = off(), onScene = on();
    offScene.reflect = onScene.reflect = darkTopBrightBottom;
    const auto dark = render(offScene), lit = render(onScene);
    fw::LitFrameCheck check;
    ASSERT_TRUE(check.setDarkReference(plane(dark)));
    // The LED-off reference alone cannot tell a dark top from an unlit one.
    auto r = check.check(plane(lit));
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    // With the LED-on reference, the same frame is lit: each band's share of the LED is 1.
    ASSERT_TRUE(check.setLitReference(plane(lit)));
    const auto again = render(onScene);
    r = check.check(plane(again));
    EXPECT_EQ(r.verdict, LitVerdict::Lit) << r.reason;
    for (int b = 0; b < r.bands; ++b) EXPECT_NEAR(r.fraction[b], 1.0, 0.05) << b;
    // And a late LED over it is still refused.
    Scene late = lateLed(150);
    late.reflect = darkTopBrightBottom;
    const auto partial = render(late);
    r = check.check(plane(partial));
    EXPECT_EQ(r.verdict, LitVerdict::PartlyLit) << r.reason;
    check.clearLitReference();
    EXPECT_FALSE(check.hasLitReference());
}

TEST(LitFrameReference, YuyvIsReadThroughItsPixelStep)
{
    const auto dark = render(off(), 2, 255), lit = render(on(), 2, 255), late = render(lateLed(150), 2, 255);
    fw::LitFrameCheck check;
    ASSERT_TRUE(check.setDarkReference(plane(dark, 2)));
    EXPECT_EQ(check.check(plane(lit, 2)).verdict, LitVerdict::Lit);
    EXPECT_EQ(check.check(plane(late, 2)).verdict, LitVerdict::PartlyLit);
    EXPECT_EQ(check.check(plane(dark, 2)).verdict, LitVerdict::NotLit);
}

TEST(LitFrameReference, OnlyTheRegionCounts)
{
    // The LED lights rows 80-160 fully (on as row 50 starts, off as row 190 does); the
    // region is those rows.
    fw::LitFrameOptions o;
    o.region = {40, 80, 240, 80};
    fw::LitFrameCheck check(o);
    const auto dark = render(off());
    ASSERT_TRUE(check.setDarkReference(plane(dark)));
    Scene s;
    s.ledOnRow = 80 - kExposureRows;
    s.ledOffRow = 160 + kExposureRows;
    const auto frame = render(s);
    EXPECT_EQ(check.check(plane(frame)).verdict, LitVerdict::Lit);
    fw::LitFrameCheck whole;
    ASSERT_TRUE(whole.setDarkReference(plane(dark)));
    EXPECT_EQ(whole.check(plane(frame)).verdict, LitVerdict::PartlyLit);
}

TEST(LitFrameReference, NothingIsDecidedWithoutAFittingReference)
{
    const auto lit = render(on());
    fw::LitFrameCheck check;
    auto r = check.check(plane(lit));
    EXPECT_EQ(r.verdict, LitVerdict::NoReference);
    EXPECT_STREQ(fw::litVerdictName(r.verdict), "no_reference");
    const auto dark = render(off());
    ASSERT_TRUE(check.setDarkReference(plane(dark)));
    fw::LumaPlane smaller = plane(lit);
    smaller.width = W / 2; // another frame size
    EXPECT_EQ(check.check(smaller).verdict, LitVerdict::NoReference);
    // A region outside the frame, and options out of range, are refused as references.
    fw::LitFrameOptions o;
    o.region = {300, 0, 100, 100};
    EXPECT_FALSE(fw::LitFrameCheck(o).setDarkReference(plane(dark)));
    o = {};
    o.bands = 40;
    EXPECT_FALSE(fw::LitFrameCheck(o).setDarkReference(plane(dark)));
    EXPECT_FALSE(check.setDarkReference({}));
    EXPECT_TRUE(check.hasDarkReference()); // the old one kept
}

TEST(LitFrameReference, ACheckAllocatesNothing)
{
    const auto dark = render(off()), lit = render(on()), late = render(lateLed(150));
    fw::LitFrameCheck check;
    ASSERT_TRUE(check.setDarkReference(plane(dark)));
    ASSERT_TRUE(check.setLitReference(plane(lit)));
    const long before = test::allocationCount();
    const auto a = check.check(plane(lit));
    const auto b = check.check(plane(late));
    const long after = test::allocationCount();
    EXPECT_EQ(after, before);
    EXPECT_EQ(a.verdict, LitVerdict::Lit);
    EXPECT_EQ(b.verdict, LitVerdict::PartlyLit);
}

} // namespace

double darkBackdropAtTheBottom(int x, int y)
{
    return y >= H - 4 ? 0.2 : reflectance(x, y);
}

TEST(LitFrameReference, ADarkBackdropAtTheEdgeIsNotTakenForADarkSliver)
{
    // The last rows are a dark surface, lit top to bottom: their rise is small, but so is
    // their luma without the ring, and the ratio of the two is the band's.
    Scene offScene = off(), onScene = on();
    offScene.reflect = onScene.reflect = darkBackdropAtTheBottom;
    const std::vector<uint8_t> dark = render(offScene), lit = render(onScene);
    fw::LitFrameCheck check;
    ASSERT_TRUE(check.setDarkReference(plane(dark)));
    const auto r = check.check(plane(lit));
    EXPECT_EQ(r.verdict, LitVerdict::Lit) << r.reason;
    EXPECT_EQ(r.darkStrips, 0);
}
