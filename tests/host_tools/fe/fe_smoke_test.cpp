// One coarse FE case end to end through ccx (skipped when ccx is not installed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "host_tools/fe/fe_runner.h"

using namespace icacam::host::fe;

TEST(FeSmoke, CoarseCaseEndToEnd)
{
    if (std::system("command -v ccx > /dev/null 2>&1") != 0) GTEST_SKIP() << "ccx (calculix-ccx) not installed";
    FeCase c;
    c.n = 0.25;
    c.mu = 0.3;
    c.elemMm = 0.5;
    c.trackStep = 0.025; // tracking frames between the snapshots
    RunOptions o;
    // One directory per process: several worktrees (engineers) may run the suite at once.
    o.workDir = (std::filesystem::temp_directory_path() / ("icacam-fe-smoke-" + std::to_string(getpid()))).string();
    o.timeoutS = 170;
    const RunResult r = runCase(c, o);
    ASSERT_EQ(r.status, "ok") << r.message << " in " << r.dir;
    ASSERT_EQ(r.radii.size(), 10u);
    const Radii &end = r.radii.back();
    EXPECT_NEAR(end.reduction, 0.5, 1e-9);
    EXPECT_GT(end.riMm, 5.0);
    EXPECT_GE(end.roMm, end.riMm);
    EXPECT_GT(end.rMaxMm, 7.0);
    EXPECT_LT(end.rMaxMm, 8.0);
    ASSERT_FALSE(r.force.empty());
    // Force at 50 %: the prototype measured 78–88 kN for K = 500 MPa.
    EXPECT_GT(r.force.back().fy, 60);
    EXPECT_LT(r.force.back().fy, 100);
    for (const Radii &x : r.radii) {
        EXPECT_GE(x.roTrackMm, x.roMm - 1e-9) << "the tracked edge is at or past the last node on the platen";
        EXPECT_LE(x.roTrackMm, x.rMaxMm);
    }
    // Post-processing again from the same results: no new solution (the .frd is untouched),
    // the same rows, the solve's wall time kept.
    const auto frd = std::filesystem::path(r.dir) / "job.frd";
    const auto stamp = std::filesystem::last_write_time(frd);
    RunOptions again = o;
    again.reuse = true;
    ASSERT_TRUE(hasReusableResults(c, again));
    FeCase same = c;
    const RunResult r2 = runCase(same, again);
    EXPECT_EQ(std::filesystem::last_write_time(frd), stamp);
    EXPECT_EQ(csvRows(c, r2), csvRows(c, r)) << "re-post-processing changed the rows";
    FeCase other = c;
    other.mu = 0.2;
    EXPECT_FALSE(hasReusableResults(other, again)) << "another case's deck never reuses these results";
    std::filesystem::remove_all(o.workDir);
}

// The rate-sensitive material end to end: the same coarse case at two press speeds a decade
// apart. σ = K ε^n (ε̇/ε̇₀)^m scales by 10^m wherever every rate scales by 10, so the force at
// each snapshot scales by it and the shape stays (docs/fe.md, "Rate dependence"); a wrong step
// time, amplitude or creep card breaks one of them.
TEST(FeSmoke, RateSensitiveCaseScalesWithPressSpeed)
{
    if (std::system("command -v ccx > /dev/null 2>&1") != 0) GTEST_SKIP() << "ccx (calculix-ccx) not installed";
    RunOptions o;
    o.workDir = (std::filesystem::temp_directory_path() / ("icacam-fe-rate-" + std::to_string(getpid()))).string();
    o.timeoutS = 170;
    RunResult r[2];
    const double speed[2] = {0.5, 5};
    for (int k = 0; k < 2; ++k) {
        FeCase c;
        c.n = 0.25;
        c.mu = 0.3;
        c.elemMm = 0.5;
        c.m = 0.05;
        c.pressSpeedMmS = speed[k];
        r[k] = runCase(c, o);
        ASSERT_EQ(r[k].status, "ok") << r[k].message << " in " << r[k].dir;
        ASSERT_EQ(r[k].radii.size(), 10u) << "every snapshot found at its step time";
        ASSERT_FALSE(r[k].force.empty());
        EXPECT_NEAR(r[k].force.back().time, 0.5, 1e-6) << "force totals at their reduction";
    }
    const Radii &slow = r[0].radii.back(), &fast = r[1].radii.back();
    // Not exactly: elasticity and the contact penalty do not scale with the flow stress (on
    // this coarse mesh R_i moves 0.6 %, R_max 0.03 %).
    EXPECT_NEAR(fast.rMaxMm / slow.rMaxMm, 1, 0.005);
    EXPECT_NEAR(fast.riMm / slow.riMm, 1, 0.01);
    EXPECT_NEAR(r[1].force.back().fy / r[0].force.back().fy, std::pow(10.0, 0.05), 0.02);
    std::filesystem::remove_all(o.workDir);
}
