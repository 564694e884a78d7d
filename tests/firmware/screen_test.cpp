#include <gtest/gtest.h>

#include <set>

#include "firmware/font5x7.h"
#include "firmware/screen.h"

using namespace icacam;

TEST(Font, GlyphsAreDistinctSoTheScreenCanBeReadBack)
{
    std::set<std::vector<uint8_t>> seen;
    for (int g = 0; g < fw::glyphCount(); ++g) {
        const uint8_t *c = fw::glyphColumns(g);
        EXPECT_TRUE(seen.insert({c, c + 5}).second) << "glyph " << g;
    }
}

TEST(Font, TextRoundTrips)
{
    hal::MonoBitmap bmp;
    const std::string text = "\xCE\xBC=0.182\xC2\xB1"
                             "0.004 \xCF\x83 ~{}";
    fw::drawText(&bmp, 0, 3, text);
    EXPECT_EQ(fw::readRow(bmp, 3), text);
    EXPECT_EQ(fw::readRow(bmp, 2), "");
    fw::drawText(&bmp, 0, 7, std::string(40, 'W')); // clipped at 21 columns
    EXPECT_EQ(fw::readRow(bmp, 7), std::string(21, 'W'));
}

TEST(Screen, ErrorsAreShownInWords)
{
    hal::MonoBitmap bmp;
    reading::Reading m;
    m.status = reading::Status::Error;
    m.error = vision::ErrorCode::InnerEdgeNotFound;
    fw::drawResult(&bmp, 12, m, "");
    EXPECT_EQ(fw::readRow(bmp, 0), "#12 error");
    EXPECT_EQ(fw::readRow(bmp, 2), "inner edge not found");
    m.status = reading::Status::Warn;
    m.error = vision::ErrorCode::None;
    m.mu = 0.182;
    m.muSigma = 0.004;
    m.flags = reading::kFlagNOutOfRange;
    m.toleranceMu = 0.0091;
    m.decision = reading::Decision::Within;
    fw::drawResult(&bmp, 13, m, "");
    EXPECT_EQ(fw::readRow(bmp, 2), "\xCE\xBC=0.182\xC2\xB1"
                                   "0.008 U");
    EXPECT_EQ(fw::readRow(bmp, 4), "U within tol 0.009");
    EXPECT_EQ(fw::readRow(bmp, 5), "n outside 0.05-0.5");
    EXPECT_EQ(fw::readRow(bmp, 6), "U: edges'") << "the advice follows the findings";
    // An ok reading: the decision and the advice, with the value to declare.
    m.status = reading::Status::Ok;
    m.flags = 0;
    m.decision = reading::Decision::Beyond;
    m.advice = {reading::AdviceInput::HFinal, 0, 0.016, 0.006, false};
    fw::drawResult(&bmp, 15, m, "");
    EXPECT_EQ(fw::readRow(bmp, 0), "#15 ok");
    EXPECT_EQ(fw::readRow(bmp, 4), "U beyond tol 0.009");
    EXPECT_EQ(fw::readRow(bmp, 5), "h_final_mm U->0.0060");
    // Nothing in the image checked the height: U covers 45-55 %, and the line says so.
    m.advice.reductionUnchecked = true;
    fw::drawResult(&bmp, 16, m, "");
    EXPECT_EQ(fw::readRow(bmp, 5), "h unchecked U->0.0060");
    fw::drawProblem(&bmp, "#14 error", "camera timeout: no frame within 2000 ms");
    EXPECT_EQ(fw::readRow(bmp, 2), "camera timeout: no");
    EXPECT_EQ(fw::readRow(bmp, 3), "frame within 2000 ms");
}
