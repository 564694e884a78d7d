// The coverage bench itself: `icacam score` counts what it says it counts, and the sets of
// `icacam synth --condition` hold what their truth says (measured with the condition
// declared, the pipeline reads them as it reads the development set's kind).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "host_tools/score_comparison.h"
#include "tests/host_tools/coverage_support.h"

using namespace icacam;

namespace {

host::Manifest csv(const std::string &text)
{
    host::Manifest m;
    std::string err;
    EXPECT_TRUE(host::parseManifest(text, &m, &err)) << err;
    return m;
}

double num(const host::ManifestRow &r, const std::string &k)
{
    double v = NAN;
    host::parseNumber(r.get(k), &v);
    return v;
}

} // namespace

TEST(Score, CountsSilentWrongAnswersAndCoveragePerCondition)
{
    const host::Manifest truth = csv("id,condition,mu\n"
                                     "a1,plain,0.100\na2,plain,0.200\na3,plain,0.150\n"
                                     "b1,odd,0.100\nb2,odd,0.300\nb3,odd,0.200\n");
    // a1: ok, 1 σ off; a2: ok, 0.012 off = beyond max(0.01, 0.05·0.2 = 0.01): silent wrong,
    // and 4 σ; a3: warn 0.05 off (not silent), 10 σ. b1: error; b2: ok 0.014 off (within
    // 5 % of 0.3 = 0.015: not silent), 0.7 σ; b3: no result at all.
    const host::Manifest results = csv("id,status,mu,mu_sigma,model\n"
                                       "a1,ok,0.102,0.002,paper_reduction\n"
                                       "a2,ok,0.212,0.003,paper_reduction\n"
                                       "a3,warn,0.200,0.005,paper_reduction\n"
                                       "b1,error,,,paper_reduction\n"
                                       "b2,ok,0.314,0.020,paper_reduction\n");
    host::ScoreReport r;
    std::string err;
    ASSERT_TRUE(host::scoreResults(results, truth, {}, &r, &err)) << err;
    const host::ConditionScore *plain = r.find("plain"), *odd = r.find("odd"), *all = r.find("all");
    ASSERT_TRUE(plain && odd && all);
    EXPECT_EQ(plain->total, 3);
    EXPECT_EQ(plain->measured, 3);
    EXPECT_EQ(plain->ok, 2);
    EXPECT_EQ(plain->silentWrong, 1);
    EXPECT_EQ(plain->right, 1) << "a1 alone lies within the tolerance";
    EXPECT_EQ(plain->okRight, 1);
    EXPECT_EQ(plain->withinK, 1);
    EXPECT_NEAR(plain->medianRatio, 4.0, 1e-9);
    EXPECT_NEAR(plain->worstDmu, 0.05, 1e-9);
    EXPECT_EQ(plain->worstId, "a3");
    EXPECT_EQ(plain->worstStatus, "warn");
    EXPECT_NEAR(plain->worstOkDmu, 0.012, 1e-9);
    EXPECT_EQ(odd->total, 3);
    EXPECT_EQ(odd->measured, 1);
    EXPECT_EQ(odd->silentWrong, 0);
    EXPECT_EQ(odd->right, 1);
    EXPECT_EQ(odd->okRight, 1);
    EXPECT_EQ(odd->withinK, 1);
    EXPECT_EQ(all->total, 6);
    EXPECT_EQ(all->measured, 4);
    EXPECT_EQ(all->silentWrong, 1);
    EXPECT_NE(std::find(r.notes.begin(), r.notes.end(), "b3: no result"), r.notes.end());
    // A tighter tolerance makes b2 silent wrong too.
    host::ScoreOptions tight;
    tight.toleranceRel = 0.04;
    ASSERT_TRUE(host::scoreResults(results, truth, tight, &r, &err));
    EXPECT_EQ(r.find("odd")->silentWrong, 1);
    EXPECT_EQ(r.find("odd")->okRight, 0) << "b2 is no longer right";
    const std::string table = host::formatScore(r, tight, true);
    EXPECT_NE(table.find("| plain | 3 of 3 | 2 | 1 of 1 | 1 | 33 % |"), std::string::npos) << table;
}

// Two runs of the same records: the readings that differ in status, μ or flags are listed
// with each run's Δμ, and both runs are counted as the score counts them.
TEST(Score, ComparesTwoRunsReadingByReading)
{
    const host::Manifest truth = csv("id,mu\na,0.100\nb,0.200\nc,0.150\nd,0.120\n");
    // a: the same in both; b: warn → ok, 0.015 off (silent wrong after); c: μ moves, right in
    // both; d: an error before, ok and right after.
    const host::Manifest before = csv("id,status,mu,flags\n"
                                      "a,ok,0.101,\n"
                                      "b,warn,0.215,no_silhouette\n"
                                      "c,warn,0.152,contact_edge_ramp\n"
                                      "d,error,,\n");
    const host::Manifest after = csv("id,status,mu,flags\n"
                                     "a,ok,0.101,\n"
                                     "b,ok,0.215,\n"
                                     "c,warn,0.149,contact_edge_ramp\n"
                                     "d,ok,0.121,\n");
    host::ComparisonReport r;
    std::string err;
    ASSERT_TRUE(host::compareResults(before, after, truth, {}, &r, &err)) << err;
    EXPECT_EQ(r.records, 4);
    ASSERT_EQ(r.changed.size(), 3u);
    EXPECT_EQ(r.changed[0].id, "b");
    EXPECT_EQ(r.changed[1].id, "c");
    EXPECT_EQ(r.changed[2].id, "d");
    EXPECT_NEAR(r.changed[0].after.dmu, 0.015, 1e-9);
    EXPECT_FALSE(r.changed[0].after.right);
    EXPECT_TRUE(r.changed[1].before.right && r.changed[1].after.right);
    EXPECT_EQ(r.before.measured, 3);
    EXPECT_EQ(r.after.measured, 4);
    EXPECT_EQ(r.before.okRight, 1);
    EXPECT_EQ(r.after.okRight, 2);
    EXPECT_EQ(r.before.silentWrong, 0);
    EXPECT_EQ(r.after.silentWrong, 1);
    const std::string text = host::formatComparison(r);
    EXPECT_NE(text.find("3 of 4 readings differ"), std::string::npos) << text;
    EXPECT_NE(text.find("ok   +0.0150 silent wrong"), std::string::npos) << text;
    // A run without a status column is refused with the file named.
    const host::Manifest bare = csv("id,mu\na,0.1\n");
    EXPECT_FALSE(host::compareResults(bare, after, truth, {}, &r, &err));
    EXPECT_NE(err.find("before"), std::string::npos) << err;
}

// With the budget columns, σ drops the model's own fit error when the truth is the paper's
// and the paper's model measured; another model keeps it.
TEST(Score, TakesTheBudgetWithoutTheModelTermWhenTheTruthIsTheModelsOwn)
{
    const host::Manifest truth = csv("id,mu\nx,0.100\ny,0.100\n");
    const std::string header =
        "id,status,mu,mu_sigma,sigma_edges,sigma_scale,sigma_reduction,sigma_n,sigma_model,model\n";
    // mu_sigma 0.005 = sqrt(0.003² + 0.004²) with sigma_model 0.004: without it σ = 0.003.
    const host::Manifest paper = csv(header + "x,ok,0.1070,0.005,0.003,0,0,0,0.004,paper\n"
                                              "y,ok,0.1020,0.005,0.003,0,0,0,0.004,paper_reduction\n");
    host::ScoreReport r;
    std::string err;
    ASSERT_TRUE(host::scoreResults(paper, truth, {}, &r, &err)) << err;
    const host::ConditionScore *all = r.find("all");
    ASSERT_TRUE(all);
    EXPECT_EQ(all->withinK, 1); // x: 0.007 > 2 · 0.003
    EXPECT_NEAR(all->medianRatio, 0.5 * (0.007 / 0.003 + 0.002 / 0.003), 1e-6);
    EXPECT_NE(r.sigmaSource.find("sigma_model"), std::string::npos);
    const host::Manifest fe = csv(header + "x,ok,0.1070,0.005,0.003,0,0,0,0.004,fe\n"
                                           "y,ok,0.1020,0.005,0.003,0,0,0,0.004,fe\n");
    ASSERT_TRUE(host::scoreResults(fe, truth, {}, &r, &err)) << err;
    EXPECT_EQ(r.find("all")->withinK, 2); // 0.007 ≤ 2 · 0.005
    host::ScoreOptions drop;
    drop.modelSigma = host::ModelSigma::Drop;
    ASSERT_TRUE(host::scoreResults(fe, truth, drop, &r, &err)) << err;
    EXPECT_EQ(r.find("all")->withinK, 1);
    // Today's results (mu_sigma only) are scored on mu_sigma whatever the model.
    const host::Manifest plain = csv("id,status,mu,mu_sigma,model\nx,ok,0.107,0.005,paper\ny,ok,0.102,0.005,paper\n");
    ASSERT_TRUE(host::scoreResults(plain, truth, {}, &r, &err)) << err;
    EXPECT_EQ(r.find("all")->withinK, 2);
    // A results file without mu_sigma is not a result file.
    EXPECT_FALSE(host::scoreResults(csv("id,status,mu\nx,ok,0.1\n"), truth, {}, &r, &err));
    EXPECT_NE(err.find("mu_sigma"), std::string::npos);
}

// Every condition's set holds what its truth says: parameters in the stated ranges, and,
// measured with everything declared (the final height, the true scale, the true camera),
// read like the development set's kind. A truth that did not match its images would shift
// every reading of a condition.
TEST(SynthConditions, TruthMatchesTheImagesWhenTheConditionIsDeclared)
{
    const int count = 4;
    test::ScoredSet set =
        test::renderMeasureScore("synth-conditions", "declared,reduction,fixture_scale,tilt,lowres", count, 4242);
    const auto &truthRows = set.truth.rows;
    ASSERT_EQ(truthRows.size(), size_t(5 * count));
    std::ostringstream declared;
    declared << "id,image,n,k_mpa,d0_mm,h0_mm,mm_per_px,h_final_mm,calibration\n";
    for (size_t i = 0; i < truthRows.size(); ++i) {
        const host::ManifestRow &t = truthRows[i], &m = set.manifest.rows[i];
        ASSERT_EQ(t.get("id"), m.get("id"));
        const std::string cond = t.get("condition");
        const double scaleError = num(t, "scale_error"), wd = num(t, "working_distance_mm");
        const double trueScale = num(t, "u_mm") / num(t, "u_px");
        const cv::Mat img = cv::imread((set.dir / m.get("image")).string(), cv::IMREAD_GRAYSCALE);
        ASSERT_FALSE(img.empty()) << t.get("id");
        EXPECT_EQ(img.cols, int(num(t, "width")));
        EXPECT_EQ(img.rows, int(num(t, "height")));
        // Declared: the final height always (else the reading infers the reduction from a
        // silhouette the perspective or a coarse frame moves), the true scale or camera.
        double mmPerPx = num(m, "mm_per_px");
        const double hFinal = 15 * (1 - num(t, "reduction"));
        std::string calib;
        if (cond == "reduction") {
            EXPECT_GE(num(t, "reduction"), 0.45);
            EXPECT_LE(num(t, "reduction"), 0.55);
        } else
            EXPECT_EQ(num(t, "reduction"), 0.5) << t.get("id");
        if (cond == "fixture_scale") {
            EXPECT_GE(wd, 70);
            EXPECT_LE(wd, 150);
            EXPECT_NEAR(scaleError, wd / (wd - 7.5) - 1, 2e-4);
            EXPECT_NEAR(mmPerPx / trueScale, 1 + scaleError, 2e-3);
            mmPerPx /= 1 + scaleError;
        } else
            EXPECT_NEAR(scaleError, 0, 1e-4) << t.get("id");
        if (cond == "tilt") {
            EXPECT_GE(num(t, "tilt_deg"), 6);
            EXPECT_LE(num(t, "tilt_deg"), 15);
            EXPECT_GE(num(t, "k1"), -0.35);
            EXPECT_LE(num(t, "k1"), -0.1);
            EXPECT_NEAR(num(t, "focal_px") / num(t, "width"), 1.1, 0.1);
            calib = t.get("camera_truth");
            EXPECT_FALSE(calib.empty());
        }
        if (cond == "lowres") {
            EXPECT_TRUE((img.cols == 640 && img.rows == 480) || (img.cols == 1280 && img.rows == 720)) << img.size();
            EXPECT_GE(1 / trueScale, 19 - 0.05);
            EXPECT_LE(1 / trueScale, (img.cols == 640 ? 30 : 42) + 0.05);
        }
        declared << t.get("id") << "," << m.get("image") << "," << m.get("n") << "," << m.get("k_mpa") << ",10,15,";
        if (calib.empty()) declared << mmPerPx;
        declared << "," << hFinal << "," << calib << "\n";
    }
    EXPECT_FALSE(set.manifest.rows[0].has("h_final_mm")) << "the reduction is not declared";
    // Measured with the condition declared.
    const std::string path = (set.dir / "declared.csv").string();
    std::ofstream(path) << declared.str();
    const std::string out = (set.dir / "declared-results.csv").string();
    testing::internal::CaptureStderr();
    host::measureCommand({"--manifest", path, "--out", out});
    testing::internal::GetCapturedStderr();
    host::Manifest results;
    std::string err;
    ASSERT_TRUE(host::readManifest(out, &results, &err)) << err;
    host::ScoreReport r;
    ASSERT_TRUE(host::scoreResults(results, set.truth, {}, &r, &err)) << err;
    std::printf("with the conditions declared:\n%s", host::formatScore(r, {}, false).c_str());
    for (const char *cond : {"declared", "reduction", "fixture_scale", "tilt", "lowres"}) {
        const host::ConditionScore *c = r.find(cond);
        ASSERT_TRUE(c) << cond;
        EXPECT_GE(c->measured, count - 1) << cond;
        EXPECT_LE(c->medianAbs, 0.004) << cond; // the edge model alone: about 0.001
    }
    std::filesystem::remove_all(set.dir);
}
