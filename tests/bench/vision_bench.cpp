// Per-frame cost of the vision pipeline and of the plain OpenCV pipeline on the same frame,
// side by side (report the ratio, never assert on wall time).
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "friction/paper_model.h"
#include "host_tools/end_face_renderer.h"
#include "reading/instrument.h"
#include "tests/bench/opencv_baseline.h"

namespace {
const cv::Mat &frame()
{
    static const cv::Mat img = [] {
        icacam::host::EndFaceScene s = icacam::host::nominalScene(0.7);
        s.stains = 3;
        s.turningMarks = 3;
        return icacam::host::renderEndFace(s);
    }();
    return img;
}

void BM_VisionPipeline(benchmark::State &state)
{
    const cv::Mat &img = frame();
    icacam::reading::Instrument a;
    icacam::friction::PaperModel model;
    a.configure(img.cols, img.rows, model);
    const icacam::vision::LumaView v{img.data, img.cols, img.rows, int(img.step[0]), 1};
    const icacam::reading::SpecimenSpec spec{0.25, 500, 10, 15, 0.0135};
    for (auto _ : state) benchmark::DoNotOptimize(a.read(v, spec).mu);
}
BENCHMARK(BM_VisionPipeline)->Unit(benchmark::kMicrosecond);

void BM_OpenCvBaseline(benchmark::State &state)
{
    cv::setNumThreads(1);
    const cv::Mat &img = frame();
    for (auto _ : state) benchmark::DoNotOptimize(icacam::bench::opencvBaselineRadius(img));
}
BENCHMARK(BM_OpenCvBaseline)->Unit(benchmark::kMicrosecond);
} // namespace

BENCHMARK_MAIN();
