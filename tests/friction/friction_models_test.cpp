// The models by name (friction/friction_models.h): every listed name gives its model, the
// same instance every time, and the default is the reduction-aware one.
#include <gtest/gtest.h>

#include <string>

#include "friction/friction_models.h"

using namespace icacam::friction;
using namespace icacam::friction;

TEST(FrictionModels, KnowsEveryListedNameAndReportsIt)
{
    std::string listed;
    for (std::string_view name : kModelNames) {
        const FrictionModel *m = frictionModel(name);
        ASSERT_NE(m, nullptr) << name;
        EXPECT_EQ(std::string_view(m->name()), name);
        EXPECT_EQ(frictionModel(std::string(name)), m) << "one static instance per name";
        listed += (listed.empty() ? "" : ", ") + std::string(name);
    }
    EXPECT_EQ(listed, kKnownModels) << "the help text lists the names the factory knows";
    EXPECT_EQ(frictionModel("nonsense"), nullptr);
    EXPECT_EQ(frictionModel(""), nullptr);
    EXPECT_EQ(frictionModel("paper "), nullptr);
}

TEST(FrictionModels, DefaultIsReductionAwareAndThePaperStaysSelectable)
{
    const FrictionModel *def = frictionModel(kDefaultModel);
    ASSERT_NE(def, nullptr);
    EXPECT_TRUE(def->correctsReduction());
    const FrictionModel *paper = frictionModel("paper");
    ASSERT_NE(paper, nullptr);
    EXPECT_FALSE(paper->correctsReduction());
    EXPECT_TRUE(frictionModel("fe")->correctsReduction());
    EXPECT_TRUE(frictionModel("fe_reduction")->correctsReduction());
}

TEST(FrictionModels, EveryModelReadsThePapersSpecimenAlike)
{
    // At the paper's own specimen (10 x 15 mm, 50 %) all four read μ of the same u within the
    // FE's difference from the paper (a few hundredths), and each says it is in range.
    ModelInputs in;
    in.uMm = 0.6;
    in.n = 0.25;
    for (std::string_view name : kModelNames) {
        const ModelEstimate e = frictionModel(name)->estimate(in);
        EXPECT_EQ(e.range, kModelInRange) << name;
        EXPECT_NEAR(e.mu, frictionModel("paper")->estimate(in).mu, 0.03) << name;
        EXPECT_GT(e.dMuDu, 0) << name;
        EXPECT_GT(e.modelSigma, 0) << name;
    }
}
