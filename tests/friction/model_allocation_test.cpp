// The models on the device: choosing one by name and every estimate, radii lookup and
// consistency check allocate nothing (operator new is counted).
#include <gtest/gtest.h>

#include "friction/fe_model.h"
#include "friction/friction_models.h"
#include "friction/radii_consistency.h"
#include "tests/support/allocation_counter.h"

using namespace icacam::friction;
using namespace icacam::friction;

TEST(ModelAllocation, NoneToChooseOrEvaluateAnyModel)
{
    // The counter must see an allocation when there is one, or the zero below proves nothing.
    const long before = icacam::test::allocationCount();
    ::operator delete(::operator new(8)); // a direct call: not elided as a new-expression may be
    ASSERT_EQ(icacam::test::allocationCount(), before + 1);

    double sum = 0;
    const long start = icacam::test::allocationCount();
    for (std::string_view name : kModelNames) {
        const FrictionModel *m = frictionModel(name);
        ASSERT_NE(m, nullptr);
        // Declared and undeclared final heights, other slenderness and size, a given K, and
        // inputs outside every range: every path through the carries.
        for (double h0 : {15.0, 10.0, 20.0, 30.0})
            for (double hFinal : {0.0, 0.48, 0.5, 0.53, 1.1})
                for (double k : {0.0, 500.0, 900.0, 5000.0})
                    for (double u : {-0.1, 0.0, 0.3, 0.8, 1.4, 4.0}) {
                        ModelInputs in;
                        in.uMm = u;
                        in.n = 0.2;
                        in.kMpa = k;
                        in.d0Mm = h0 == 30 ? 20 : 10;
                        in.h0Mm = h0;
                        in.hFinalMm = hFinal * h0;
                        const ModelEstimate e = m->estimate(in);
                        sum += e.mu + e.dMuDu + e.modelSigma;
                    }
    }
    const FeModel fe;
    for (double r : {0.0, 0.35, 0.5, 0.58}) {
        sum += fe.uAt(0.3, 0.12, r, 700) + fe.radii(0.3, 0.12, 12, r, 700).rMaxMm;
        double mm = 0;
        if (feRadiusAt(FeRadius::Inner, 0.3, 0.12, r, &mm)) sum += mm;
        const RadiiCheck c = checkRadii(7.3, 0.3, 0.12, 10, r > 0 ? r : 0.5, 14);
        sum += c.z + c.reductionEst;
    }
    EXPECT_EQ(icacam::test::allocationCount() - start, 0);
    EXPECT_TRUE(sum == sum); // used, so the loop is not optimised away
}
