// Zero heap allocations per measurement after configure(): operator new is counted.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "friction/paper_model.h"
#include "host_tools/end_face_renderer.h"
#include "host_tools/image_file.h"
#include "reading/instrument.h"
#include "tests/host_tools/test_support.h"
#include "tests/support/allocation_counter.h"
#include "tests/vision/oblique_end_face.h"
#include "vision/end_face_analyzer.h"

using namespace icacam;

TEST(Allocation, NoneDuringMeasurement)
{
    host::EndFaceScene s = host::nominalScene(0.7);
    s.stains = 3;
    const cv::Mat img = host::renderEndFace(s);
    reading::Instrument analyzer;
    friction::PaperModel model;
    ASSERT_EQ(analyzer.configure(img.cols, img.rows, model), vision::ErrorCode::None);
    EXPECT_LE(analyzer.workingBytes(), size_t(1) << 20) << "working memory over 1 MiB";
    const vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
    const reading::SpecimenSpec spec{0.25, 500, 10, 15, s.mmPerPx};
    const long before = icacam::test::allocationCount();
    reading::Reading m;
    for (int i = 0; i < 3; ++i) m = analyzer.read(v, spec);
    const long after = icacam::test::allocationCount();
    ASSERT_TRUE(m.hasValue()) << vision::errorMessage(m.error);
    EXPECT_EQ(after - before, 0) << "heap allocations during measure()";
    // An error path allocates nothing either.
    const vision::LumaView blank{img.data, 16, 16, int(img.step[0]), 1};
    const long b2 = icacam::test::allocationCount();
    m = analyzer.read(blank, spec);
    EXPECT_EQ(icacam::test::allocationCount() - b2, 0);
}

// A tilted camera's view, read only on the second search about the end face's own centre
// (tests/vision/oblique_view_test.cpp): that search allocates nothing either.
TEST(Allocation, NoneReadingAnObliqueViewAgain)
{
    const test::ObliqueEndFace f;
    const auto px = f.draw();
    vision::EndFaceAnalyzer analyzer;
    ASSERT_EQ(analyzer.configure(f.width, f.height), vision::ErrorCode::None);
    const long before = icacam::test::allocationCount();
    const vision::EndFaceGeometry g = analyzer.measure(f.view(px), {10, 5.0 / f.r0});
    const long after = icacam::test::allocationCount();
    ASSERT_EQ(g.error, vision::ErrorCode::None) << vision::errorMessage(g.error);
    EXPECT_EQ(after - before, 0) << "heap allocations during measure()";
}

namespace {
// One unit photograph read as the instrument reads it, with and without a declared tone curve:
// a value (or, for lowres-s3-0015, whose face and ring are one shade and whose original face
// shows no edge, tests/data/photo/README.md, that error), and no heap allocation either way.
void expectReadWithoutAllocating(const std::string &dir, const std::string &id,
                                 const std::map<std::string, std::string> &m)
{
    friction::PaperModel model;
    host::LumaImage image;
    ASSERT_EQ(host::loadLuma(dir + m.at("image"), &image), "") << id;
    const cv::Mat &img = image.luma;
    reading::Instrument instrument;
    ASSERT_EQ(instrument.configure(img.cols, img.rows, model), vision::ErrorCode::None) << id;
    const vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
    reading::SpecimenSpec spec{std::stod(m.at("n")), std::stod(m.at("k_mpa")), std::stod(m.at("d0_mm")),
                               std::stod(m.at("h0_mm")), std::stod(m.at("mm_per_px"))};
    for (const double gamma : {1.0, 2.2}) {
        spec.toneGamma = gamma;
        const long before = icacam::test::allocationCount();
        const reading::Reading r = instrument.read(v, spec);
        const long after = icacam::test::allocationCount();
        if (id == "lowres-s3-0015")
            EXPECT_EQ(r.error, vision::ErrorCode::InnerEdgeNotFound) << id;
        else
            EXPECT_TRUE(r.hasValue()) << id << ": " << vision::errorMessage(r.error);
        EXPECT_EQ(after - before, 0) << id << " (tone_gamma " << gamma << "): heap allocations during read()";
    }
}
} // namespace

// Every rendered photograph of the unit set (tests/data/photo: the ramps, the folds, the step
// back beyond a drop, the narrow barrel bands, the tilted view; full/ and large/: the grooved
// ring whose steps back are tried in turn): none of their paths allocates.
TEST(Allocation, NoneReadingAnyUnitPhotograph)
{
    for (const std::string folder : {"", "full/", "large/"}) {
        const std::string dir = std::string(ICACAM_SOURCE_DIR) + "/tests/data/photo/" + folder;
        const auto manifest = test::readCsvById(dir + "manifest.csv");
        ASSERT_GE(manifest.size(), folder.empty() ? 10u : 1u);
        for (const auto &[id, m] : manifest) expectReadWithoutAllocating(dir, id, m);
    }
}

// The same with the ring light lit in turn: four segment frames beside the photograph.
TEST(Allocation, NoneReadingWithSegmentFrames)
{
    const std::string dir = std::string(ICACAM_SOURCE_DIR) + "/tests/data/photo/segments/";
    const auto manifest = test::readCsvById(dir + "manifest.csv");
    ASSERT_GE(manifest.size(), 1u);
    friction::PaperModel model;
    for (const auto &[id, m] : manifest) {
        host::LumaImage image, segment[4];
        ASSERT_EQ(host::loadLuma(dir + m.at("image"), &image), "") << id;
        vision::LitInTurn lit;
        const std::vector<std::string> paths = host::splitList(m.at("segment_images"));
        ASSERT_EQ(paths.size(), 4u) << id;
        for (size_t k = 0; k < 4; ++k) {
            ASSERT_EQ(host::loadLuma(dir + paths[k], &segment[k]), "") << id;
            const cv::Mat &s = segment[k].luma;
            lit.segment[k] = {s.data, s.cols, s.rows, int(s.step[0]), 1};
        }
        lit.count = 4;
        const cv::Mat &img = image.luma;
        reading::Instrument instrument;
        ASSERT_EQ(instrument.configure(img.cols, img.rows, model), vision::ErrorCode::None) << id;
        const vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
        const reading::SpecimenSpec spec{std::stod(m.at("n")), std::stod(m.at("k_mpa")), std::stod(m.at("d0_mm")),
                                         std::stod(m.at("h0_mm")), std::stod(m.at("mm_per_px"))};
        const long before = icacam::test::allocationCount();
        const reading::Reading r = instrument.read(v, spec, &lit);
        const long after = icacam::test::allocationCount();
        EXPECT_TRUE(r.hasValue()) << id << ": " << vision::errorMessage(r.error);
        EXPECT_NE(r.geometry.imageFlags & (vision::kImageContactEdgeByTilt | vision::kImageTiltConfirms), 0u) << id;
        EXPECT_EQ(after - before, 0) << id << ": heap allocations during read() with segment frames";
    }
}
