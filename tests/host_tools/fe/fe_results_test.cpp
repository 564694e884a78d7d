// The .frd/.dat readers and the radii on a small committed CalculiX result
// (tests/host_tools/fe/data/sample_h1.*: `icacam fe deck --elem 1 --mu 0.3` run by ccx 2.20).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "host_tools/fe/fe_case.h"
#include "host_tools/fe/fe_results.h"

using namespace icacam::host::fe;

namespace {
std::string slurp(const std::string &p)
{
    std::ifstream f(p);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}
const std::string kDir = std::string(ICACAM_SOURCE_DIR) + "/tests/host_tools/fe/data/";
} // namespace

TEST(FeResults, FrdSample)
{
    const FrdResults r = parseFrd(slurp(kDir + "sample_h1.frd"));
    FeCase c;
    c.elemMm = 1;
    c.mu = 0.3;
    const FeMesh m = meshFor(c);
    ASSERT_EQ(r.coords.size(), 78u); // 6 × 9 specimen + 2 × 12 platen nodes
    ASSERT_EQ(r.steps.size(), 4u);   // reductions 0.3 0.4 0.45 0.5
    EXPECT_NEAR(r.steps.back().time, 1.0, 1e-9);
    EXPECT_NEAR(r.coords.at(m.cornerNode()).first, 5.0, 1e-9);
    EXPECT_NEAR(r.coords.at(m.cornerNode()).second, 7.5, 1e-9);
    // The platen moved the prescribed half stroke.
    EXPECT_NEAR(r.steps.back().disp.at(m.platenFirstNode).second, -3.75, 1e-6);
    EXPECT_NEAR(r.steps[0].disp.at(m.platenFirstNode).second, -3.75 * 0.6, 1e-6);
    // Symmetry: mid-plane nodes stay at z = 0, axis nodes at r = 0.
    EXPECT_NEAR(r.steps.back().disp.at(m.node(3, 0)).second, 0.0, 1e-12);
    EXPECT_NEAR(r.steps.back().disp.at(m.node(0, 4)).first, 0.0, 1e-12);
    for (const auto &s : r.steps) {
        const Radii x = computeRadii(c, m, r.coords, s.disp, s.time * 0.5);
        EXPECT_GT(x.riMm, 5.0);
        EXPECT_GE(x.roMm, x.riMm);
        EXPECT_GE(x.roInterpMm, x.roMm);
        EXPECT_GT(x.rMaxMm, x.roMm);
        EXPECT_LT(x.rMaxMm, 8.5);
    }
}

TEST(FeResults, DatTotals)
{
    const auto f = parseDatTotals(slurp(kDir + "sample_h1.dat"));
    ASSERT_EQ(f.size(), 4u);
    EXPECT_NEAR(f[0].time, 0.6, 1e-9);
    EXPECT_NEAR(f[0].fy, -270.1972, 1e-3);
    for (size_t i = 1; i < f.size(); ++i) EXPECT_LT(f[i].fy, f[i - 1].fy) << "force grows with stroke";
    EXPECT_THROW(parseFrd("nothing"), std::runtime_error);
}

TEST(FeResults, RadiiOnAConstructedShape)
{
    // A 2 × 2 mesh moved by hand: the corner node and the next lateral node on the platen.
    FeCase c;
    c.d0Mm = 2;
    c.h0Mm = 4;
    c.elemMm = 1;
    const FeMesh m = meshFor(c);
    NodeXY coords, disp;
    for (int j = 0; j <= m.nz; ++j)
        for (int i = 0; i <= m.nr; ++i) {
            coords[m.node(i, j)] = {i * 0.5, j * 1.0};
            disp[m.node(i, j)] = {0, 0};
        }
    // Reduction 0.5: the platen is at z = 1. Corner at r = 1.2, next lateral node on the
    // platen at r = 1.5, the mid-plane node free at r = 1.6.
    disp[m.node(2, 2)] = {0.2, -1.0};
    disp[m.node(2, 1)] = {0.5, 0.0};
    disp[m.node(2, 0)] = {0.6, 0.0};
    const Radii r = computeRadii(c, m, coords, disp, 0.5);
    EXPECT_NEAR(r.riMm, 1.2, 1e-12);
    EXPECT_NEAR(r.roMm, 1.5, 1e-12);
    EXPECT_NEAR(r.uMm(), 0.3, 1e-12);
    EXPECT_NEAR(r.rMaxMm, 1.6, 1e-12);
    EXPECT_EQ(r.contactNodes, 1);
}
