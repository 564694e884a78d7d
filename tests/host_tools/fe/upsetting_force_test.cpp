// The FE base's upsetting force (host_tools/fe/upsetting_force.h) on the committed sweep.
#include <gtest/gtest.h>

#include "friction/reduction_table.h"
#include "host_tools/fe/upsetting_force.h"
#include "tests/support/table_inputs.h"

namespace icacam::host::fe {
namespace {

TEST(UpsettingForce, TheBasesForcePerKScaledByKAndD0Squared)
{
    UpsettingForce force;
    std::string e;
    ASSERT_TRUE(force.load(test::repositoryPaths(friction::reduction_table::kFeSources), &e)) << e;
    double at500 = 0, at1000 = 0, small = 0;
    ASSERT_TRUE(force.at(0.25, 0.2, 0.5, 500, 10, &at500));
    EXPECT_NEAR(at500, 72.867, 0.01) << "the sweep's own snapshot (K 500, n 0.25, μ 0.2, 50 %)";
    ASSERT_TRUE(force.at(0.25, 0.2, 0.5, 1000, 10, &at1000));
    EXPECT_NEAR(at1000, 2 * at500, 1e-9);
    ASSERT_TRUE(force.at(0.25, 0.2, 0.5, 500, 5, &small));
    EXPECT_NEAR(small, at500 / 4, 1e-9);
    // Between the snapshots and the grid's points: between its neighbours, rising with the
    // reduction (a larger face at a higher strain).
    double lo = 0, mid = 0, hi = 0;
    ASSERT_TRUE(force.at(0.3, 0.17, 0.45, 500, 10, &lo));
    ASSERT_TRUE(force.at(0.3, 0.17, 0.475, 500, 10, &mid));
    ASSERT_TRUE(force.at(0.3, 0.17, 0.5, 500, 10, &hi));
    EXPECT_LT(lo, mid);
    EXPECT_LT(mid, hi);
    double out = 0;
    EXPECT_FALSE(force.at(0.25, 0.5, 0.5, 500, 10, &out)) << "μ beyond the sweep";
    EXPECT_FALSE(force.at(0.25, 0.2, 0.7, 500, 10, &out)) << "beyond the last snapshot";
}

} // namespace
} // namespace icacam::host::fe
