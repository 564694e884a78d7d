// The product's accuracy bar on the reference set (../shared/data/devset): every image
// measured, median |μ − μ_true| ≤ 0.002, max ≤ 0.008 (PRODUCT.md §7), with the paper model;
// no consistency flag on any of them (docs/loop-method.md, "Consistency of the radii").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "host_tools/measure_command.h"
#include "tests/host_tools/test_support.h"

using namespace icacam;
namespace fs = std::filesystem;

TEST(Devset, AccuracyBar)
{
    const fs::path dev = fs::path(test::sharedData()) / "devset";
    if (!fs::exists(dev / "manifest.csv")) GTEST_SKIP() << "no devset at " << dev;
    const fs::path dir = test::tempDir("devset");
    const std::string out = (dir / "out.csv").string();
    ASSERT_EQ(host::measureCommand({"--manifest", (dev / "manifest.csv").string(), "--out", out, "--model", "paper"}),
              0);
    auto got = test::readCsvById(out);
    auto truth = test::readCsvById((dev / "truth.csv").string());
    ASSERT_FALSE(truth.empty());
    std::vector<double> errs;
    int withoutSilhouette = 0;
    for (auto &[id, t] : truth) {
        auto &r = got[id];
        ASSERT_NE(r["status"], "error") << id << ": " << r["message"];
        const double e = std::fabs(std::stod(r["mu"]) - std::stod(t["mu"]));
        errs.push_back(e);
        EXPECT_LE(e, 0.008) << id;
        // Every devset image is consistent (exact scale, 50 %): the silhouette check against
        // the FE must stay quiet, and the reduction R_max implies must be near 50 % (it is
        // good to about 0.01, 1 σ: docs/loop-method.md).
        EXPECT_EQ(r["flags"].find("scale_suspect"), std::string::npos) << id << " r_max_z " << r["r_max_z"];
        EXPECT_EQ(r["flags"].find("radii_inconsistent"), std::string::npos) << id;
        // One dark barrel on a dark fixture (devset-032) shows no outline on the rays: the
        // reading says so and reports no reduction of its own.
        if (r["flags"].find("no_silhouette") != std::string::npos) {
            ++withoutSilhouette;
            continue;
        }
        ASSERT_FALSE(r["reduction_est"].empty()) << id;
        EXPECT_NEAR(std::stod(r["reduction_est"]), 0.5, 0.03) << id;
    }
    EXPECT_LE(withoutSilhouette, 1);
    std::sort(errs.begin(), errs.end());
    std::printf("devset: %zu images, median |dmu| %.4f, max %.4f\n", errs.size(), errs[errs.size() / 2], errs.back());
    EXPECT_LE(errs[errs.size() / 2], 0.002);
    fs::remove_all(dir);
}
