// The outline a camera sees against R_max (friction/outline_ratio.h): the generated table is
// what its command makes from the committed barrel profiles, and it obeys the projection's
// bounds: the rim (R_o, on the end face's plane) and the widest section (R_max, h/2 below it)
// are both on the outline's side, so W/(W + h/2) ≤ outline/R_max ≤ 1, and a closer camera
// sees less.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "friction/outline_ratio.h"
#include "friction/outline_table.h"
#include "friction/radii_consistency.h"
#include "host_tools/outline_table.h"

using namespace icacam;
namespace t = friction::outline_table;

TEST(OutlineTable, IsWhatItsCommandMakesFromTheCommittedProfiles)
{
    const std::string prefix = "icacam fe outline-table --profiles ";
    const std::string provenance = t::kProvenance;
    ASSERT_EQ(provenance.rfind(prefix, 0), 0u);
    std::string summary;
    const std::string text =
        host::outlineTableText(provenance.substr(prefix.size()), std::string(ICACAM_SOURCE_DIR) + "/", &summary);
    std::ifstream f(std::string(ICACAM_SOURCE_DIR) + "/friction/outline_table.h", std::ios::binary);
    ASSERT_TRUE(f);
    std::stringstream committed;
    committed << f.rdbuf();
    EXPECT_EQ(committed.str(), text) << "stale friction/outline_table.h: rerun `" << provenance << "`";
}

TEST(OutlineRatio, ATelecentricViewSeesRMax)
{
    EXPECT_DOUBLE_EQ(friction::outlineRatioAt(0.25, 0.15, 0.5, 0), 1.0);
}

TEST(OutlineRatio, LiesBetweenTheWidestSectionsProjectionAndRMax)
{
    for (double r : {0.45, 0.5, 0.55})
        for (double n : {0.05, 0.2, 0.5})
            for (double mu : {0.06, 0.15, 0.29}) {
                double prev = 1.0;
                for (double w : {400.0, 150.0, 90.0, 60.0, 45.0, 40.0}) {
                    const double half = t::kH0Mm * (1 - r) / 2;
                    const double ratio = friction::outlineRatioAt(n, mu, r, t::kD0Mm / w);
                    EXPECT_GE(ratio, w / (w + half) - 1e-6) << "r " << r << " n " << n << " mu " << mu << " W " << w;
                    EXPECT_LT(ratio, prev) << "a closer camera sees less: W " << w;
                    prev = ratio;
                }
            }
}

TEST(OutlineRatio, ACloseCameraSeesTheOutlineThreeToSevenPerCentInside)
{
    // At 45–95 mm the outline lies 3–7 % inside R_max (docs/uncertainty.md).
    const double at45 = friction::outlineRatioAt(0.25, 0.15, 0.5, 10.0 / 45);
    const double at95 = friction::outlineRatioAt(0.25, 0.15, 0.5, 10.0 / 95);
    EXPECT_GT(at45, 0.92);
    EXPECT_LT(at45, 0.96);
    EXPECT_GT(at95, 0.95);
    EXPECT_LT(at95, 0.98);
    EXPECT_GT(friction::outlineRatioRelSigma(), 0);
    EXPECT_LT(friction::outlineRatioRelSigma(), 0.01);
}

// The outline's centre is drawn towards the optical axis by the share of the end face's
// distance from it that the side's depth takes off: none for a telecentric view, more the
// closer the camera. Over the grid the outline is (1 − share)·c with c = r(z0)/R_max the
// radius the side reaches at that depth: between the contact edge's share and R_max itself.
TEST(OutlineShift, GrowsAsTheCameraComesCloserAndMatchesTheOutlinesDepth)
{
    EXPECT_DOUBLE_EQ(friction::outlineShiftAt(0.25, 0.15, 0.5, 0), 0.0);
    const double at95 = friction::outlineShiftAt(0.25, 0.15, 0.5, 10.0 / 95);
    const double at45 = friction::outlineShiftAt(0.25, 0.15, 0.5, 10.0 / 45);
    EXPECT_GT(at95, 0.02);
    EXPECT_LT(at95, at45);
    EXPECT_LT(at45, 0.07);
    for (int ir = 0; ir < t::kRCount; ++ir)
        for (int in = 0; in < t::kNCount; ++in)
            for (int im = 0; im < t::kMuCount; ++im)
                for (int ix = 1; ix < t::kXCount; ++ix) {
                    const double x = t::kX[ix], r = t::kR[ir], n = t::kN[in], mu = t::kMu[im];
                    const double share = friction::outlineShiftAt(n, mu, r, x);
                    const double c = friction::outlineRatioAt(n, mu, r, x) / (1 - share);
                    EXPECT_GT(share, 0) << r << " " << n << " " << mu << " " << x;
                    EXPECT_GT(c, 0.95) << r << " " << n << " " << mu << " " << x;
                    EXPECT_LE(c, 1.0 + 1e-9) << r << " " << n << " " << mu << " " << x;
                }
}
