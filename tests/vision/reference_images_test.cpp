// The measurement of the bundled sample images must be the same, bit for bit, on every build
// (STYLE.md §8): x86-64 and aarch64 under qemu compare against one committed file. The
// images are decoded by the file-backed HAL (libpng / libjpeg-turbo, no OpenCV), so the test
// also pins the decoder: a different luma plane shows as a different digest first.
//
// Regenerate the expected file on x86-64 after a deliberate change to vision/ (commit it
// with that change):  cmake --build build --target update-reference-measurements
// (which runs this program with ICACAM_WRITE_REFERENCE set to the file's path).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "friction/paper_model.h"
#include "hal/file/image_decoder.h"
#include "reading/instrument.h"

namespace {

using namespace icacam;

const std::string kSample = std::string(ICACAM_SOURCE_DIR) + "/tests/data/sample";
const std::string kExpected = kSample + "/reference-measurements.txt";

struct SampleRow {
    std::string id, image;
    reading::SpecimenSpec spec;
};

// manifest.csv: id,image,n,k_mpa,d0_mm,h0_mm,mm_per_px (a fixed, tiny file: no CSV library).
std::vector<SampleRow> readManifest()
{
    std::vector<SampleRow> rows;
    std::ifstream in(kSample + "/manifest.csv");
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::stringstream ss(line);
        std::string cell[7];
        for (auto &c : cell) std::getline(ss, c, ',');
        SampleRow r;
        r.id = cell[0];
        r.image = cell[1];
        r.spec.n = std::strtod(cell[2].c_str(), nullptr);
        r.spec.kMpa = std::strtod(cell[3].c_str(), nullptr);
        r.spec.d0Mm = std::strtod(cell[4].c_str(), nullptr);
        r.spec.h0Mm = std::strtod(cell[5].c_str(), nullptr);
        r.spec.mmPerPx = std::strtod(cell[6].c_str(), nullptr);
        rows.push_back(r);
    }
    return rows;
}

// FNV-1a over the luma plane, row by row (the stride padding is not part of the image).
uint64_t digest(const uint8_t *data, int width, int height, int stride)
{
    uint64_t h = 1469598103934665603ull;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            h ^= data[size_t(y) * size_t(stride) + size_t(x)];
            h *= 1099511628211ull;
        }
    return h;
}

void put(std::string *out, const char *fmt, auto... args)
{
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, args...);
    *out += buf;
}

// Doubles are printed as hexadecimal floating point (%a): exact, so "identical" means bit
// for bit; fixed-point values as their raw integers.
void printFit(std::string *out, const char *name, const vision::BoundaryFit &f)
{
    put(out, "%s rEqPx %a rEqSigmaPx %a scatterPx %a coverage %a used %d\n", name, f.rEqPx, f.rEqSigmaPx, f.scatterPx,
        f.coverage, f.used);
    put(out, "%s contrast %a ellipticity %.12g axisDeg %a centre %a %a harmonics %d\n", name, f.contrast, f.ellipticity,
        f.axisDeg, f.centreX, f.centreY, f.harmonics);
}

void printPoints(std::string *out, const char *name, const vision::EdgeSample *pts, int n)
{
    for (int i = 0; pts && i < n; ++i) {
        const auto &p = pts[i];
        put(out, "%s %d %d x %d y %d r %d s %d\n", name, i, int(p.valid), int(p.x.raw()), int(p.y.raw()),
            int(p.radius.raw()), int(p.strength));
    }
}

std::string measureAll(std::string *failure)
{
    reading::Instrument analyzer;
    constexpr int kMaxW = 2048, kMaxH = 2048;
    friction::PaperModel model;
    if (analyzer.configure(kMaxW, kMaxH, model) != vision::ErrorCode::None) {
        *failure = "configure";
        return {};
    }
    const size_t cap = size_t(kMaxW) * kMaxH * 3;
    std::unique_ptr<uint8_t[]> buf(new uint8_t[cap]);
    std::string out = "# Measurements of tests/data/sample, generated on x86-64 by tests/vision/reference_images_test\n"
                      "# with ICACAM_WRITE_REFERENCE set; aarch64 (qemu) must print the same, bit for bit.\n";
    for (const auto &row : readManifest()) {
        hal::DecodedImage img;
        const hal::Error e = hal::decodeImage(kSample + "/" + row.image, buf.get(), cap, kMaxW, kMaxH, 0, &img);
        if (!e.ok()) {
            *failure = row.image + ": " + e.message;
            return {};
        }
        if (img.channels != 1) {
            *failure = row.image + ": expected a grey image";
            return {};
        }
        const vision::LumaView luma{buf.get(), img.width, img.height, img.stride, 1};
        const reading::Reading m = analyzer.read(luma, row.spec);
        put(&out, "image %s %dx%d luma-fnv1a %016llx\n", row.id.c_str(), img.width, img.height,
            static_cast<unsigned long long>(digest(buf.get(), img.width, img.height, img.stride)));
        put(&out, "status %s error %d flags %08x\n", reading::statusName(m.status), int(m.error), unsigned(m.flags));
        put(&out, "centre %a %a rMaxPx %a edgeWidthPx %a saturated %a\n", m.geometry.centreX, m.geometry.centreY,
            m.geometry.rMaxPx, m.geometry.edgeWidthPx, m.geometry.saturatedFraction);
        printFit(&out, "inner", m.geometry.inner);
        printFit(&out, "outer", m.geometry.outer);
        put(&out, "mm rInner %a rOuter %a rMax %a\n", m.rInnerMm(), m.rOuterMm(), m.rMaxMm());
        put(&out, "u px %a mm %a sigma %a\n", m.uPx, m.uMm, m.uSigmaMm);
        put(&out, "mu %a sigma %a (%.6f)\n", m.mu, m.muSigma, m.mu);
        // std::hypot is not correctly rounded and glibc's x86-64 and aarch64 builds differ in
        // its last bit (seen: 0x1.dba7936758132p-6 vs ...133p-6). Values from it are printed
        // to 12 digits until vision/ computes them with sqrt (correctly rounded everywhere).
        put(&out, "centreOffsetPx %.12g rays %d\n", m.centreOffsetPx, m.geometry.rayCount);
        printPoints(&out, "innerPt", m.geometry.innerPoints, m.geometry.rayCount);
        printPoints(&out, "outerPt", m.geometry.outerPoints, m.geometry.rayCount);
    }
    return out;
}

std::vector<std::string> lines(const std::string &s)
{
    std::vector<std::string> v;
    std::stringstream ss(s);
    for (std::string l; std::getline(ss, l);) v.push_back(l);
    return v;
}

TEST(ReferenceImages, MeasurementsMatchTheCommittedX86Results)
{
    std::string failure;
    const std::string got = measureAll(&failure);
    ASSERT_TRUE(failure.empty()) << failure;
    ASSERT_GT(got.size(), 200u);

    if (const char *w = std::getenv("ICACAM_WRITE_REFERENCE")) {
        std::ofstream(w) << got;
        GTEST_SKIP() << "wrote " << w;
    }
    std::ifstream in(kExpected);
    ASSERT_TRUE(in) << "missing " << kExpected;
    std::stringstream ss;
    ss << in.rdbuf();
    const auto want = lines(ss.str()), have = lines(got);
    ASSERT_EQ(want.size(), have.size());
    int shown = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        if (want[i] != have[i] && shown++ < 20)
            ADD_FAILURE() << "line " << i + 1 << "\n  expected: " << want[i] << "\n  measured: " << have[i];
    }
    EXPECT_EQ(shown, 0) << "lines differ from " << kExpected
                        << "\nIf vision/ was changed on purpose, regenerate it on x86-64 with\n"
                           "  cmake --build <build> --target update-reference-measurements\n"
                           "and commit it with the change; if only aarch64 differs, that is the bug.";
}

} // namespace
