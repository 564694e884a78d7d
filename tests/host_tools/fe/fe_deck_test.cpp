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

TEST(FeDeck, RateSensitiveMaterialRunsAsNortonTimeHardeningInAViscoStep)
{
    FeCase c;
    c.reductionMax = 0.6;
    const std::string plain = makeDeck(c);
    // Without a press speed ε̇₀ and CETOL are inert: the rate-independent deck.
    FeCase inert = c;
    inert.rate0 = 10;
    inert.creepTol = 1e-3;
    EXPECT_EQ(makeDeck(inert), plain);
    EXPECT_EQ(inert.label(), c.label());
    EXPECT_DOUBLE_EQ(stepTime(c), 1.0);
    EXPECT_EQ(plain.find("*VISCO"), std::string::npos);
    EXPECT_EQ(plain.find("*CREEP"), std::string::npos);
    EXPECT_EQ(plain.find("*AMPLITUDE"), std::string::npos);
    FeCase m = c;
    m.m = 0.05;
    EXPECT_THROW(makeDeck(m), std::invalid_argument) << "a rate sensitivity needs a press speed";

    FeCase r = c;
    r.n = 0.25;
    r.kMpa = 500;
    r.m = 0.05;
    r.rate0 = 2;
    r.pressSpeedMmS = 0.5;
    const std::string deck = makeDeck(r);
    // The whole stroke, 0.6 · 15 = 9 mm, at 0.5 mm/s: 18 s.
    EXPECT_DOUBLE_EQ(stepTime(r), 18.0);
    EXPECT_EQ(deck.find("*PLASTIC"), std::string::npos) << "the creep law replaces the table";
    // Norton: N = 1/(m + n), M = −n/(m + n), A = (K ε̇₀^(−m))^(−N).
    const auto p = deck.find("*CREEP,LAW=NORTON\n");
    ASSERT_NE(p, std::string::npos);
    std::istringstream law(deck.substr(p + 18));
    double a = 0, n = 0, mm = 0;
    char comma = 0;
    law >> a >> comma >> n >> comma >> mm;
    EXPECT_NEAR(n, 1 / 0.3, 1e-8);
    EXPECT_NEAR(mm, -0.25 / 0.3, 1e-8);
    EXPECT_NEAR(a / std::pow(500 * std::pow(2.0, -0.05), -1 / 0.3), 1, 1e-8);
    // A ramp over the step time: a constant press speed.
    EXPECT_NE(deck.find("*AMPLITUDE,NAME=PRESS\n0, 0\n18, 1\n*STEP"), std::string::npos);
    // Increments in step time (a first one of 1e-4, then 1e-7 and 0.01 of 18 s); the stroke
    // under the amplitude.
    EXPECT_NE(
        deck.find("*VISCO,CETOL=0.01\n0.0018, 18, 1.8e-06, 0.18\n*BOUNDARY,AMPLITUDE=PRESS\nPLATENN, 2, 2, -4.5\n"),
        std::string::npos);
    // Snapshots in step time: 0.45 of 0.6 at 13.5 s.
    EXPECT_NE(deck.find("\n13.5\n"), std::string::npos);
    EXPECT_EQ(deck.find("\n0.75\n"), std::string::npos);
    // The rest of the deck (mesh, contact, output) is the rate-independent deck's.
    const auto tail = [](const std::string &d) { return d.substr(d.find("*NODE FILE")); };
    EXPECT_EQ(tail(deck), tail(plain));
    const auto head = [](const std::string &d) {
        const auto at = d.find("\n*NODE,");
        return d.substr(at, d.find("*MATERIAL,NAME=WORK") - at);
    };
    EXPECT_EQ(head(deck), head(plain));
    // Each speed and m is its own case (the sweep's resume key); m = 0 with a speed is the
    // time-hardening form without a rate term, not the rate-independent case.
    EXPECT_EQ(r.label(), c.label() + "_v0.5_m0.05_e02");
    FeCase fast = r;
    fast.pressSpeedMmS = 5;
    EXPECT_NE(fast.label(), r.label());
    EXPECT_DOUBLE_EQ(stepTime(fast), 1.8);
    FeCase m0 = r;
    m0.m = 0;
    EXPECT_NE(makeDeck(m0).find("*VISCO"), std::string::npos);
    EXPECT_NE(m0.label(), c.label());
    // ccx 2.20 integrates Norton's law wrongly for A below 1e-18: such a case is refused, not run.
    FeCase low = r;
    low.n = 0.125;
    low.m = 0;
    low.rate0 = 1;
    EXPECT_THROW(makeDeck(low), std::invalid_argument) << "A = 500^-8 = 2.6e-22";
    low.m = 0.05;
    EXPECT_NO_THROW(makeDeck(low)) << "A = 500^-5.7 = 3.7e-16";
}
