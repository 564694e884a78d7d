// The status's lines on physically rendered photographs (PRODUCT.md §7, docs/uncertainty.md):
// a small set per condition rendered by POV-Ray from a seed no tuning saw, measured with the
// default model as a user would, and scored with `icacam score`'s code. Where a line is not yet
// reached the measured floor is kept, so that it cannot slip further unseen
// (data/photobench/README.md has the larger sets' figures). Skipped where POV-Ray is not
// installed.
#include <gtest/gtest.h>

#include <filesystem>

#include "host_tools/photo/photo_bench.h"
#include "tests/host_tools/coverage_support.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

struct PhotoLines {
    double measured = 0;  // share of the records measured
    double within = 0;    // share of the measured within 2 σ
    double ok = 0;        // share of the measured that say ok
    double okOnRight = 0; // share of the right readings that say ok
    int silentWrong = 0;  // ok and beyond max(0.01, 5 % of μ)
};

void expectScore(const test::ScoredSet &set, const std::string &name, int count, PhotoLines line)
{
    const host::ConditionScore *c = set.report.find(name);
    ASSERT_TRUE(c) << name;
    EXPECT_EQ(c->total, count);
    EXPECT_GE(double(c->measured) / c->total, line.measured) << c->measured << " of " << c->total << " measured";
    EXPECT_LE(c->silentWrong, line.silentWrong) << "worst ok " << c->worstOkDmu << " (" << c->worstOkId << ")";
    EXPECT_GE(c->withinFraction(), line.within) << c->withinK << " of " << c->measured << " within 2 σ";
    EXPECT_GE(c->okFraction(), line.ok) << c->ok << " of " << c->measured << " ok";
    EXPECT_GE(c->okOnRightFraction(), line.okOnRight) << "ok on " << c->okRight << " of " << c->right << " right";
}

// Renders the set, measures it as rendered and holds `line`; with `heightLine`, measures it
// again with the final height declared (the bench presses to 50 %: 7.5 mm) and holds that.
void expectLines(host::photo::PhotoCondition condition, const std::string &name, int count, uint32_t seed,
                 PhotoLines line, const PhotoLines *heightLine = nullptr)
{
#ifdef ICACAM_SANITIZED
    GTEST_SKIP() << "rendered sets are not run under a sanitizer";
#endif
    if (!host::photo::povrayAvailable()) GTEST_SKIP() << "povray is not installed (apt-get install povray)";
    const fs::path dir = test::tempDir("photo-status-" + name);
    host::photo::PhotoBenchOptions opt;
    opt.conditions = {condition};
    opt.countPerCondition = count;
    opt.seed = seed;
    opt.frame = host::photo::PhotoFrame::Small;
    opt.quiet = true;
    opt.profilesCsv = std::string(ICACAM_SOURCE_DIR) + "/data/photobench/fe_profiles.csv";
    const std::string manifest = host::photo::writePhotoSet(dir.string(), opt);
    expectScore(test::measureAndScore(dir, manifest), name, count, line);
    if (heightLine) {
        test::declareColumns(manifest, {{"h_final_mm", "7.5"}});
        expectScore(test::measureAndScore(dir, manifest), name, count, *heightLine);
    }
    fs::remove_all(dir);
}

} // namespace

// A straight camera at a declared scale: the lines are 95 % measured, 90 % within 2 σ and
// 90 % ok. Measured: 16 of 16, 100 % within 2 σ, none silent; 4 ok, on 4 of the 11 right
// readings, the ok share far below its line (contact_edge_ramp at 640 × 480, the working
// distance the image cannot weigh, a right reading without a silhouette: docs/photographs.md
// "What is known to be off"). The
// same photographs with the final height declared, as the advice asks: 16 of 16, 88 %
// within 2 σ (under its line), none silent; 3 ok, on 3 of the 11 right readings (the
// undeclared height's share of U no longer covers the edges' own errors:
// docs/photographs.md).
TEST(PhotoStatus, StraightCameraDeclaredScale)
{
    const PhotoLines declaredHeight{0.95, 0.87, 0.18, 0.27, 0};
    expectLines(host::photo::PhotoCondition::Straight, "straight", 16, 21, {0.95, 0.9, 0.25, 0.36, 0}, &declaredHeight);
}

// A tilted camera, the mean scale declared: an undeclared condition, so no silent wrong
// reading, 90 % within 2 σ and ok on at least half of the right ones are the lines.
// Measured: 11 of 12, 100 % within 2 σ, none silent; 2 ok, on 2 of the 7 right readings (the
// eleventh, a 5 px dark ring read on the profile's last step, warns: contact_edge_undecided).
TEST(PhotoStatus, TiltedCamera)
{
    expectLines(host::photo::PhotoCondition::Tilted, "tilted", 12, 21, {0.9, 0.9, 0.18, 0.28, 0});
}
