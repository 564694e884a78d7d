// The uncertainty's bars on rendered sets, one condition per test (PRODUCT.md §7,
// docs/uncertainty.md "Coverage"): `icacam measure` (default model) on 40 new scenes of a
// condition the manifest does not declare (30 through the tilted cameras: slower to render); no ok result beyond the
// tolerance (max(0.01, 5 % of μ)), at least 90 % of the results within 2 σ (σ without the model's own fit error: the
// truth is the paper's model), and where nothing is undeclared a σ that is neither inflated nor too small: median
// |Δμ|/σ between 0.3 and 1. The first two always run; the σ-ratio bar only with -DICACAM_COVERAGE_RATIO_BAR=ON: without
// a declared final height the reduction the silhouette implies is uncertain by ≈ 0.007, wider than the development
// set's exact 50 % needs (docs/uncertainty.md, "What is missing").
#include <gtest/gtest.h>

#include "tests/host_tools/coverage_support.h"

using namespace icacam;

namespace {

// The status's lines (PRODUCT.md §7): where nothing is undeclared at least 90 % of the measured
// readings ok; under an undeclared condition ok on at least half of the right readings. A
// condition the status does not yet reach keeps its measured floor here (docs/uncertainty.md,
// "What is missing"), so that it cannot slip further unseen.
struct StatusLine {
    double okShare = 0;        // of the measured readings
    double okOnRightShare = 0; // of the right readings
};

void expectBars(const std::string &condition, uint32_t seed, bool nothingUndeclared, StatusLine line, int scenes = 40)
{
#ifdef ICACAM_SANITIZED
    // Statistics, not memory: the sanitizer build runs the same code paths in the always-on
    // coverage tests, and hundreds of rendered scenes there would take most of an hour.
    GTEST_SKIP() << "coverage bars are not run under a sanitizer";
#endif
    const test::ScoredSet set = test::renderMeasureScore("bars-" + condition, condition, scenes, seed);
    const host::ConditionScore *c = set.report.find(condition);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->total, scenes);
    EXPECT_EQ(c->silentWrong, 0) << condition << ": ok results beyond the tolerance (worst ok " << c->worstOkDmu << ", "
                                 << c->worstOkId << ")";
    EXPECT_GE(c->withinFraction(), 0.9) << condition << ": " << c->withinK << " of " << c->measured << " within 2 σ";
    EXPECT_GE(c->okFraction(), line.okShare) << condition << ": " << c->ok << " of " << c->measured << " ok";
    EXPECT_GE(c->okOnRightFraction(), line.okOnRightShare)
        << condition << ": ok on " << c->okRight << " of " << c->right << " right readings";
#ifdef ICACAM_COVERAGE_RATIO_BAR
    if (nothingUndeclared) {
        EXPECT_GE(c->medianRatio, 0.3) << condition << ": σ inflated";
        EXPECT_LE(c->medianRatio, 1.0) << condition << ": σ too small";
    }
#else
    (void)nothingUndeclared;
#endif
    std::filesystem::remove_all(set.dir);
}

} // namespace

// Where the lab declares what the renderer holds exact (the final height, n and the scale,
// each to a small tolerance), σ is the edges' and the reading must neither inflate it nor
// leave the edge model's own error out: the σ-ratio bar runs here always.
TEST(CoverageBars, EverythingDeclaredExactly)
{
#ifdef ICACAM_SANITIZED
    GTEST_SKIP() << "coverage bars are not run under a sanitizer";
#endif
    const test::ScoredSet set = test::renderMeasureScore(
        "bars-exact", "declared", 120, 9107, {},
        {{"h_final_mm", "7.5"}, {"h_final_tol_mm", "0.005"}, {"n_tol", "0.001"}, {"mm_per_px_tol", "0.001"}});
    const host::ConditionScore *c = set.report.find("declared");
    ASSERT_TRUE(c);
    EXPECT_EQ(c->silentWrong, 0) << "worst ok " << c->worstOkDmu << " (" << c->worstOkId << ")";
    EXPECT_GE(c->withinFraction(), 0.9) << c->withinK << " of " << c->measured << " within 2 σ";
    EXPECT_GE(c->medianRatio, 0.3) << "σ inflated";
    EXPECT_LE(c->medianRatio, 1.0) << "σ too small";
    std::filesystem::remove_all(set.dir);
}

TEST(CoverageBars, Declared)
{
    expectBars("declared", 9101, true, {0.9, 0.9});
}
TEST(CoverageBars, LowResolution)
{
    expectBars("lowres", 9102, true, {0.9, 0.9});
}
// Below the half line: 34 % measured (10 of 29 right readings). A reading the silhouette
// places at another height is read there and right, but warned of (reduction_not_nominal), as
// the nominal conditions' check asks: the more readings the silhouette places right, the more
// of the right ones warn. Another height the image says first, beyond the tolerance, is a
// finding even where the mixture's μ stays near half height's: that took one right reading
// here, and half the silent wrong ones on drawn seeds 104 and 105.
TEST(CoverageBars, ReductionNotDeclared)
{
    expectBars("reduction", 9103, false, {0, 0.3});
}
// Below the half line: a scale off and a higher height explain the silhouette alike (24 %).
TEST(CoverageBars, ScaleMeasuredOnTheFixture)
{
    expectBars("fixture_scale", 9104, false, {0, 0.2});
}
// A tilt the budget's tilt term covers is no finding, and neither is the barrel hidden on the
// view's far side: the reading is ok with U covering the unchecked height, and the advice says
// that the height and the declared scale went unchecked (calibrating the camera checks the scale).
TEST(CoverageBars, TiltedDistortingCamera)
{
    expectBars("tilt", 9105, false, {0, 0.5}, 30);
}
// The calibrated camera's oblique view shows no silhouette to check the height with; the scale
// is the calibration's: U covers the undeclared reduction, and the reading is ok.
TEST(CoverageBars, CalibratedTiltedCamera)
{
    expectBars("calibrated_tilt", 9106, false, {0, 0.5}, 30);
}
