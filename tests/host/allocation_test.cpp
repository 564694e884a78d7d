// Zero heap allocations per measurement after configure(): operator new is counted.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "end_face_renderer.h"
#include "vision/end_face_analyzer.h"
#include "vision/model/paper_model.h"

static std::atomic<long> gAllocations{0};

void *operator new(std::size_t n)
{
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void *operator new[](std::size_t n) { return operator new(n); }
void *operator new(std::size_t n, const std::nothrow_t &) noexcept
{
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(n ? n : 1);
}
void *operator new[](std::size_t n, const std::nothrow_t &t) noexcept { return operator new(n, t); }
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }

using namespace icacam;

TEST(Allocation, NoneDuringMeasurement)
{
    host::EndFaceScene s = host::nominalScene(0.7);
    s.stains = 3;
    const cv::Mat img = host::renderEndFace(s);
    vision::EndFaceAnalyzer analyzer;
    ASSERT_EQ(analyzer.configure(img.cols, img.rows), vision::ErrorCode::None);
    EXPECT_LE(analyzer.workingBytes(), size_t(1) << 20) << "working memory over 1 MiB";
    vision::PaperModel model;
    const vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
    const vision::SpecimenSpec spec{0.25, 500, 10, 15, s.mmPerPx};
    const long before = gAllocations.load();
    vision::Measurement m;
    for (int i = 0; i < 3; ++i) m = analyzer.measure(v, spec, model);
    const long after = gAllocations.load();
    ASSERT_TRUE(m.hasValue()) << vision::errorMessage(m.error);
    EXPECT_EQ(after - before, 0) << "heap allocations during measure()";
    // An error path allocates nothing either.
    const vision::LumaView blank{img.data, 16, 16, int(img.step[0]), 1};
    const long b2 = gAllocations.load();
    m = analyzer.measure(blank, spec, model);
    EXPECT_EQ(gAllocations.load() - b2, 0);
}
