// The reduction-aware model in the product (friction/reduction_corrected_model.h, docs/loop-method.md):
// its generator reads the FE sweep by column name, its slope is the loop tool's, it carries a
// forward reduction effect back, it is the base model at 50 %, and it flags reductions the FE
// snapshots do not cover.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "friction/paper_model.h"
#include "friction/reduction_corrected_model.h"
#include "friction/reduction_table.h"
#include "host_tools/fe/fe_table_sources.h"
#include "host_tools/fe/reduction_slope.h"
#include "host_tools/fe/reduction_table.h"
#include "host_tools/model_inverse.h"

using namespace icacam::host::fe;
using icacam::friction::ModelInputs;
using icacam::friction::PaperModel;
using icacam::friction::ReductionCorrectedModel;
using icacam::host::uForMu;

namespace {

// The FE sweep(s) the committed table names as its sources, as the repository names them and
// as files under the source tree.
const std::vector<std::string> kNames = splitSources(icacam::friction::reduction_table::kFeSources);
std::vector<std::string> files()
{
    std::vector<std::string> v;
    for (const std::string &n : kNames) v.push_back(std::string(ICACAM_SOURCE_DIR) + "/" + n);
    return v;
}
const std::vector<std::string> kSweep = files();

ModelInputs inputs(double u, double n, double hFinal, double d0 = 10, double h0 = 15)
{
    ModelInputs in;
    in.uMm = u;
    in.n = n;
    in.d0Mm = d0;
    in.h0Mm = h0;
    in.hFinalMm = hFinal;
    return in;
}

} // namespace

TEST(ReductionTable, GeneratorReadsColumnsByNameAndIgnoresAddedOnes)
{
    // A richer base sweep (columns moved and added, as the FE engineer's next runs will be)
    // gives the same table. The committed table's byte-for-byte check is tables_test.cpp.
    ASSERT_EQ(kNames.size(), 1u) << "one base";
    TableSources src;
    src.command = "icacam fe tables --base " + kNames[0];
    src.base = kNames[0];
    const std::string dir = ::testing::TempDir() + "icacam_sweep_extra_" + std::to_string(::getpid()) + "/";
    std::filesystem::create_directories(std::filesystem::path(dir + src.base).parent_path());
    {
        std::ifstream in(kSweep[0]);
        std::ofstream out(dir + src.base);
        std::string line;
        bool header = true;
        while (std::getline(in, line)) {
            out << (header ? "extra_a," : "1.5,") << line << (header ? ",extra_b\n" : ",x\n");
            header = false;
        }
    }
    std::string err;
    const std::string a = reductionTableText(src, std::string(ICACAM_SOURCE_DIR) + "/", &err);
    ASSERT_FALSE(a.empty()) << err;
    const std::string b = reductionTableText(src, dir, &err);
    std::filesystem::remove_all(dir);
    ASSERT_FALSE(b.empty()) << err;
    EXPECT_EQ(a, b);
}

TEST(ReductionTable, MissingSweepIsAClearError)
{
    std::string err;
    TableSources src;
    src.base = "/nonexistent/sweep.csv";
    EXPECT_TRUE(reductionTableText(src, "", &err).empty());
    EXPECT_NE(err.find("cannot read"), std::string::npos) << err;
}

TEST(ReductionCorrectedModel, SlopeIsTheLoopToolsSlope)
{
    ReductionSlope slope;
    std::string err;
    ASSERT_TRUE(slope.load(kSweep, &err)) << err;
    for (double n : {0.05, 0.2, 0.35, 0.5})
        for (double mu : {0.05, 0.1, 0.17, 0.3})
            EXPECT_NEAR(ReductionCorrectedModel::slopeAt(n, mu), slope.slope(n, mu), 1e-6) << n << " " << mu;
    EXPECT_NEAR(ReductionCorrectedModel::reductionMin(), slope.reductionMin(), 1e-6);
    EXPECT_NEAR(ReductionCorrectedModel::reductionMax(), slope.reductionMax(), 1e-6);
    // u widens with the reduction near 50 % (docs/fe.md: 3–5 mm per unit r).
    EXPECT_GT(ReductionCorrectedModel::slopeAt(0.25, 0.15), 1.0);
}

TEST(ReductionCorrectedModel, IsTheBaseModelWithoutAFinalHeightAndAt50Percent)
{
    PaperModel paper;
    ReductionCorrectedModel model(paper, "paper_reduction");
    for (double u : {0.2, 0.5, 0.8}) {
        const auto base = paper.estimate(inputs(u, 0.25, 0));
        const auto none = model.estimate(inputs(u, 0.25, 0));
        const auto half = model.estimate(inputs(u, 0.25, 7.5));
        EXPECT_EQ(none.mu, base.mu);
        EXPECT_EQ(none.range, base.range);
        EXPECT_NEAR(half.mu, base.mu, 1e-12);
        EXPECT_EQ(half.range, base.range);
    }
    EXPECT_STREQ(model.name(), "paper_reduction");
    EXPECT_TRUE(model.correctsReduction());
    EXPECT_FALSE(paper.correctsReduction());
}

TEST(ReductionCorrectedModel, CarriesAForwardReductionEffectBack)
{
    // A specimen with friction μ pressed to r shows u50 + du/dr(n, μ)(r − 0.5): the model must
    // return μ, where the paper's reads more (r > 0.5) or less (r < 0.5) friction.
    PaperModel paper;
    ReductionCorrectedModel model(paper, "paper_reduction");
    // Reductions across what the table covers (it widens when the FE runs to 60 % land).
    const double lo = ReductionCorrectedModel::reductionMin(), hi = ReductionCorrectedModel::reductionMax();
    for (double n : {0.1, 0.25, 0.4})
        for (double mu : {0.1, 0.15, 0.2})
            for (double r : {lo + 0.05 * (hi - lo), 0.5 - 0.3 * (0.5 - lo), 0.5 + 0.3 * (hi - 0.5), hi - 0.001}) {
                const double u50 = uForMu(paper, mu, n);
                const double u = u50 + ReductionCorrectedModel::slopeAt(n, mu) * (r - 0.5);
                const auto e = model.estimate(inputs(u, n, 15 * (1 - r)));
                EXPECT_NEAR(e.mu, mu, 2e-4) << "n " << n << " mu " << mu << " r " << r;
                const double naive = paper.estimate(inputs(u, n, 0)).mu;
                EXPECT_EQ(naive > mu, r > 0.5);
                EXPECT_EQ(e.range & icacam::friction::kModelReductionOutside, 0u);
                // The carry's own uncertainty adds to the model's.
                EXPECT_GT(e.modelSigma, paper.estimate(inputs(u50, n, 0)).modelSigma);
            }
}

TEST(ReductionCorrectedModel, ScalesWithTheSpecimenByGeometricSimilarity)
{
    PaperModel paper;
    ReductionCorrectedModel model(paper, "paper_reduction");
    const auto a = model.estimate(inputs(0.6, 0.2, 7.2, 10, 15));
    const auto b = model.estimate(inputs(1.2, 0.2, 14.4, 20, 30));
    EXPECT_NEAR(a.mu, b.mu, 1e-9);
}

TEST(ReductionCorrectedModel, FlagsReductionsTheFeSnapshotsDoNotCover)
{
    PaperModel paper;
    ReductionCorrectedModel model(paper, "paper_reduction");
    const double lo = ReductionCorrectedModel::reductionMin(), hi = ReductionCorrectedModel::reductionMax();
    ASSERT_LT(lo, 0.5);
    ASSERT_GT(hi, 0.5);
    auto flagged = [&](double r) {
        return (model.estimate(inputs(0.5, 0.25, 15 * (1 - r))).range & icacam::friction::kModelReductionOutside) != 0;
    };
    EXPECT_FALSE(flagged(0.5));
    EXPECT_FALSE(flagged(lo + 0.002));
    EXPECT_FALSE(flagged(hi - 0.002));
    EXPECT_TRUE(flagged(lo - 0.01));
    EXPECT_TRUE(flagged(hi + 0.01));
    EXPECT_TRUE(flagged(0.7));
    // Not an upset specimen at all: flagged, never a silent value.
    EXPECT_TRUE(model.estimate(inputs(0.5, 0.25, 15)).range & icacam::friction::kModelReductionOutside);
    EXPECT_TRUE(model.estimate(inputs(0.5, 0.25, 20)).range & icacam::friction::kModelReductionOutside);
}
