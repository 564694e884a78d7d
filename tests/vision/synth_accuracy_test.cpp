// Accuracy over many random synthetic cases rendered by our own renderer, with nuisances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "friction/paper_model.h"
#include "host_tools/end_face_renderer.h"
#include "host_tools/model_inverse.h"
#include "reading/instrument.h"

using namespace icacam;

namespace {

// A random scene of the given friction and exponent (the barrel from volume constancy, the
// nuisances as randomScene draws them), rendered.
struct Rendered {
    host::EndFaceScene scene;
    cv::Mat image;
    vision::LumaView view() const { return {image.data, image.cols, image.rows, int(image.step[0]), 1}; }
};

Rendered renderRandom(std::mt19937 &rng, double n, double mu)
{
    const double u = host::uForMu(friction::PaperModel(), mu, n);
    const double rOuter = 6.85 - 0.95 * u;
    const double rMax = 5.0 * std::sqrt(2.0) * (1.008 + 0.034 * u);
    Rendered r{host::randomScene(rng, u, rOuter, rMax, false), {}};
    r.image = host::renderEndFace(r.scene);
    return r;
}

} // namespace

TEST(SynthAccuracy, RandomScenesWithNuisances)
{
    std::mt19937 rng(20261121);
    std::uniform_real_distribution<double> U(0, 1);
    reading::Instrument analyzer;
    friction::PaperModel model;
    ASSERT_EQ(analyzer.configure(2028, 1520, model), vision::ErrorCode::None);
    std::vector<double> errs;
    int silentWrong = 0;
    const int cases = 30;
    for (int i = 0; i < cases; ++i) {
        const double n = 0.05 + 0.45 * U(rng), mu = 0.06 + 0.23 * U(rng);
        const Rendered r = renderRandom(rng, n, mu);
        const host::EndFaceScene &s = r.scene;
        const reading::SpecimenSpec spec{n, 500, 10, 15, s.mmPerPx};
        const reading::Reading m = analyzer.read(r.view(), spec);
        const double muTrue = model.estimate({s.rOuterEqMm() - s.rInnerEqMm(), n}).mu;
        if (!m.hasValue()) {
            errs.push_back(1);
            continue;
        }
        const double e = std::fabs(m.mu - muTrue);
        errs.push_back(e);
        // Scenes at the exact scale and 50 %: the silhouette check stays quiet.
        EXPECT_FALSE(m.flags & (reading::kFlagScaleSuspect | reading::kFlagRadiiInconsistent))
            << "case " << i << " r_max_z " << m.rMaxZ;
        if (e > std::max(0.01, 0.05 * muTrue) && m.status == reading::Status::Ok) ++silentWrong;
        RecordProperty("case" + std::to_string(i), std::to_string(e));
    }
    std::sort(errs.begin(), errs.end());
    const double median = errs[errs.size() / 2];
    const double p90 = errs[errs.size() * 9 / 10];
    std::printf("synth: median |dmu| %.4f, p90 %.4f, max %.4f\n", median, p90, errs.back());
    EXPECT_LE(median, 0.002);
    EXPECT_LE(p90, 0.008);
    EXPECT_EQ(silentWrong, 0);
}

TEST(SynthAccuracy, RecordedReductionOutsideTheModelIsFlagged)
{
    const host::EndFaceScene s = host::nominalScene(0.6);
    const cv::Mat img = host::renderEndFace(s);
    reading::Instrument analyzer;
    friction::PaperModel model;
    ASSERT_EQ(analyzer.configure(img.cols, img.rows, model), vision::ErrorCode::None);
    const vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
    reading::SpecimenSpec spec{0.25, 500, 10, 15, s.mmPerPx};
    spec.hFinalMm = 7.5; // exactly 50 %
    auto m = analyzer.read(v, spec);
    ASSERT_TRUE(m.hasValue());
    EXPECT_FALSE(m.flags & reading::kFlagReductionOutside);
    spec.hFinalMm = 7.0; // 53 %
    m = analyzer.read(v, spec);
    EXPECT_TRUE(m.flags & reading::kFlagReductionOutside);
    EXPECT_EQ(m.status, reading::Status::Warn);
}

// Well-lubricated specimens leave a ring a few pixels wide (μ 0.05–0.07: u 2–5 px at these
// scales), too narrow for the per-ray search: the aligned profile's two-step fit measures it
// (no per-ray inner points), and its σ covers the error.
TEST(SynthAccuracy, NarrowRingsOfWellLubricatedSpecimens)
{
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<double> U(0, 1);
    reading::Instrument analyzer;
    friction::PaperModel model;
    ASSERT_EQ(analyzer.configure(2028, 1520, model), vision::ErrorCode::None);
    int measured = 0, narrow = 0, covered = 0;
    const int cases = 16;
    for (int i = 0; i < cases; ++i) {
        const double n = 0.3 + 0.2 * U(rng), mu = 0.05 + 0.02 * U(rng);
        const Rendered r = renderRandom(rng, n, mu);
        const host::EndFaceScene &s = r.scene;
        reading::SpecimenSpec spec{n, 500, 10, 15, s.mmPerPx};
        spec.hFinalMm = 7.5;
        const reading::Reading m = analyzer.read(r.view(), spec);
        const double uTrue = s.rOuterEqMm() - s.rInnerEqMm();
        std::printf("case %2d: u %.1f px  %s", i, uTrue / s.mmPerPx, m.hasValue() ? "" : "not measured\n");
        if (!m.hasValue()) continue;
        ++measured;
        const bool fromProfile = m.geometry.inner.used == 0;
        narrow += fromProfile;
        const double muTrue = model.estimate({uTrue, n}).mu;
        const double sigma = std::sqrt(m.muSigma * m.muSigma - m.budget.model * m.budget.model);
        covered += std::fabs(m.mu - muTrue) <= 2 * sigma;
        std::printf("measured %.1f px, dmu %+.4f, sigma %.4f%s\n", m.uPx, m.mu - muTrue, sigma,
                    fromProfile ? ", from the profile" : "");
        EXPECT_FALSE(m.status == reading::Status::Ok && std::fabs(m.mu - muTrue) > 0.01) << "case " << i;
    }
    EXPECT_GE(measured, cases * 3 / 4);
    EXPECT_GE(narrow, 1) << "no scene needed the narrow-ring fit: the cases no longer test it";
    EXPECT_GE(covered, measured * 9 / 10);
}
