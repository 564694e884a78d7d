// The coarse specimen locator on drawn end faces: the Hough peak must land on the drawn
// centre within a decimated cell, the specimen's concentric edges must outvote a lone circle
// in the fixture, and a frame with nothing to find must say so.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tests/vision/synthetic_end_face.h"
#include "vision/specimen_locator.h"

using namespace icacam;
using namespace icacam::vision;

namespace {

// The analyzer's acceptance of a peak: at least 20 votes, and 12 times the mean 3×3 sum of the
// accumulator (end_face_analyzer.cpp).
bool acceptedAsSpecimen(const CentreEstimate &e)
{
    return e.found && e.votes >= 20 && e.votes * 100 >= 12 * e.background;
}

// One decimated cell in full-frame pixels: the locator's resolution.
double cellPx(int width, int height)
{
    return std::ceil(std::max(width, height) / double(SpecimenLocator::kMaxCells));
}

// Searched as the analyzer searches for a specimen of initial radius r0: 0.8 … 1.8 r0.
CentreEstimate locate(const LumaView &v, double r0)
{
    std::vector<uint8_t> work(SpecimenLocator::kWorkBytes);
    SpecimenLocator locator(work.data());
    return locator.locate(v, 0.8 * r0, 1.8 * r0);
}

} // namespace

TEST(SpecimenLocator, PeakIsTheDrawnCentreWithinACell)
{
    // Several sizes, centres and frames, so the decimation grid meets the centre at different
    // phases (4, 7 and 10 px cells).
    struct Case {
        double r0;
        int w, h;
        double cx, cy;
    };
    for (const Case c : {Case{80, 384, 288, 170.8, 140.2}, Case{80, 640, 480, 402.5, 211.7},
                         Case{120, 640, 480, 250.1, 260.9}, Case{250, 900, 880, 451.3, 438.6}}) {
        test::SyntheticEndFace face;
        face.scaleTo(c.r0);
        face.width = c.w;
        face.height = c.h;
        face.cx = c.cx;
        face.cy = c.cy;
        const auto px = face.draw();
        const CentreEstimate e = locate(face.view(px), c.r0);
        SCOPED_TRACE(testing::Message() << "R0 " << c.r0 << " in " << c.w << "x" << c.h << " at " << c.cx << ","
                                        << c.cy);
        ASSERT_TRUE(e.found);
        EXPECT_TRUE(acceptedAsSpecimen(e)) << e.votes << " votes over a floor of " << e.background / 100.0;
        const double cell = cellPx(c.w, c.h);
        EXPECT_LE(std::fabs(e.x - c.cx), cell) << "x " << e.x;
        EXPECT_LE(std::fabs(e.y - c.cy), cell) << "y " << e.y;
    }
}

TEST(SpecimenLocator, ReadsAYuyvFrameThroughItsPixelStep)
{
    // The same picture as the luma of a YUYV frame (every other byte chroma at 128): the
    // locator must step over the chroma and find the same centre.
    test::SyntheticEndFace grey;
    const auto gpx = grey.draw();
    test::SyntheticEndFace yuyv = grey;
    yuyv.pixelStep = 2;
    const auto ypx = yuyv.draw();
    const CentreEstimate a = locate(grey.view(gpx), grey.r0), b = locate(yuyv.view(ypx), yuyv.r0);
    ASSERT_TRUE(a.found && b.found);
    EXPECT_DOUBLE_EQ(a.x, b.x);
    EXPECT_DOUBLE_EQ(a.y, b.y);
    EXPECT_EQ(a.votes, b.votes);
}

TEST(SpecimenLocator, TheSpecimenOutvotesALoneCircleInTheFixture)
{
    // A circle in the fixture beside the specimen, as the host renderer draws one: a bright
    // line (25 grey levels, 2 px wide) of 0.7 R_max. Its votes pile up on its own centre, but
    // the specimen's concentric edges all vote on one cell and win.
    test::SyntheticEndFace face;
    face.scaleTo(120);
    face.width = 800;
    face.height = 480;
    face.cx = 230.4;
    face.cy = 241.1;
    auto px = face.draw();
    const double dx0 = 600.0, dy0 = 200.0, dr = 0.7 * face.rMax;
    for (int y = 0; y < face.height; ++y)
        for (int x = 0; x < face.width; ++x) {
            const double d = std::hypot(x - dx0, y - dy0) - dr;
            uint8_t &p = px[size_t(y) * face.width + x];
            p = uint8_t(std::min(255L, p + std::lround(25 * std::exp(-0.5 * d * d / 4.0))));
        }
    const CentreEstimate e = locate(face.view(px), face.r0);
    ASSERT_TRUE(e.found);
    const double cell = cellPx(face.width, face.height);
    EXPECT_LE(std::fabs(e.x - face.cx), cell) << "x " << e.x << " (the lone circle is at " << dx0 << ")";
    EXPECT_LE(std::fabs(e.y - face.cy), cell) << "y " << e.y;
}

TEST(SpecimenLocator, NothingToFindIsNotFoundOrNotASpecimen)
{
    // A flat frame has no voters at all.
    std::vector<uint8_t> flat(size_t(320) * 240, 90);
    EXPECT_FALSE(locate(LumaView{flat.data(), 320, 240, 320, 1}, 80).found);
    // A textured frame spreads its votes: whatever peak it has, the analyzer's acceptance
    // rejects it.
    std::mt19937 rng(7);
    std::vector<uint8_t> noise(size_t(320) * 240);
    for (auto &p : noise) p = uint8_t(rng() & 255);
    const CentreEstimate n = locate(LumaView{noise.data(), 320, 240, 320, 1}, 80);
    EXPECT_FALSE(acceptedAsSpecimen(n)) << n.votes << " votes over a floor of " << n.background / 100.0;
    // A frame smaller than 8 decimated cells each way is not searched.
    std::vector<uint8_t> tiny(size_t(7) * 7, 90);
    EXPECT_FALSE(locate(LumaView{tiny.data(), 7, 7, 7, 1}, 80).found);
}
