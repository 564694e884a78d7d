// The base choice of the FE models (host_tools/fe/fe_rows.h): which runs are averaged into
// the model and which stay checks.
#include <gtest/gtest.h>

#include "host_tools/fe/fe_rows.h"

using namespace icacam::host::fe;

namespace {
FeRow row(double k, double n, double mu, double u, double contactPerK = 200, double stickPerK = 20)
{
    FeRow r;
    r.status = "ok";
    r.element = "CAX8R";
    r.elem = 0.5;
    r.cornerMm = 0.1;
    r.kMpa = k;
    r.n = n;
    r.mu = mu;
    r.eMpa = 210000;
    r.d0 = 10;
    r.h0 = 15;
    r.reduction = 0.5;
    r.contactSlope = contactPerK * k;
    r.stickSlope = stickPerK * k;
    r.ri = 5;
    r.rMax = 7;
    r.force = 0.14 * k;
    r.uTrack = u;
    return r;
}
void grid(std::vector<FeRow> &rows, double k, double u, double contactPerK = 200, double stickPerK = 20)
{
    for (double n : {0.05, 0.5})
        for (double mu : {0.1, 0.3}) rows.push_back(row(k, n, mu, u, contactPerK, stickPerK));
}
} // namespace

TEST(FeBaseChoice, AveragesTheKThatCoverTheGridWithTheSamePenaltyPerK)
{
    std::vector<FeRow> rows;
    grid(rows, 500, 1.0);
    grid(rows, 500, 1.0);                     // the most common K: 500
    grid(rows, 1250, 0.9);                    // scaled slopes, full grid: joins
    grid(rows, 250, 0.5, 100, 10);            // other (softer) slopes per K: a check, not the base
    rows.push_back(row(750, 0.05, 0.1, 0.1)); // partial grid: a check
    const BaseChoice b = chooseBase(rows, 0.5);
    ASSERT_TRUE(b.found);
    EXPECT_EQ(b.kMpa, 500);
    EXPECT_EQ(b.kAveraged, (std::vector<double>{500, 1250}));
    EXPECT_EQ(b.kCovered, (std::vector<double>{500, 1250})); // not K 250 (other slopes per K) nor 750 (partial)
    const PointGrid pts = basePoints(rows, 0.5);
    ASSERT_EQ(pts.size(), 4u);
    for (const auto &[key, p] : pts) {
        EXPECT_EQ(p.count, 3);
        EXPECT_NEAR(p.u, (1.0 + 1.0 + 0.9) / 3, 1e-12);
        EXPECT_NEAR(p.force, 0.14, 1e-12); // force per K
        EXPECT_EQ(p.kMin, 500);
        EXPECT_EQ(p.kMax, 1250);
    }
}

TEST(FeBaseChoice, OtherMeshesAndSpecimensStayOut)
{
    std::vector<FeRow> rows;
    grid(rows, 500, 1.0);
    grid(rows, 500, 1.0);
    auto finer = row(500, 0.05, 0.1, 2.0);
    finer.cornerMm = 0.05; // the mesh study
    rows.push_back(finer);
    auto s2s = row(500, 0.05, 0.1, 2.5);
    s2s.contact = "surface-to-surface penalty"; // an independent contact discretisation
    rows.push_back(s2s);
    EXPECT_EQ(meshKey(s2s), "CAX8R h0.5 c0.1 s2s");
    auto slender = row(500, 0.05, 0.1, 3.0);
    slender.h0 = 20; // another slenderness
    rows.push_back(slender);
    auto stopped = row(500, 0.05, 0.1, 4.0);
    stopped.status = "error";
    rows.push_back(stopped);
    const PointGrid pts = basePoints(rows, 0.5);
    ASSERT_EQ(pts.size(), 4u);
    EXPECT_NEAR(pts.at({0.05, 0.1}).u, 1.0, 1e-12);
    EXPECT_TRUE(basePoints(rows, 0.45).empty());
}

TEST(FeBaseChoice, TheFinestCompleteMeshIsTheBase)
{
    std::vector<FeRow> rows;
    grid(rows, 500, 1.0);
    grid(rows, 1250, 1.0); // the coarse mesh has the most rows …
    auto finer = [&](double u) {
        for (double n : {0.05, 0.5})
            for (double mu : {0.1, 0.3}) {
                rows.push_back(row(500, n, mu, u));
                rows.back().cornerMm = 0.05;
            }
    };
    finer(1.1); // … but the finer one covers the whole grid too: it is the base
    BaseChoice b = chooseBase(rows, 0.5);
    EXPECT_EQ(b.mesh, "CAX8R h0.5 c0.05");
    EXPECT_EQ(b.kAveraged, (std::vector<double>{500}));
    // The coarse mesh's K 1250 covered the grid with the same penalty per K: it checked
    // K-independence, so the model answers for K 500-1250 (fe fit's K range).
    EXPECT_EQ(b.kCovered, (std::vector<double>{500, 1250}));
    EXPECT_NEAR(basePoints(rows, 0.5).at({0.5, 0.3}).u, 1.1, 1e-12);

    // A finer mesh at part of the grid (the mesh study) stays a check.
    auto finest = row(500, 0.05, 0.1, 2.0);
    finest.cornerMm = 0.025;
    rows.push_back(finest);
    EXPECT_EQ(chooseBase(rows, 0.5).mesh, "CAX8R h0.5 c0.05");

    // The mesh is chosen over the cases, not per reduction: a finer run that stopped before
    // 50 % does not hand that reduction to another mesh.
    for (auto &r : rows)
        if (r.cornerMm == 0.05 && r.n == 0.5 && r.mu == 0.3) {
            r.status = "failed";
            r.reduction = 0.45;
        }
    EXPECT_EQ(chooseBase(rows, 0.5).mesh, "CAX8R h0.5 c0.05");
    EXPECT_EQ(basePoints(rows, 0.5).count({0.5, 0.3}), 0u);
}

TEST(FeBaseChoice, TheStiffestRegularisationOnTheFinestMeshIsTheBase)
{
    // The regularised Coulomb law and the penalty contact approach the exact laws as their
    // slopes grow: of two complete sets on the finest mesh the stiffer stick slope is the base,
    // whatever the row counts; the other stays a check and is never averaged in.
    std::vector<FeRow> rows;
    auto finer = [&](double u, double stickPerK) {
        for (double n : {0.05, 0.5})
            for (double mu : {0.1, 0.3}) {
                rows.push_back(row(500, n, mu, u, 200, stickPerK));
                rows.back().cornerMm = 0.05;
            }
    };
    finer(1.0, 20);
    finer(1.0, 20);        // more rows with the base's first stick slope …
    finer(1.2, 200);       // … but a stick slope ten times stiffer covers the grid too
    grid(rows, 500, 0.8);  // the factorial on a coarser mesh (slopes 200 K / 20 K) …
    grid(rows, 1250, 0.8); // … checked K 500-1250
    const BaseChoice b = chooseBase(rows, 0.5);
    ASSERT_TRUE(b.found);
    EXPECT_EQ(b.mesh, "CAX8R h0.5 c0.05");
    EXPECT_DOUBLE_EQ(b.stickPerK, 200);
    EXPECT_DOUBLE_EQ(b.contactPerK, 200);
    EXPECT_EQ(b.kAveraged, (std::vector<double>{500}));
    // The K range still comes from the family that covered the grid at the base's K and others.
    EXPECT_EQ(b.kCovered, (std::vector<double>{500, 1250}));
    const PointGrid pts = basePoints(rows, 0.5, b);
    ASSERT_EQ(pts.size(), 4u);
    for (const auto &[key, p] : pts) {
        EXPECT_EQ(p.count, 1) << "only the stiff set, not averaged with the soft one";
        EXPECT_NEAR(p.u, 1.2, 1e-12);
    }
    // A stiffer set at part of the grid (a penalty study) stays a check.
    rows.push_back(row(500, 0.05, 0.1, 3.0, 200, 2000));
    rows.back().cornerMm = 0.05;
    EXPECT_DOUBLE_EQ(chooseBase(rows, 0.5).stickPerK, 200);
}

TEST(FeKCarry, HowUMovesWithKFromTheFamilyWithTheMostK)
{
    // The base: one K on the fine mesh. The factorial on a coarser mesh covers the grid at
    // K 250, 500 and 1250; its values are off (coarse), its differences in K are the carry.
    std::vector<FeRow> rows;
    for (double n : {0.05, 0.5})
        for (double mu : {0.1, 0.3}) {
            rows.push_back(row(500, n, mu, 1.2, 200, 200));
            rows.back().cornerMm = 0.05;
        }
    grid(rows, 500, 0.8);
    grid(rows, 250, 0.7);
    grid(rows, 1250, 0.95);
    for (auto &r : rows)
        if (r.cornerMm == 0.1) r.ri = 5 - (r.uTrack - 0.8); // R_i moves against u
    grid(rows, 750, 0.5, 100, 10);                          // another regularisation at one more K: no base K, no carry
    rows.push_back(row(2000, 0.05, 0.1, 2.0));              // a partial grid: not a K of the carry
    const BaseChoice b = chooseBase(rows, 0.5);
    ASSERT_EQ(b.mesh, "CAX8R h0.5 c0.05");
    const KCarry c = kCarry(rows, 0.5, b);
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.mesh, "CAX8R h0.5 c0.1");
    EXPECT_EQ(c.k, (std::vector<double>{250, 500, 1250}));
    ASSERT_EQ(c.delta.size(), 3u);
    for (const auto &[key, d] : c.delta.at(250)) {
        EXPECT_NEAR(d.u, -0.1, 1e-12);
        EXPECT_NEAR(d.ri, 0.1, 1e-12);
        EXPECT_NEAR(d.ro, 0.0, 1e-12);
    }
    for (const auto &[key, d] : c.delta.at(500)) EXPECT_NEAR(d.u, 0.0, 1e-12);
    for (const auto &[key, d] : c.delta.at(1250)) EXPECT_NEAR(d.u, 0.15, 1e-12);

    // Without runs at several K that cover the grid there is no carry.
    std::vector<FeRow> one;
    grid(one, 500, 1.0);
    grid(one, 250, 0.5, 100, 10);
    EXPECT_FALSE(kCarry(one, 0.5, chooseBase(one, 0.5)).found);
}
