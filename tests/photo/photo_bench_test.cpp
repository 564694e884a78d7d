// The photographic bench itself (host_tools/photo, docs/photobench.md): the FE barrel
// profiles it builds the side from, its camera's projection, and a small set rendered by
// POV-Ray whose truth is checked against the renderer's own label images (the zones as flat
// greys through the same camera). Skipped where POV-Ray is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "friction/paper_model.h"
#include "host_tools/photo/barrel_profile.h"
#include "host_tools/photo/photo_bench.h"
#include "host_tools/photo/photo_record.h"
#include "host_tools/photo/photo_scene.h"
#include "tests/host_tools/test_support.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

const std::string kProfiles = std::string(ICACAM_SOURCE_DIR) + "/data/photobench/fe_profiles.csv";

double num(const std::map<std::string, std::string> &row, const std::string &key)
{
    double v = NAN;
    const auto it = row.find(key);
    if (it != row.end()) host::parseNumber(it->second, &v);
    return v;
}

} // namespace

TEST(BarrelProfiles, CoverTheGridAndRunFromTheWidestSectionToTheContactEdge)
{
    const auto table = host::photo::readBarrelProfiles(kProfiles);
    for (double n : host::photo::profileGridN())
        for (double mu : host::photo::profileGridMu())
            for (double red : host::photo::profileReductions()) {
                const auto shape = host::photo::barrelShapeAt(table, n, mu, red);
                ASSERT_EQ(shape.s.size(), size_t(host::photo::kShapePoints));
                EXPECT_NEAR(shape.zeta.front(), 0, 1e-9) << n << " " << mu << " " << red;
                EXPECT_NEAR(shape.zeta.back(), 1, 1e-9);
                EXPECT_NEAR(shape.s.back(), 0, 1e-9);
                // The widest section is the mid-plane (the FE's symmetry plane).
                EXPECT_NEAR(*std::max_element(shape.s.begin(), shape.s.end()), shape.s.front(), 1e-3);
                EXPECT_GT(shape.s.front(), 0.99);
                for (size_t k = 1; k < shape.zeta.size(); ++k) EXPECT_GE(shape.zeta[k], shape.zeta[k - 1] - 1e-9);
            }
}

// The same specimen, camera and light with its side flattened about the widest section
// (--flat-barrel): the radii stay, the outline a close camera sees moves towards R_max (the
// FE's 3–6 % inside it at 45–95 mm, a parametric barrel's 1–3 %), a barrel the reading must
// take at half height whether or not the working distance is declared.
TEST(PhotoBench, AFlatterBarrelShowsItsOutlineNearerRMax)
{
    const auto table = host::photo::readBarrelProfiles(kProfiles);
    for (uint32_t seed : {3u, 11u, 29u}) {
        std::mt19937 a(seed), b(seed);
        const auto fe =
            host::photo::drawRecord(host::photo::PhotoCondition::Straight, host::photo::FaceProfile::Staircase, a,
                                    table, host::photo::PhotoFrame::Small);
        const auto flat =
            host::photo::drawRecord(host::photo::PhotoCondition::Straight, host::photo::FaceProfile::Staircase, b,
                                    table, host::photo::PhotoFrame::Small, 4);
        ASSERT_EQ(fe.scene.rMaxMm, flat.scene.rMaxMm);
        ASSERT_EQ(fe.scene.rOuterMm, flat.scene.rOuterMm);
        ASSERT_EQ(fe.workingDistanceMm, flat.workingDistanceMm);
        const double rMax = fe.scene.rMaxMm;
        // The outline in pixels at the end face's scale, as the truth file gives it.
        const double feRatio = host::photo::projectTruth(fe.scene).outlinePx * fe.trueMmPerPx / rMax;
        const double flatRatio = host::photo::projectTruth(flat.scene).outlinePx * flat.trueMmPerPx / rMax;
        SCOPED_TRACE(fe.workingDistanceMm);
        EXPECT_LT(feRatio, 0.975);
        EXPECT_GT(flatRatio, feRatio + 0.01);
        EXPECT_LT(flatRatio, 1);
    }
}

// The reference photographs' larger frame (--large): the same specimen, finish and light
// drawn, on 2028 × 1520 pixels at about 1.4 times the 1456 × 1088 frame's pixels per mm.
TEST(PhotoBench, TheLargeFrameDrawsTheSameSpecimenOnMorePixels)
{
    const auto table = host::photo::readBarrelProfiles(kProfiles);
    for (uint32_t seed : {3u, 11u}) {
        std::mt19937 a(seed), b(seed);
        const auto full =
            host::photo::drawRecord(host::photo::PhotoCondition::Straight, host::photo::FaceProfile::DarkRing, a, table,
                                    host::photo::PhotoFrame::Full);
        const auto large =
            host::photo::drawRecord(host::photo::PhotoCondition::Straight, host::photo::FaceProfile::DarkRing, b, table,
                                    host::photo::PhotoFrame::Large);
        EXPECT_EQ(full.scene.camera.width, 1456);
        EXPECT_EQ(large.scene.camera.width, 2028);
        EXPECT_EQ(large.scene.camera.height, 1520);
        EXPECT_EQ(full.scene.rOuterMm, large.scene.rOuterMm);
        EXPECT_EQ(full.mu50, large.mu50);
        EXPECT_EQ(full.material, large.material);
        EXPECT_NEAR(full.trueMmPerPx / large.trueMmPerPx, 1520.0 / 1088, 0.02);
    }
}

TEST(PhotoCamera, ProjectsItsTargetOntoTheImageCentreAndKeepsTheScale)
{
    for (double tilt : {0.0, 12.0}) {
        const cv::Vec3d target(1, 7.5, -2);
        const auto cam = host::photo::cameraLookingAt(target, 60, tilt, 40, 3000, 640, 480);
        const cv::Point2d c = cam.project(target);
        EXPECT_NEAR(c.x, 319.5, 1e-9);
        EXPECT_NEAR(c.y, 239.5, 1e-9);
        EXPECT_NEAR(cv::norm(cam.location - target), 60, 1e-9);
        if (tilt == 0) {
            // Straight down: 1 mm in the target's plane is f / WD pixels, +x to the right.
            const cv::Point2d d = cam.project(target + cv::Vec3d(1, 0, 0));
            EXPECT_NEAR(d.x - c.x, 50, 1e-9);
            EXPECT_NEAR(d.y - c.y, 0, 1e-9);
        }
    }
}

TEST(PhotoBench, RendersASmallSetWhoseTruthMatchesTheRenderedGeometry)
{
    if (!host::photo::povrayAvailable()) GTEST_SKIP() << "povray is not installed (apt-get install povray)";
    const fs::path dir = test::tempDir("photobench");
    host::photo::PhotoBenchOptions opt;
    opt.conditions = {host::photo::PhotoCondition::Straight, host::photo::PhotoCondition::Tilted};
    opt.countPerCondition = 2;
    opt.seed = 5;
    opt.frame = host::photo::PhotoFrame::Small;
    opt.labels = true;
    opt.quiet = true;
    // No anti-aliasing in the photographs (the label images keep theirs): CI time, not realism.
    opt.quality = "-A";
    opt.profilesCsv = kProfiles;
    host::photo::writePhotoSet(dir.string(), opt);

    const auto manifest = test::readCsvById((dir / "manifest.csv").string());
    const auto truth = test::readCsvById((dir / "truth.csv").string());
    ASSERT_EQ(manifest.size(), 4u);
    ASSERT_EQ(truth.size(), 4u);
    const friction::PaperModel paper;
    for (const auto &[id, m] : manifest) {
        SCOPED_TRACE(id);
        ASSERT_TRUE(truth.count(id));
        const auto &t = truth.at(id);
        const cv::Mat photo = cv::imread((dir / m.at("image")).string(), cv::IMREAD_GRAYSCALE);
        ASSERT_FALSE(photo.empty());
        EXPECT_EQ(photo.cols, 640);
        EXPECT_EQ(photo.rows, 480);
        EXPECT_TRUE(fs::exists(dir / "scenes" / (id + ".pov")));
        // The renderer ran: a lit scene, not a blank frame (its noise alone is 1–3 grey levels).
        cv::Scalar mean, sd;
        cv::meanStdDev(photo, mean, sd);
        EXPECT_GT(sd[0], 4);

        // The truth is the paper's μ at the modelled ring, the radii in their physical order,
        // the scale declared exactly where the end face lies.
        const double u = num(t, "u_mm"), n = num(t, "n");
        EXPECT_NEAR(num(t, "mu"), paper.estimate({u, n, 0, 10, 15, 0}).mu, 2e-5);
        EXPECT_NEAR(num(t, "r_outer_mm") - num(t, "r_inner_mm"), u, 2e-5);
        EXPECT_LT(num(t, "r_outer_mm"), num(t, "r_bulge_mm"));
        EXPECT_NEAR(num(m, "mm_per_px"), num(t, "mm_per_px_true"), 1e-7);
        EXPECT_GT(num(t, "working_distance_mm"), 44);
        EXPECT_LT(num(t, "working_distance_mm"), 96);
        // A camera 45–95 mm away sees the barrel's widest section from farther than the end
        // face: its outline lies inside R_max but outside the contact edge.
        EXPECT_LT(num(t, "outline_mm"), num(t, "r_bulge_mm"));
        EXPECT_GT(num(t, "outline_mm"), num(t, "r_outer_mm"));

        // The label image: each zone's area through the same camera gives the projected
        // equal-area radii the truth states, and the end face's centre where it says (a
        // tilted view moves the projected disc's centroid off its centre's image by a few px).
        const cv::Mat labels = cv::imread((dir / "labels" / (id + ".png")).string(), cv::IMREAD_GRAYSCALE);
        ASSERT_FALSE(labels.empty());
        auto eqRadius = [&](int above) { return std::sqrt(cv::countNonZero(labels > above) / M_PI); };
        EXPECT_NEAR(eqRadius(212), num(t, "r_inner_px"), 0.3);
        EXPECT_NEAR(eqRadius(127), num(t, "r_outer_px"), 0.3);
        EXPECT_NEAR(eqRadius(42), num(t, "outline_px"), 0.4);
        const cv::Moments mo = cv::moments(labels > 127, true);
        const double centreTol = num(t, "tilt_deg") > 0 ? 5 : 0.3;
        EXPECT_NEAR(mo.m10 / mo.m00, num(t, "cx_px"), centreTol);
        EXPECT_NEAR(mo.m01 / mo.m00, num(t, "cy_px"), centreTol);
    }
    fs::remove_all(dir);
}

// The ring light lit in turn: each segment frame lights the barrel on its own side of the
// image (segment k at azimuth k·90° from +x towards +y, rows down), the full-ring photograph is
// the one rendered without segments, and the manifest lists the frames in order.
TEST(PhotoBench, SegmentFramesLightTheirOwnSide)
{
    if (!host::photo::povrayAvailable()) GTEST_SKIP() << "povray is not installed (apt-get install povray)";
    const fs::path with = test::tempDir("photobench-seg"), without = test::tempDir("photobench-noseg");
    host::photo::PhotoBenchOptions opt;
    opt.conditions = {host::photo::PhotoCondition::Straight};
    opt.countPerCondition = 1;
    opt.seed = 5;
    opt.frame = host::photo::PhotoFrame::Small;
    opt.quiet = true;
    opt.quality = "-A";
    opt.profilesCsv = kProfiles;
    host::photo::writePhotoSet(without.string(), opt);
    opt.segments = 4;
    host::photo::writePhotoSet(with.string(), opt);

    const auto m = test::readCsvById((with / "manifest.csv").string()).at("straight-0001");
    const auto t = test::readCsvById((with / "truth.csv").string()).at("straight-0001");
    const cv::Mat whole = cv::imread((with / m.at("image")).string(), cv::IMREAD_GRAYSCALE);
    const cv::Mat alone = cv::imread((without / m.at("image")).string(), cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(whole.empty());
    ASSERT_EQ(whole.size(), alone.size());
    EXPECT_EQ(cv::norm(whole, alone, cv::NORM_INF), 0);
    std::vector<cv::Mat> seg;
    for (const std::string &p : host::splitList(m.at("segment_images")))
        seg.push_back(cv::imread((with / p).string(), cv::IMREAD_GRAYSCALE));
    ASSERT_EQ(seg.size(), 4u);
    // The barrel band just outside the contact edge, on the image's right (+x) and left (−x).
    const double cx = num(t, "cx_px"), cy = num(t, "cy_px");
    const double ro = num(t, "r_outer_px"), outline = num(t, "outline_px");
    auto band = [&](const cv::Mat &img, double dirX, double dirY) {
        double sum = 0;
        int n = 0;
        for (double r = ro + 1; r < outline; r += 0.5)
            for (int k = -10; k <= 10; ++k) {
                const double a = std::atan2(dirY, dirX) + k * 0.02;
                sum += img.at<uint8_t>(int(cy + r * std::sin(a)), int(cx + r * std::cos(a)));
                ++n;
            }
        return sum / n;
    };
    EXPECT_GT(band(seg[0], 1, 0), band(seg[2], 1, 0) + 10);   // s0 lights the right
    EXPECT_GT(band(seg[2], -1, 0), band(seg[0], -1, 0) + 10); // s2 the left
    EXPECT_GT(band(seg[1], 0, 1), band(seg[3], 0, 1) + 10);   // s1 the bottom (rows down)
}
