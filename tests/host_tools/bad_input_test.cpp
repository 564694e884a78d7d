// Every kind of bad input gets status=error with a message, and the batch goes on.
#include <gtest/gtest.h>

#include <random>

#include <opencv2/imgcodecs.hpp>

#include "host_tools/end_face_renderer.h"
#include "host_tools/measure_command.h"
#include "tests/host_tools/test_support.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {
void writeBytes(const fs::path &p, const std::vector<uint8_t> &b)
{
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char *>(b.data()), std::streamsize(b.size()));
}
} // namespace

TEST(BadInput, EachGetsAnErrorAndTheBatchGoesOn)
{
    const fs::path dir = test::tempDir("bad");
    // One good image, rendered by our own renderer.
    const host::EndFaceScene s = host::nominalScene(0.6);
    const cv::Mat good = host::renderEndFace(s);
    std::vector<uint8_t> png;
    cv::imencode(".png", good, png);
    writeBytes(dir / "good.png", png);
    writeBytes(dir / "empty.png", {});
    writeBytes(dir / "truncated.png", std::vector<uint8_t>(png.begin(), png.begin() + long(png.size() / 2)));
    std::vector<uint8_t> jpg;
    cv::imencode(".jpg", good, jpg);
    writeBytes(dir / "truncated.jpg", std::vector<uint8_t>(jpg.begin(), jpg.begin() + long(jpg.size() * 2 / 3)));
    std::vector<uint8_t> junk(5000);
    std::mt19937 rng(1);
    for (auto &b : junk) b = uint8_t(rng());
    writeBytes(dir / "corrupt.png", junk);
    std::vector<uint8_t> corruptPng = png;
    for (size_t i = 100; i < corruptPng.size() - 100; i += 7) corruptPng[i] ^= 0x5a;
    writeBytes(dir / "corrupt-body.png", corruptPng);
    writeBytes(dir / "text.png", std::vector<uint8_t>{'h', 'e', 'l', 'l', 'o'});
    auto save = [&](const char *name, const cv::Mat &m) { cv::imwrite((dir / name).string(), m); };
    save("tiny.png", cv::Mat(8, 8, CV_8UC1, cv::Scalar(100)));
    save("black.png", cv::Mat(1088, 1456, CV_8UC1, cv::Scalar(0)));
    save("white.png", cv::Mat(1088, 1456, CV_8UC1, cv::Scalar(255)));
    cv::Mat noise(1088, 1456, CV_8UC1);
    cv::randu(noise, 0, 255);
    save("noise.png", noise);
    cv::Mat saturated = good.clone();
    saturated.convertTo(saturated, CV_8U, 4.0, 0);
    save("saturated.png", saturated);

    std::ofstream man(dir / "manifest.csv");
    man << "id,image,n,mm_per_px\n"
           "good,good.png,0.25,0.0135\n"
           "missing,nope.png,0.25,0.0135\n"
           "empty,empty.png,0.25,0.0135\n"
           "truncated,truncated.png,0.25,0.0135\n"
           "truncated-jpg,truncated.jpg,0.25,0.0135\n"
           "corrupt,corrupt.png,0.25,0.0135\n"
           "corrupt-body,corrupt-body.png,0.25,0.0135\n"
           "text,text.png,0.25,0.0135\n"
           "tiny,tiny.png,0.25,0.0135\n"
           "black,black.png,0.25,0.0135\n"
           "white,white.png,0.25,0.0135\n"
           "noise,noise.png,0.25,0.0135\n"
           "saturated,saturated.png,0.25,0.0135\n"
           "bad-n,good.png,abc,0.0135\n"
           "bad-scale,good.png,0.25,-1\n"
           "short-row,good.png\n"
           "directory,.,0.25,0.0135\n"
           "good-again,good.png,0.25,0.0135\n";
    man.close();
    const std::string out = (dir / "out.csv").string();
    ASSERT_EQ(host::measureCommand({"--manifest", (dir / "manifest.csv").string(), "--out", out}), 0);
    auto rows = test::readCsvById(out);
    ASSERT_EQ(rows.size(), 18u);
    for (const char *id : {"good", "good-again"}) {
        EXPECT_NE(rows[id]["status"], "error") << id << ": " << rows[id]["message"];
        EXPECT_FALSE(rows[id]["mu"].empty());
    }
    for (auto &[id, r] : rows) {
        if (id == "good" || id == "good-again") continue;
        EXPECT_EQ(r["status"], "error") << id;
        EXPECT_FALSE(r["message"].empty()) << id;
        EXPECT_TRUE(r["mu"].empty()) << id << " must not carry a value";
    }
    EXPECT_NE(rows["truncated"]["message"].find("truncated"), std::string::npos);
    EXPECT_NE(rows["missing"]["message"].find("not found"), std::string::npos);
    EXPECT_NE(rows["empty"]["message"].find("empty"), std::string::npos);
    EXPECT_NE(rows["bad-n"]["message"].find("n"), std::string::npos);
    EXPECT_NE(rows["directory"]["message"].find("not a file"), std::string::npos);
    fs::remove_all(dir);
}

// Segment frames (the ring light lit in turn): too few, a path missing, a file missing, another
// size, not an image: each its error, and the batch goes on.
TEST(BadInput, SegmentFramesEachGetAnError)
{
    const fs::path dir = test::tempDir("badseg");
    std::vector<uint8_t> png;
    cv::imencode(".png", host::renderEndFace(host::nominalScene(0.6)), png);
    writeBytes(dir / "good.png", png);
    cv::imwrite((dir / "small.png").string(), cv::Mat(64, 64, CV_8UC1, cv::Scalar(90)));
    writeBytes(dir / "text.png", std::vector<uint8_t>{'h', 'i'});
    std::ofstream man(dir / "manifest.csv");
    man << "id,image,n,mm_per_px,segment_images,segment0_deg\n"
           "two,good.png,0.25,0.0135,good.png;good.png,\n"
           "nine,good.png,0.25,0.0135,good.png;good.png;good.png;good.png;good.png;good.png;good.png;good.png;"
           "good.png,\n"
           "no-path,good.png,0.25,0.0135,good.png;;good.png,\n"
           "missing,good.png,0.25,0.0135,good.png;good.png;nope.png,\n"
           "directory,good.png,0.25,0.0135,good.png;good.png;.,\n"
           "other-size,good.png,0.25,0.0135,good.png;good.png;small.png,\n"
           "text,good.png,0.25,0.0135,good.png;good.png;text.png,\n"
           "angle,good.png,0.25,0.0135,good.png;good.png;good.png,ninety\n"
           "none,good.png,0.25,0.0135,,\n";
    man.close();
    const std::string out = (dir / "out.csv").string();
    ASSERT_EQ(host::measureCommand({"--manifest", (dir / "manifest.csv").string(), "--out", out}), 0);
    auto rows = test::readCsvById(out);
    ASSERT_EQ(rows.size(), 9u);
    const std::pair<const char *, const char *> expected[] = {{"two", "3-8"},
                                                              {"nine", "3-8"},
                                                              {"no-path", "no path"},
                                                              {"missing", "not found"},
                                                              {"directory", "not a file"},
                                                              {"other-size", "64x64"},
                                                              {"text", "segment 2"},
                                                              {"angle", "segment0_deg"}};
    for (const auto &[id, words] : expected) {
        EXPECT_EQ(rows[id]["status"], "error") << id;
        EXPECT_NE(rows[id]["message"].find(words), std::string::npos) << id << ": " << rows[id]["message"];
    }
    EXPECT_NE(rows["none"]["status"], "error") << "an empty column is no segment frames: " << rows["none"]["message"];
    fs::remove_all(dir);
}

TEST(BadInput, SlendernessOutsideTheModelIsFlaggedNeverSilent)
{
    const fs::path dir = test::tempDir("aspect");
    std::vector<uint8_t> png;
    cv::imencode(".png", host::renderEndFace(host::nominalScene(0.6)), png);
    writeBytes(dir / "good.png", png);
    std::ofstream man(dir / "manifest.csv");
    man << "id,image,n,mm_per_px,d0_mm,h0_mm\n"
           "paper,good.png,0.25,0.0135,10,15\n"
           "squat,good.png,0.25,0.0135,10,10\n"
           "slender,good.png,0.25,0.0135,10,20\n"
           "too-slender,good.png,0.25,0.0135,10,25\n";
    man.close();
    auto run = [&](const char *model) {
        const std::string out = (dir / (std::string(model) + ".csv")).string();
        EXPECT_EQ(host::measureCommand({"--manifest", (dir / "manifest.csv").string(), "--out", out, "--model", model}),
                  0);
        return test::readCsvById(out);
    };
    auto flagged = [](std::map<std::string, std::string> &r) {
        return r["flags"].find("aspect_outside_model") != std::string::npos;
    };
    // The paper's fit knows 10 x 15 only: every other slenderness says so.
    auto paper = run("paper");
    EXPECT_FALSE(flagged(paper["paper"]));
    for (const char *id : {"squat", "slender", "too-slender"}) {
        EXPECT_TRUE(flagged(paper[id])) << id;
        EXPECT_EQ(paper[id]["status"], "warn") << id;
    }
    // The default model carries 1.0-2.0 to 1.5 with the FE ratio (a squat specimen's ring is
    // narrower for the same friction, so the same ring means more friction) and flags beyond.
    auto carried = run("paper_reduction");
    EXPECT_FALSE(flagged(carried["paper"]));
    EXPECT_FALSE(flagged(carried["squat"]));
    EXPECT_FALSE(flagged(carried["slender"]));
    EXPECT_TRUE(flagged(carried["too-slender"]));
    EXPECT_GT(std::stod(carried["squat"]["mu"]), std::stod(carried["paper"]["mu"]) + 0.01);
    EXPECT_LT(std::stod(carried["slender"]["mu"]), std::stod(carried["paper"]["mu"]));
}
