// Deck generation: mesh numbering, material table, contact, boundary conditions, snapshots.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "host_tools/fe/fe_case.h"
#include "host_tools/fe/fe_runner.h"

using namespace icacam::host::fe;

namespace {
int countLines(const std::string &deck, const std::string &from, const std::string &to)
{
    const auto a = deck.find(from);
    const auto b = deck.find(to, a + from.size());
    if (a == std::string::npos || b == std::string::npos) return -1;
    std::istringstream s(deck.substr(a + from.size(), b - a - from.size()));
    std::string line;
    int n = 0;
    while (std::getline(s, line))
        if (!line.empty()) ++n;
    return n;
}
} // namespace

TEST(FeDeck, MeshNumberingAndCounts)
{
    FeCase c;
    c.elemMm = 0.5;
    const FeMesh m = meshFor(c);
    EXPECT_EQ(m.nr, 10);
    EXPECT_EQ(m.nz, 15);
    EXPECT_EQ(m.cornerNode(), 11 * 16);
    const std::string deck = makeDeck(c);
    // 11 × 16 specimen nodes + 2 rows of 23 platen nodes.
    EXPECT_EQ(countLines(deck, "*NODE,NSET=NALL\n", "*ELEMENT"), 11 * 16 + 2 * 23);
    EXPECT_EQ(countLines(deck, "*ELEMENT,TYPE=CAX4R,ELSET=SPEC\n", "*ELEMENT"), 150);
    EXPECT_EQ(countLines(deck, "*ELEMENT,TYPE=CAX4R,ELSET=PLATEN\n", "*NSET"), 22);
    EXPECT_NE(deck.find("*STEP,NLGEOM"), std::string::npos);
    EXPECT_NE(deck.find("TYPE=NODE TO SURFACE"), std::string::npos);
    EXPECT_EQ(deck.find("CAX4,"), std::string::npos) << "fully integrated CAX4 locks";
}

TEST(FeDeck, MaterialFrictionAndStroke)
{
    FeCase c;
    c.kMpa = 750;
    c.n = 0.125;
    c.mu = 0.08;
    c.reductionMax = 0.6;
    const std::string deck = makeDeck(c);
    // First plastic point: σ = K · 0.002^n at ε_p = 0.
    const auto p = deck.find("*PLASTIC\n");
    ASSERT_NE(p, std::string::npos);
    const double sigma0 = std::stod(deck.substr(p + 9));
    EXPECT_NEAR(sigma0, 750 * std::pow(0.002, 0.125), 1e-6);
    EXPECT_NE(deck.find("*FRICTION\n0.08, 10000"), std::string::npos);
    // Quarter model: the platen moves half the stroke, 0.6 · 15 / 2 = 4.5 mm.
    EXPECT_NE(deck.find("PLATENN, 2, 2, -4.5\n"), std::string::npos);
    // Snapshots as step-time fractions: 0.45 of 0.6 → 0.75.
    EXPECT_NE(deck.find("\n0.75\n"), std::string::npos);
}

TEST(FeDeck, SnapshotsAndLabels)
{
    FeCase c;
    c.reductionMax = 0.5;
    c.reductions = {0.48, 0.7};
    const auto s = snapshotReductions(c);
    ASSERT_EQ(s.size(), 11u); // 0.05 … 0.5 and 0.48; 0.7 is beyond the run
    EXPECT_DOUBLE_EQ(s.back(), 0.5);
    EXPECT_NEAR(s[9], 0.48, 1e-12);
    FeCase d = c;
    d.mu = 0.25;
    EXPECT_NE(c.label(), d.label());
    EXPECT_THROW(makeDeck(FeCase{.kMpa = -1}), std::invalid_argument);
}

TEST(FeDeck, GradedMeshResolvesTheCorner)
{
    FeCase c;
    c.elemMm = 0.2;
    c.cornerMm = 0.05;
    const FeMesh m = meshFor(c);
    ASSERT_EQ(m.r.size(), size_t(m.nr + 1));
    EXPECT_DOUBLE_EQ(m.r.front(), 0.0);
    EXPECT_DOUBLE_EQ(m.r.back(), 5.0);
    EXPECT_DOUBLE_EQ(m.z.back(), 7.5);
    EXPECT_NEAR(m.r[m.nr] - m.r[m.nr - 1], 0.05, 1e-9);
    EXPECT_NEAR(m.z[m.nz] - m.z[m.nz - 1], 0.05, 1e-9);
    for (int i = 0; i < m.nr; ++i) {
        const double h = m.r[i + 1] - m.r[i];
        EXPECT_GT(h, 0.049);
        EXPECT_LT(h, 0.25);
    }
    const std::string deck = makeDeck(c);
    EXPECT_NE(deck.find("\n" + std::to_string(m.cornerNode()) + ", 5, 7.5\n"), std::string::npos);
}

TEST(FeDeck, LabelsOfTheFirstSweepsStayValid)
{
    // The sweep resumes by label: rows committed before new settings existed must keep theirs.
    FeCase c;
    c.mu = 0.05;
    EXPECT_EQ(c.label(), "K500_n0.25_mu0.05_E210_D10_H15_r0.5_h0.2_c0_cs100000");
    c.element = "CAX8R";
    c.incMax = 0.02;
    EXPECT_EQ(c.label(), "K500_n0.25_mu0.05_E210_D10_H15_r0.5_h0.2_c0_cs100000_CAX8R_im0.02");
}

TEST(FeDeck, QuadraticElementsHaveMidSideNodes)
{
    FeCase c;
    c.elemMm = 0.5;
    c.element = "CAX8R";
    const FeMesh m = meshFor(c);
    EXPECT_EQ(m.q, 2);
    EXPECT_EQ(m.cols(), 21);
    EXPECT_EQ(m.rows(), 31);
    EXPECT_DOUBLE_EQ(m.rn[1], 0.25);
    EXPECT_DOUBLE_EQ(m.zn.back(), 7.5);
    const std::string deck = makeDeck(c);
    // Node grid 21 × 31 without the 10 × 15 element centres, plus 2 rows of 23 platen nodes.
    EXPECT_EQ(countLines(deck, "*NODE,NSET=NALL\n", "*ELEMENT"), 21 * 31 - 10 * 15 + 2 * 23);
    EXPECT_EQ(countLines(deck, "*ELEMENT,TYPE=CAX8R,ELSET=SPEC\n", "*ELEMENT"), 150);
    // First element: corners 1, 3, 45, 43 of the node grid, then bottom, right, top, left mid-sides.
    EXPECT_NE(deck.find("*ELEMENT,TYPE=CAX8R,ELSET=SPEC\n1, 1, 3, 45, 43, 2, 24, 44, 22\n"), std::string::npos);
    // The corner node is the last specimen node; the element centre (1, 1) is not written.
    EXPECT_NE(deck.find("\n" + std::to_string(m.cornerNode()) + ", 5, 7.5\n"), std::string::npos);
    const std::string nodes = deck.substr(0, deck.find("*ELEMENT"));
    EXPECT_EQ(nodes.find("\n" + std::to_string(m.node(1, 1)) + ", "), std::string::npos);
    EXPECT_NE(nodes.find("\n" + std::to_string(m.node(1, 0)) + ", 0.25, 0\n"), std::string::npos);
    EXPECT_EQ(m.lateralNode(m.rows() - 1), m.cornerNode());
    FeCase bad = c;
    bad.element = "CAX4";
    EXPECT_THROW(makeDeck(bad), std::invalid_argument);
}

TEST(FeDeck, FoldZoneKeepsTheSideFine)
{
    FeCase c;
    c.elemMm = 0.5;
    c.cornerMm = 0.1;
    c.foldZoneMm = 1.5;
    const FeMesh m = meshFor(c);
    // The top 1.5 mm of the side in 0.1 mm elements, then graded; the radius is graded as before.
    for (int j = m.nz; j > m.nz - 15; --j) EXPECT_NEAR(m.z[j] - m.z[j - 1], 0.1, 1e-9) << j;
    EXPECT_GT(m.z[m.nz - 15] - m.z[m.nz - 16], 0.1 + 1e-6);
    EXPECT_NEAR(m.r[m.nr - 1] - m.r[m.nr - 2], 0.12, 1e-9);
    EXPECT_NE(c.label().find("_fz1.5"), std::string::npos);
}

TEST(FeDeck, SurfaceToSurfaceContactIsItsOwnCase)
{
    FeCase c;
    c.element = "CAX8R";
    const std::string nodeDeck = makeDeck(c), nodeLabel = c.label();
    c.contact = "surface";
    const std::string deck = makeDeck(c);
    EXPECT_NE(deck.find("TYPE=SURFACE TO SURFACE"), std::string::npos);
    EXPECT_EQ(deck.find("NODE TO SURFACE"), std::string::npos);
    EXPECT_EQ(c.label(), nodeLabel + "_s2s"); // its own resume key and work directory
    c.contact = "mortar";
    EXPECT_THROW(makeDeck(c), std::invalid_argument);
    EXPECT_NE(nodeDeck.find("TYPE=NODE TO SURFACE"), std::string::npos);
}
