// Zero heap allocations per measurement after configure(): operator new is counted.
#include <gtest/gtest.h>

#include "friction/paper_model.h"
#include "host_tools/end_face_renderer.h"
#include "tests/support/allocation_counter.h"
#include "vision/end_face_analyzer.h"

using namespace icacam;

TEST(Allocation, NoneDuringMeasurement)
{
    host::EndFaceScene s = host::nominalScene(0.7);
    s.stains = 3;
    const cv::Mat img = host::renderEndFace(s);
    vision::EndFaceAnalyzer analyzer;
    ASSERT_EQ(analyzer.configure(img.cols, img.rows), vision::ErrorCode::None);
    EXPECT_LE(analyzer.workingBytes(), size_t(1) << 20) << "working memory over 1 MiB";
    friction::PaperModel model;
    const vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
    const vision::SpecimenSpec spec{0.25, 500, 10, 15, s.mmPerPx};
    const long before = icacam::test::allocationCount();
    vision::Measurement m;
    for (int i = 0; i < 3; ++i) m = analyzer.measure(v, spec, model);
    const long after = icacam::test::allocationCount();
    ASSERT_TRUE(m.hasValue()) << vision::errorMessage(m.error);
    EXPECT_EQ(after - before, 0) << "heap allocations during measure()";
    // An error path allocates nothing either.
    const vision::LumaView blank{img.data, 16, 16, int(img.step[0]), 1};
    const long b2 = icacam::test::allocationCount();
    m = analyzer.measure(blank, spec, model);
    EXPECT_EQ(icacam::test::allocationCount() - b2, 0);
}
