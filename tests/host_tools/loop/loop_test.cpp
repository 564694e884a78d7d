// icacam loop on record sets that carry an effect nobody declared (docs/loop.md): the record
// sets are radii-only, generated from the paper's model plus a hidden effect plus 0.003 of
// reference scatter. The tool must rank the true cause first and cut the held-out error, and
// add nothing on a null set.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "friction/paper_model.h"
#include "friction/reduction_table.h"
#include "host_tools/fe/reduction_slope.h"
#include "host_tools/loop/loop_analysis.h"
#include "host_tools/loop/loop_command.h"
#include "host_tools/model_inverse.h"
#include "tests/support/table_inputs.h"

namespace fs = std::filesystem;
using namespace icacam::host::loop;
using icacam::host::uForMu;
using icacam::host::fe::ReductionSlope;
using icacam::host::fe::uAtModelReduction;

namespace {

enum class Effect { Process, Optical, Null };

// The FE sweep(s) the product's table was generated from (its kFeSources).
const std::vector<std::string> kSweep = icacam::test::repositoryPaths(icacam::friction::reduction_table::kFeSources);

// Writes a manifest of `count` radii-only records and returns its path.
std::string makeSet(const std::string &name, Effect effect, int count, uint32_t seed)
{
    // One directory per process: other worktrees run the same suite at the same time.
    const fs::path dir = fs::temp_directory_path() / ("icacam_loop_test_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "manifest.csv").string();
    std::ofstream f(path);
    f << "id,n,k_mpa,d0_mm,h0_mm,r_inner_mm,r_outer_mm,mu_ref,h_final_mm,operator,lens,press_speed_mm_s,"
         "ambient_c,sequence\n";
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> un(0.1, 0.45), umu(0.08, 0.22), ured(0.46, 0.54), uspeed(1, 5),
        utemp(18, 28), uro(6.95, 7.55);
    std::normal_distribution<double> noise(0, 0.003);
    icacam::friction::PaperModel paper;
    ReductionSlope slope;
    std::string err;
    if (!slope.load(kSweep, &err)) ADD_FAILURE() << err;
    const char *ops[] = {"A", "B", "C"};
    const char *lenses[] = {"L16", "L25"};
    for (int i = 0; i < count; ++i) {
        const double n = un(rng), mu = umu(rng);
        double red = ured(rng);
        const double speed = uspeed(rng), temp = utemp(rng);
        const std::string op = ops[rng() % 3], lens = lenses[rng() % 2];
        double u = uForMu(paper, mu, n); // u at 50 %
        double scale = 1.0;
        if (effect == Effect::Process)
            u += slope.slope(n, mu) * (red - 0.5);
        else
            red = 0.5 + 0.002 * (ured(rng) - 0.5); // held at 50 % within the press's tolerance
        if (effect == Effect::Optical && lens == "L25")
            scale = 1.08; // the lab kept the other lens's mm_per_px: 8 % off
        const double ro = uro(rng);
        const double ri = ro - u;
        char line[400];
        std::snprintf(line, sizeof line, "%s-%03d,%.4f,700,10,15,%.5f,%.5f,%.4f,%.3f,%s,%s,%.2f,%.1f,%d\n",
                      name.c_str(), i + 1, n, ri * scale, ro * scale, mu + noise(rng), 15 * (1 - red), op.c_str(),
                      lens.c_str(), speed, temp, i + 1);
        f << line;
    }
    return path;
}

LoopSummary run(const std::string &name, Effect effect, uint32_t seed)
{
    const std::string manifest = makeSet(name, effect, 60, seed);
    const std::string report = (fs::path(manifest).parent_path() / "report").string();
    RankingOptions opt;
    opt.folds = 5;
    opt.seed = 7;
    LoopSummary s = runLoop(manifest, report, "paper", opt, kSweep);
    EXPECT_TRUE(fs::exists(fs::path(report) / "ranking.csv"));
    EXPECT_TRUE(fs::exists(fs::path(report) / "report.md"));
    EXPECT_TRUE(fs::exists(fs::path(report) / "before_after.png"));
    fs::remove_all(fs::path(manifest).parent_path());
    return s;
}

} // namespace

TEST(LoopFolds, ReproducibleAndBalanced)
{
    const auto a = foldAssignment(23, 5, 3), b = foldAssignment(23, 5, 3);
    EXPECT_EQ(a, b);
    int counts[5] = {};
    for (int k : a) counts[k]++;
    for (int c : counts) EXPECT_TRUE(c == 4 || c == 5);
}

TEST(LoopSlope, FeDuDrIsPositiveWhereTheIcaIsOpen)
{
    ReductionSlope s;
    std::string err;
    ASSERT_TRUE(s.load(kSweep, &err)) << err;
    EXPECT_GE(s.cases(), 6);
    for (double n : {0.1, 0.25, 0.45})
        for (double mu : {0.1, 0.15, 0.2}) EXPECT_GT(s.slope(n, mu), 0.5) << n << " " << mu;
}

TEST(LoopSlope, CorrectionInvertsTheForwardEffect)
{
    ReductionSlope s;
    std::string err;
    ASSERT_TRUE(s.load(kSweep, &err)) << err;
    icacam::friction::PaperModel paper;
    icacam::friction::ModelInputs in;
    in.n = 0.2;
    const double u50 = uForMu(paper, 0.15, 0.2);
    in.uMm = u50 + s.slope(0.2, 0.15) * (0.53 - 0.5);
    EXPECT_NEAR(uAtModelReduction(paper, s, in, 0.53), u50, 0.01);
}

TEST(LoopSets, ProcessEffectRankedFirstAndCorrectedPhysically)
{
    for (uint32_t seed : {11u, 21u}) {
        const LoopSummary s = run("process" + std::to_string(seed), Effect::Process, seed);
        ASSERT_FALSE(s.ranking.empty());
        const std::string top = s.ranking.front().name;
        EXPECT_TRUE(top == "reduction" || top == "h_final_mm") << top;
        EXPECT_TRUE(s.physical);
        EXPECT_LT(s.cvRmsAfter, 0.5 * s.rmsBefore) << s.rmsBefore << " -> " << s.cvRmsAfter;
    }
}

TEST(LoopSets, OpticalEffectRankedFirst)
{
    for (uint32_t seed : {12u, 22u, 32u}) {
        const LoopSummary s = run("optical" + std::to_string(seed), Effect::Optical, seed);
        ASSERT_FALSE(s.ranking.empty());
        EXPECT_EQ(s.ranking.front().name, "lens") << "seed " << seed;
        EXPECT_EQ(s.chosen, "lens") << "seed " << seed;
        EXPECT_FALSE(s.physical);
        EXPECT_LT(s.cvRmsAfter, 0.7 * s.rmsBefore) << s.rmsBefore << " -> " << s.cvRmsAfter;
    }
}

TEST(LoopSets, NullSetAddsNothing)
{
    for (uint32_t seed : {13u, 14u, 15u}) {
        const LoopSummary s = run("null" + std::to_string(seed), Effect::Null, seed);
        EXPECT_TRUE(s.chosen.empty()) << "seed " << seed << " chose " << s.chosen;
        EXPECT_FALSE(s.physical);
        EXPECT_DOUBLE_EQ(s.cvRmsAfter, s.rmsBefore);
        for (const RankedCandidate &r : s.ranking) EXPECT_FALSE(r.significant) << r.name;
    }
}
