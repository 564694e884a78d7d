// The fixed-tone tuning override: adaptive contrast off and the told tone curve in a Raspberry
// Pi tuning file, and
// the override folder laid out as libcamera searches LIBCAMERA_IPA_CONFIG_PATH
// ("<dir>/<ipa module>/<model>.json", IPAProxy::configurationFile). The tuning texts here
// have the shape of the Raspberry Pi files (version 2: an "algorithms" list of one-key
// objects; version 1: the algorithms at the top level), not their numbers.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hal/libcamera/tuning.h"

namespace {

using namespace icacam;

const char *kVersion2 = R"({
    "version": 2.0,
    "target": "pisp",
    "algorithms": [
        { "rpi.black_level": { "black_level": 4096 } },
        { "rpi.ce_enable_lookalike": { "ce_enable": 1 } },
        {
            "rpi.contrast":
            {
                "ce_enable": 1,
                "gamma_curve": [ 0, 0, 1024, 5040, 65535, 65535 ],
                "nested": { "ce_enable": 1 }
            }
        },
        { "rpi.ccm": { "ccms": [ ] } }
    ]
})";

std::string slurp(const std::filesystem::path &p)
{
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

int count(const std::string &s, const std::string &what)
{
    int n = 0;
    for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

TEST(Tuning, AdaptiveContrastIsSwitchedOffInTheContrastBlockOnly)
{
    std::string out;
    ASSERT_TRUE(hal::withoutAdaptiveContrast(kVersion2, &out).ok());
    const size_t block = out.find("\"rpi.contrast\"");
    ASSERT_NE(block, std::string::npos);
    EXPECT_NE(out.find("\"ce_enable\": 0,", block), std::string::npos) << out;
    // The look-alike block before and the nested object inside keep their 1.
    EXPECT_EQ(count(out, "\"ce_enable\": 1"), 2) << out;
    EXPECT_EQ(out.size(), std::string(kVersion2).size());
}

TEST(Tuning, AMissingKeyMeansOnSoItIsAdded)
{
    const std::string v1 = R"({ "rpi.contrast": { "gamma_curve": [ 0, 0, 65535, 65535 ] }, "rpi.awb": { } })";
    std::string out;
    ASSERT_TRUE(hal::withoutAdaptiveContrast(v1, &out).ok());
    EXPECT_EQ(out, R"({ "rpi.contrast": { "ce_enable": 0, "gamma_curve": [ 0, 0, 65535, 65535 ] }, "rpi.awb": { } })");
}

TEST(Tuning, AFileWithoutAContrastBlockIsRefused)
{
    std::string out;
    EXPECT_EQ(hal::withoutAdaptiveContrast(R"({ "rpi.awb": { } })", &out).code, hal::Errc::BadFormat);
    EXPECT_EQ(hal::withoutAdaptiveContrast(R"({ "rpi.contrast": 3 })", &out).code, hal::Errc::BadFormat);
    EXPECT_EQ(hal::withoutAdaptiveContrast(R"({ "rpi.contrast": { "ce_enable": 1 )", &out).code, hal::Errc::BadFormat);
}

TEST(Tuning, TheToneCurveIsTheOneThePipelineIsTold)
{
    std::string out;
    ASSERT_TRUE(hal::withFixedTone(kVersion2, 1.0, &out).ok());
    EXPECT_NE(out.find("\"gamma_curve\": [ 0, 0, 65535, 65535 ],"), std::string::npos) << out;
    EXPECT_EQ(out.find("5040"), std::string::npos) << "the sensor's curve is gone";
    EXPECT_NE(out.find("\"ce_enable\": 0,"), std::string::npos);
    EXPECT_EQ(count(out, "\"ce_enable\": 1"), 2) << "other blocks keep theirs";

    // A power curve: every point on linear^(1/2.2), rising, from (0, 0) to (65535, 65535).
    ASSERT_TRUE(hal::withFixedTone(kVersion2, 2.2, &out).ok());
    const size_t open = out.find('[', out.find("\"gamma_curve\""));
    const size_t close = out.find(']', open);
    std::stringstream list(out.substr(open + 1, close - open - 1));
    std::vector<double> v;
    for (std::string item; std::getline(list, item, ',');) v.push_back(std::stod(item));
    ASSERT_EQ(v.size(), 66u);
    EXPECT_EQ(v.front(), 0);
    EXPECT_EQ(v.back(), 65535);
    for (size_t i = 2; i < v.size(); i += 2) {
        EXPECT_GT(v[i], v[i - 2]);
        EXPECT_NEAR(v[i + 1], 65535 * std::pow(v[i] / 65535, 1 / 2.2), 1.0) << "point " << i / 2;
    }
    // Where the block has no curve, one is added; an impossible exponent is refused.
    ASSERT_TRUE(hal::withFixedTone(R"({ "rpi.contrast": { "ce_enable": 1 } })", 1.0, &out).ok());
    EXPECT_EQ(out, R"({ "rpi.contrast": { "gamma_curve": [ 0, 0, 65535, 65535 ], "ce_enable": 0 } })");
    EXPECT_EQ(hal::withFixedTone(kVersion2, 0.5, &out).code, hal::Errc::Invalid);
    EXPECT_EQ(hal::withFixedTone(R"({ "rpi.contrast": { "gamma_curve": 3 } })", 1.0, &out).code, hal::Errc::BadFormat);
}

class TuningFolders : public ::testing::Test {
protected:
    void SetUp() override
    {
        char t[] = "/tmp/icacam-tuning-test-XXXXXX";
        root_ = ::mkdtemp(t);
    }
    void TearDown() override { std::filesystem::remove_all(root_); }
    void put(const std::string &rel, const std::string &text)
    {
        const std::filesystem::path p = root_ / rel;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p) << text;
    }
    std::filesystem::path root_;
};

TEST_F(TuningFolders, EveryPlatformsFileForTheSensorIsOverriddenFromTheFirstDirectoryThatHasIt)
{
    // sysconf overrides datadir for the Pi 5 module; the Pi 4 module only in datadir.
    put("etc/rpi/pisp/imx708.json", R"({ "rpi.contrast": { "ce_enable": 1, "from": "etc" } })");
    put("share/rpi/pisp/imx708.json", R"({ "rpi.contrast": { "ce_enable": 1, "from": "share" } })");
    put("share/rpi/vc4/imx708.json", R"({ "rpi.contrast": { "ce_enable": 1, "from": "share-vc4" } })");
    put("share/rpi/vc4/imx477.json", R"({ "rpi.contrast": { "ce_enable": 1 } })");
    const std::string etc = (root_ / "etc").string(), share = (root_ / "share").string();
    const std::string_view dirs[] = {etc, share};
    const std::string out = (root_ / "override").string();
    hal::TuningOverride o;
    ASSERT_TRUE(hal::writeFixedToneTuning(dirs, "imx708", out, 1.0, &o).ok());
    EXPECT_EQ(o.files, 2);
    EXPECT_EQ(o.source, etc + "/rpi/pisp/imx708.json");
    EXPECT_EQ(slurp(out + "/rpi/pisp/imx708.json"),
              R"({ "rpi.contrast": { "gamma_curve": [ 0, 0, 65535, 65535 ], "ce_enable": 0, "from": "etc" } })");
    EXPECT_EQ(slurp(out + "/rpi/vc4/imx708.json"),
              R"({ "rpi.contrast": { "gamma_curve": [ 0, 0, 65535, 65535 ], "ce_enable": 0, "from": "share-vc4" } })");
    EXPECT_FALSE(std::filesystem::exists(out + "/rpi/vc4/imx477.json")); // only the sensor in use
}

TEST_F(TuningFolders, AnUnknownSensorWritesNothing)
{
    const std::string share = (root_ / "share").string();
    const std::string_view dirs[] = {share};
    hal::TuningOverride o;
    ASSERT_TRUE(hal::writeFixedToneTuning(dirs, "imx999", (root_ / "override").string(), 1.0, &o).ok());
    EXPECT_EQ(o.files, 0);
    EXPECT_FALSE(std::filesystem::exists(root_ / "override"));
}

TEST_F(TuningFolders, ABrokenSystemFileIsAnErrorThatNamesIt)
{
    put("share/raspberrypi/ov5647.json", R"({ "rpi.awb": { } })");
    const std::string share = (root_ / "share").string();
    const std::string_view dirs[] = {share};
    hal::TuningOverride o;
    const hal::Error e = hal::writeFixedToneTuning(dirs, "ov5647", (root_ / "override").string(), 1.0, &o);
    EXPECT_EQ(e.code, hal::Errc::BadFormat);
    EXPECT_NE(e.message.find("raspberrypi/ov5647.json"), std::string::npos) << e.message;
}

} // namespace
