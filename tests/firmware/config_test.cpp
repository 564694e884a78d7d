#include <gtest/gtest.h>

#include "firmware/config.h"

using namespace icacam::fw;

namespace {
const char *kGood = R"(# a device
[specimen]
n = 0.21
k_mpa = 400
material = "AlMgSi1"
[calibration]
mm_per_px = 0.0125
[camera]
frames = frames/
timeout_ms = 500
[display]
dir = screen
[serial]
link = tty
journal.dir = journal
)";
}

TEST(Config, GoodFileParses)
{
    Config c;
    auto issues = parseConfig(kGood, &c);
    EXPECT_TRUE(issues.empty()) << issues[0].message;
    EXPECT_DOUBLE_EQ(c.n, 0.21);
    EXPECT_EQ(c.material, "AlMgSi1");
    EXPECT_EQ(c.captureTimeoutMs, 500);
    EXPECT_EQ(c.journalDir, "journal");
}

TEST(Config, EveryMistakeIsReportedWithItsLine)
{
    Config c;
    auto issues = parseConfig("[specimen]\nn = 2\nk_mpa = abc\nbogus = 1\nno equals sign\n[camera\n"
                              "camera.format = yuv\ncamera.timeout_ms = 10.5\n",
                              &c);
    std::vector<int> lines;
    for (auto &i : issues) lines.push_back(i.line);
    for (int want : {2, 3, 4, 5, 6, 7, 8}) EXPECT_NE(std::find(lines.begin(), lines.end(), want), lines.end()) << want;
    bool mentionsRange = false, missingScale = false;
    for (auto &i : issues) {
        mentionsRange |= i.message.find("between") != std::string::npos;
        missingScale |= i.message.find("mm_per_px or calibration.file is required") != std::string::npos;
    }
    EXPECT_TRUE(mentionsRange);
    EXPECT_TRUE(missingScale);
}

TEST(Config, LiveKeysOnlyOverSerial)
{
    Config c;
    EXPECT_EQ(setConfigKey(&c, "n", "0.3", true), "");
    EXPECT_DOUBLE_EQ(c.n, 0.3);
    EXPECT_NE(setConfigKey(&c, "journal.dir", "/", true), "");
    EXPECT_NE(setConfigKey(&c, "n", "nan", true), "");
    EXPECT_NE(setConfigKey(&c, "n", "inf", true), "");
    EXPECT_NE(setConfigKey(&c, "material", "a\"b", true), "");
    std::string v;
    bool num = false;
    ASSERT_TRUE(getConfigKey(c, "n", &v, &num));
    EXPECT_TRUE(num);
    EXPECT_EQ(v, "0.3");
}

TEST(Config, FinalHeightMustBeBelowTheInitialHeight)
{
    Config c;
    auto issues =
        parseConfig("[specimen]\nn = 0.2\nh_final_mm = 16\nh0_mm = 15\n[calibration]\nmm_per_px = 0.01\n"
                    "[journal]\ndir = /tmp\n[camera]\nframes = /tmp\n[display]\ndir = /tmp\n[serial]\nlink = /tmp/x\n",
                    &c);
    bool named = false;
    for (auto &i : issues)
        named |= i.message.find("h_final_mm (16) must be below specimen.h0_mm (15)") != std::string::npos;
    EXPECT_TRUE(named);
    Config ok;
    EXPECT_EQ(setConfigKey(&ok, "h_final_mm", "7.4", true), "");
    EXPECT_EQ(specimenIssue(ok), "");
    EXPECT_DOUBLE_EQ(ok.hFinalMm, 7.4);
    EXPECT_NE(setConfigKey(&ok, "h_final_mm", "-1", true), "");
}

TEST(Config, ACalibrationFileMayStandInsteadOfMmPerPx)
{
    std::string text = kGood;
    text.replace(text.find("mm_per_px = 0.0125"), 18, "file = cam.cal");
    Config c;
    auto issues = parseConfig(text, &c);
    EXPECT_TRUE(issues.empty()) << issues[0].message;
    EXPECT_EQ(c.calibrationFile, "cam.cal");
    EXPECT_EQ(c.mmPerPx, 0.0);
    // Over serial by its short name; the final height too.
    EXPECT_EQ(setConfigKey(&c, "calibration_file", "/etc/icacam/other.cal", true), "");
    EXPECT_EQ(setConfigKey(&c, "h_final_mm", "7.4", true), "");
    EXPECT_EQ(liveKeyName("calibration.file"), "calibration_file");
    EXPECT_EQ(liveKeyName("journal.dir"), "");
    // Neither: the scale is missing.
    text.replace(text.find("file = cam.cal"), 14, "");
    issues = parseConfig(text, &c);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_NE(issues[0].message.find("calibration.mm_per_px or calibration.file is required"), std::string::npos);
}
