// What a reading says in words: each finding with what to supply, the height the silhouette
// says and μ at the nominal conditions, and the advice.
#include <gtest/gtest.h>

#include <string>

#include "reading/reading_record.h"

namespace icacam::reading {
namespace {

Reading warned(uint32_t flags)
{
    Reading m;
    m.error = ErrorCode::None;
    m.status = Status::Warn;
    m.flags = flags;
    m.mu = 0.1876;
    m.reduction = 0.5041;
    m.nominalMu = 0.1998;
    return m;
}

std::string message(const Reading &m, size_t size = 768)
{
    char buf[768];
    readingMessage(m, buf, size);
    return buf;
}

// A height other than half moves μ by the height; where the reading also took part of the
// silhouette's discrepancy as the scale's, μ moved by that too, and the message says by how
// much, so that "50.4 %" beside μ 0.012 from μ at 50 % is not a riddle.
TEST(ReadingMessage, AnotherHeightNamesTheScaleTheReadingApplied)
{
    Reading m = warned(kFlagReductionNotNominal);
    const std::string height = message(m);
    EXPECT_NE(height.find("(50.4 %; mu 0.1998 at 50 %)"), std::string::npos) << height;
    EXPECT_EQ(height.find("scale x"), std::string::npos) << height;
    m.scaleFactor = 0.97878;
    const std::string both = message(m);
    EXPECT_NE(both.find("(50.4 %, scale x0.979; mu 0.1998 at 50 % and the declared scale)"), std::string::npos) << both;
}

// Every finding in a warned reading is named with what to do; one that does not fit the
// buffer is left out whole, never cut mid-word.
TEST(ReadingMessage, FindingsAreJoinedAndLeftOutWhole)
{
    const Reading m = warned(kFlagBlurred | kFlagNoSilhouette);
    const std::string all = message(m);
    EXPECT_NE(all.find("refocus"), std::string::npos) << all;
    EXPECT_NE(all.find("; no barrel silhouette"), std::string::npos) << all;
    const std::string first = message(m, all.find("; no barrel") + 4);
    EXPECT_EQ(first, all.substr(0, all.find("; no barrel")));
}

// Without a silhouette and with a declared final height only the scale went unchecked: the
// words ask for the scale, not for the height the manifest already gave.
TEST(ReadingMessage, NoSilhouetteWithADeclaredHeightAsksForTheScaleOnly)
{
    Reading m = warned(kFlagNoSilhouette);
    EXPECT_NE(message(m).find("declare h_final_mm"), std::string::npos) << message(m);
    m.advice.heightDeclared = true;
    const std::string scale = message(m);
    EXPECT_EQ(scale.find("h_final_mm"), std::string::npos) << scale;
    EXPECT_NE(scale.find("the declared scale is unchecked"), std::string::npos) << scale;
    EXPECT_NE(scale.find("mm_per_px on the end-face plane"), std::string::npos) << scale;
}

// An undecided contact edge says what the image showed: the profile's band (the flag's own
// words), a face holding an edge of its own, or a contact edge with no outline beyond it.
TEST(ReadingMessage, AnUndecidedContactEdgeSaysWhatTheImageShowed)
{
    Reading m = warned(kFlagContactEdgeUndecided);
    m.geometry.imageFlags = vision::kImageContactEdgeUndecided;
    EXPECT_NE(message(m).find("does not tell which edge ends the flat face"), std::string::npos) << message(m);
    m.geometry.imageFlags |= vision::kImageUndecidedNoStepBeyond;
    const std::string noStep = message(m);
    EXPECT_NE(noStep.find("no outline beyond it"), std::string::npos) << noStep;
    EXPECT_EQ(noStep.find("does not tell"), std::string::npos) << noStep;
    m.geometry.imageFlags |= vision::kImageUndecidedFaceHoldsEdge;
    const std::string face = message(m);
    EXPECT_NE(face.find("the face read shows an edge of its own"), std::string::npos) << face;
    EXPECT_EQ(face.find("no outline beyond it"), std::string::npos) << face;
}

TEST(ReadingMessage, OkSaysNothingAndTheAdviceSaysWhatToDeclare)
{
    Reading m = warned(0);
    m.status = Status::Ok;
    EXPECT_EQ(message(m), "");
    Advice a;
    a.input = AdviceInput::HFinal;
    a.uNow = 0.0160, a.uThen = 0.0060;
    a.reductionUnchecked = true;
    char buf[160];
    adviceText(a, buf, sizeof buf);
    EXPECT_STREQ(buf, "h_final_mm: U 0.0160 \xE2\x86\x92 0.0060 (height unchecked: U covers 45-55 %)");
}

} // namespace
} // namespace icacam::reading
