// The silhouette check against the FE (friction/radii_consistency.h, docs/loop-method.md): consistent
// records stay quiet, a scale error of 4 % fires, with and without a declared final
// height, and the reduction R_max implies is recovered. On rendered images through the whole
// pipeline as well as on the relation itself.
#include <gtest/gtest.h>

#include <cmath>

#include "friction/aspect_corrected_model.h"
#include "friction/paper_model.h"
#include "friction/radii_consistency.h"
#include "friction/reduction_corrected_model.h"
#include "host_tools/end_face_renderer.h"
#include "host_tools/model_inverse.h"
#include "reading/instrument.h"

using namespace icacam;
using friction::checkRadii;
using friction::feRMaxAt;

TEST(RadiiConsistency, FeSilhouetteGrowsWithReductionAndFriction)
{
    double a, b, c;
    ASSERT_TRUE(feRMaxAt(0.25, 0.15, 0.45, &a));
    ASSERT_TRUE(feRMaxAt(0.25, 0.15, 0.5, &b));
    ASSERT_TRUE(feRMaxAt(0.25, 0.25, 0.5, &c));
    EXPECT_GT(b, a + 0.1); // volume constancy: ≈ 0.35 mm per 0.05 of reduction
    EXPECT_GT(c, b);       // barrelling grows with μ
    // R0·√2 = 7.07 mm at 50 % without barrelling; the FE's barrel adds 1–5 %.
    EXPECT_GT(b, 7.07);
    EXPECT_LT(b, 7.07 * 1.05);
    // Past one snapshot step beyond the data: no answer rather than a guess.
    EXPECT_FALSE(feRMaxAt(0.25, 0.15, friction::radiiReductionMax() + 0.01, &a));
}

// The FE's offset above the reference specimens' R_max (data/fe/rmax_offset.py): 0.2–1.1 %
// over the development set, falling with n and with μ where n is low, and held beyond the
// span it was fitted on rather than extrapolated.
TEST(RadiiConsistency, FeOffsetOverSpecimensFallsWithNAndHoldsBeyondItsSpan)
{
    using friction::feRMaxOverSpecimen;
    for (double mu : {0.07, 0.15, 0.27}) {
        double last = 1;
        for (double n : {0.08, 0.15, 0.25, 0.35, 0.47}) {
            const double o = feRMaxOverSpecimen(n, mu);
            EXPECT_GT(o, 0.001) << n << " " << mu;
            EXPECT_LT(o, 0.014) << n << " " << mu;
            EXPECT_LT(o, last) << n << " " << mu;
            last = o;
        }
    }
    EXPECT_GT(feRMaxOverSpecimen(0.1, 0.1), feRMaxOverSpecimen(0.1, 0.25));
    EXPECT_EQ(feRMaxOverSpecimen(0.02, 0.2), feRMaxOverSpecimen(0.075, 0.2));
    EXPECT_EQ(feRMaxOverSpecimen(0.6, 0.2), feRMaxOverSpecimen(0.475, 0.2));
    EXPECT_EQ(feRMaxOverSpecimen(0.2, 0.4), feRMaxOverSpecimen(0.2, 0.275));
    EXPECT_EQ(feRMaxOverSpecimen(0.2, 0.01), feRMaxOverSpecimen(0.2, 0.065));
}

TEST(RadiiConsistency, ConsistentQuietScaleErrorFiresReductionRecovered)
{
    for (double n : {0.1, 0.3, 0.45})
        for (double mu : {0.08, 0.15, 0.22})
            for (double r : {0.47, 0.5, 0.52}) {
                double fe;
                ASSERT_TRUE(feRMaxAt(n, mu, r, &fe));
                const auto ok = checkRadii(fe, n, mu, 10, r);
                EXPECT_TRUE(ok.valid);
                EXPECT_FALSE(ok.inconsistent());
                EXPECT_NEAR(ok.reductionEst, r, 0.002) << n << " " << mu << " " << r;
                for (double scale : {1.04, 0.96}) {
                    const auto bad = checkRadii(fe * scale, n, mu, 10, r);
                    EXPECT_TRUE(bad.inconsistent()) << "scale " << scale << " z " << bad.z;
                }
                // Geometric similarity: a 20 mm specimen scales R_max.
                EXPECT_FALSE(checkRadii(2 * fe, n, mu, 20, r).inconsistent());
            }
}

TEST(RadiiConsistency, OtherSlendernessCarriesTheSilhouette)
{
    // A squat specimen (H0/D0 1.0) barrels less: its FE R_max is up to 1.8 % below the 10 x 15
    // one's (aspect_table.h). Checked at its own slenderness, a consistent silhouette is
    // quiet and gives its reduction back; checked as if it were 1.5 slender, it reads low.
    int biased = 0;
    for (double n : {0.1, 0.3, 0.45})
        for (double mu : {0.08, 0.15, 0.22})
            for (double r : {0.45, 0.5, 0.55}) {
                double fe;
                ASSERT_TRUE(feRMaxAt(n, mu, r, &fe));
                const double squat = fe * friction::AspectCorrectedModel::rMaxRatio(1.0, n, r, mu);
                EXPECT_LT(squat, fe);
                const auto own = checkRadii(squat, n, mu, 10, r, 10);
                EXPECT_TRUE(own.valid);
                EXPECT_NEAR(own.z, 0, 1e-9);
                EXPECT_NEAR(own.reductionEst, r, 0.002) << n << " " << mu << " " << r;
                const auto as15 = checkRadii(squat, n, mu, 10, r);
                EXPECT_LT(as15.z, own.z - 0.1);
                biased += std::fabs(as15.reductionEst - r) > 0.005;
                // At the paper's slenderness the ratio is 1: the same check as without H0.
                EXPECT_EQ(checkRadii(fe, n, mu, 10, r, 15).z, checkRadii(fe, n, mu, 10, r).z);
            }
    EXPECT_GT(biased, 0); // the carry matters somewhere, or this test checks nothing
}

namespace {

struct Rendered {
    cv::Mat img;
    host::EndFaceScene scene;
};

// A clean rendering of a specimen of hardening n and friction μ pressed to reduction r: the
// ring's width from the paper's model carried by the FE slope, the silhouette from the FE.
Rendered render(double n, double mu, double r)
{
    friction::PaperModel paper;
    const double u = host::uForMu(paper, mu, n) + friction::ReductionCorrectedModel::slopeAt(n, mu) * (r - 0.5);
    Rendered out;
    out.scene = host::nominalScene(u);
    double fe = 0;
    EXPECT_TRUE(feRMaxAt(n, mu, r, &fe));
    out.scene.rMaxMm = fe;
    out.img = host::renderEndFace(out.scene);
    return out;
}

reading::Reading measure(const Rendered &x, double n, double mmPerPx, double hFinal,
                         const friction::FrictionModel &model)
{
    static reading::Instrument analyzer;
    analyzer.configure(x.img.cols, x.img.rows, model);
    const vision::LumaView v{x.img.data, x.img.cols, x.img.rows, int(x.img.step[0]), 1};
    reading::SpecimenSpec spec{n, 500, 10, 15, mmPerPx};
    spec.hFinalMm = hFinal;
    return analyzer.read(v, spec);
}

} // namespace

TEST(RadiiConsistency, ThroughThePipelineOnRenderedImages)
{
    friction::PaperModel paper;
    friction::ReductionCorrectedModel model(paper, "paper_reduction");
    const uint32_t kCheck = reading::kFlagScaleSuspect | reading::kFlagRadiiInconsistent;
    for (double r : {0.5, 0.515}) {
        const Rendered x = render(0.25, 0.15, r);
        const double s = x.scene.mmPerPx;
        // Declared final height, right scale: quiet; μ recovered by the corrected model.
        auto m = measure(x, 0.25, s, 15 * (1 - r), model);
        ASSERT_TRUE(m.hasValue());
        EXPECT_FALSE(m.flags & kCheck) << "r " << r << " z " << m.rMaxZ;
        EXPECT_NEAR(m.mu, 0.15, 0.006) << "r " << r;
        // The lab's mm_per_px 4 % off: the silhouette contradicts scale and height.
        for (double k : {1.04, 0.96}) {
            m = measure(x, 0.25, s * k, 15 * (1 - r), model);
            ASSERT_TRUE(m.hasValue());
            EXPECT_TRUE(m.flags & reading::kFlagRadiiInconsistent) << "r " << r << " k " << k << " z " << m.rMaxZ;
        }
        // No final height given: the reduction is inferred from R_max.
        m = measure(x, 0.25, s, 0, model);
        ASSERT_TRUE(m.hasValue());
        EXPECT_NEAR(m.reductionEst, r, 0.008) << "r " << r;
        EXPECT_FALSE(m.flags & reading::kFlagRadiiInconsistent);
        m = measure(x, 0.25, s * 1.04, 0, model);
        EXPECT_TRUE(m.flags & reading::kFlagScaleSuspect) << "z " << m.rMaxZ;
        // The implied reduction moves up by ≈ 0.04, or past what the FE snapshots span (-1).
        EXPECT_TRUE(m.reductionEst < 0 || m.reductionEst > r + 0.025) << m.reductionEst;
    }
    // A specimen pressed to 54.5 % without saying so: the image tells (flag, estimate).
    const Rendered far = render(0.25, 0.15, 0.545);
    auto m = measure(far, 0.25, far.scene.mmPerPx, 0, model);
    ASSERT_TRUE(m.hasValue());
    EXPECT_TRUE(m.flags & reading::kFlagScaleSuspect) << "z " << m.rMaxZ;
    EXPECT_NEAR(m.reductionEst, 0.545, 0.008);
    // Declared, inside or outside what the model's FE data cover: the model's range flag
    // reaches the measurement (never a silent value).
    m = measure(far, 0.25, far.scene.mmPerPx, 15 * (1 - 0.545), model);
    ASSERT_TRUE(m.hasValue());
    EXPECT_EQ((m.flags & reading::kFlagReductionOutside) != 0,
              0.545 > friction::ReductionCorrectedModel::reductionMax());
    EXPECT_FALSE(m.flags & reading::kFlagRadiiInconsistent) << "z " << m.rMaxZ;
    if (m.flags & reading::kFlagReductionOutside) { EXPECT_EQ(m.status, reading::Status::Warn); }
    const Rendered mid = render(0.25, 0.15, 0.515);
    m = measure(mid, 0.25, mid.scene.mmPerPx, 15 * (1 - 0.515), model);
    EXPECT_FALSE(m.flags & reading::kFlagReductionOutside);
}
