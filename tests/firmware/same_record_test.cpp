// One instrument: the same image and declared inputs give the same reading fields on the
// device (icacam-fw over the file-backed HAL, its serial result line) and on the PC
// (`icacam measure --format jsonl`, and `icacam loop`, which measures through the same
// RecordMeasurer), field by field and to the printed digit.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "firmware/device.h"
#include "friction/friction_models.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/scripted_light.h"
#include "host_tools/loop/loop_records.h"
#include "host_tools/manifest.h"
#include "host_tools/record_measurer.h"
#include "host_tools/result_writer.h"
#include "reading/reading_record.h"
#include "reading/record_line.h"
#include "tests/support/recording_serial.h"
#include "tests/support/same_reading.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

const std::string kSample = std::string(ICACAM_SOURCE_DIR) + "/tests/data/sample";

// The device's result line for one frame of the sample set.
reading::FlatObject deviceResult(const std::string &image, const fw::Config &base, const friction::FrictionModel &model)
{
    char t[] = "/tmp/icacam-same-XXXXXX";
    const fs::path dir = ::mkdtemp(t);
    fs::create_directories(dir / "frames");
    fs::copy_file(kSample + "/images/" + image, dir / "frames" / image);
    hal::ManualClock clock;
    hal::ScriptedLight light{clock}; // the file LED lights the file camera's frames
    hal::FileCamera camera(clock, hal::FileCameraOptions{(dir / "frames").string(), 1, false, 0, {}, &light});
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    EXPECT_TRUE(storage.open((dir / "journal").string()).ok());
    fw::Config cfg = base;
    cfg.baseDir = dir.string();
    fw::Device device(fw::DeviceHal{camera, trigger, led, display, serial, storage, clock}, cfg, model);
    EXPECT_TRUE(device.start().ok());
    serial.in += "trigger\n";
    device.tick();
    const reading::FlatObject r = serial.last("result");
    fs::remove_all(dir);
    return r;
}

reading::FlatObject hostResult(const std::string &manifestText, const friction::FrictionModel &model)
{
    return test::hostResult(manifestText, kSample, model);
}

using test::expectSameReading;

} // namespace

TEST(OneInstrument, DeviceAndMeasureGiveTheSameReading)
{
    const friction::FrictionModel *model = friction::frictionModel(friction::kDefaultModel);
    ASSERT_NE(model, nullptr);
    fw::Config cfg;
    cfg.n = 0.1742, cfg.kMpa = 647, cfg.mmPerPx = 0.0153924;
    cfg.cameraMaxWidth = 2048, cfg.cameraMaxHeight = 1536;
    // Nothing more declared: the reduction is inferred from the silhouette on both.
    const reading::FlatObject d1 = deviceResult("synth-0002.jpg", cfg, *model);
    const reading::FlatObject h1 =
        hostResult("id,image,n,k_mpa,mm_per_px\na,images/synth-0002.jpg,0.1742,647,0.0153924\n", *model);
    ASSERT_NE(d1.find("mu"), nullptr);
    EXPECT_EQ(d1.find("mu")->type, reading::JsonField::Type::Number);
    expectSameReading(d1, h1);

    // Declared final height and tolerances, set the device's way and the manifest's way.
    cfg.hFinalMm = 7.6, cfg.nTol = 0.02, cfg.toleranceMu = 0.02, cfg.toleranceRel = 0.04, cfg.mmPerPxTolRel = 0.01;
    const reading::FlatObject d2 = deviceResult("synth-0002.jpg", cfg, *model);
    const reading::FlatObject h2 =
        hostResult("id,image,n,k_mpa,mm_per_px,h_final_mm,n_tol,tolerance_mu,tolerance_rel,mm_per_px_tol\n"
                   "a,images/synth-0002.jpg,0.1742,647,0.0153924,7.6,0.02,0.02,0.04,0.01\n",
                   *model);
    expectSameReading(d2, h2);
    EXPECT_NE(d1.find("mu_sigma")->text, d2.find("mu_sigma")->text); // the declarations changed the budget
    EXPECT_EQ(d2.find("tolerance_mu")->number, 0.02);
}

TEST(OneInstrument, TheDeviceRunsAnyModelByName)
{
    fw::Config cfg;
    cfg.n = 0.1742, cfg.kMpa = 647, cfg.mmPerPx = 0.0153924, cfg.hFinalMm = 7.5;
    cfg.cameraMaxWidth = 2048, cfg.cameraMaxHeight = 1536;
    for (const char *name : {"fe", "fe_reduction", "paper"}) {
        // The config names the model as `icacam measure --model` does.
        fw::Config c = cfg;
        ASSERT_EQ(fw::setConfigKey(&c, "reading.model", name, false), "") << name;
        const friction::FrictionModel *model = friction::frictionModel(c.model);
        ASSERT_NE(model, nullptr) << name;
        const reading::FlatObject d = deviceResult("synth-0002.jpg", c, *model);
        const reading::FlatObject h = hostResult("id,image,n,k_mpa,mm_per_px,h_final_mm\n"
                                                 "a,images/synth-0002.jpg,0.1742,647,0.0153924,7.5\n",
                                                 *model);
        ASSERT_NE(d.find("model"), nullptr);
        EXPECT_EQ(d.find("model")->text, name);
        expectSameReading(d, h);
    }
    fw::Config bad = cfg;
    EXPECT_NE(fw::setConfigKey(&bad, "reading.model", "cubic", false), "");
}

// `icacam loop` holds the same instrument: an image row becomes the face at the declared
// scale and the model's estimate there, as `icacam measure` reads it; a radii row with that
// face's radii gives the same estimate.
TEST(OneInstrument, TheLoopReadsImageAndRadiiRowsThroughIt)
{
    const friction::FrictionModel *model = friction::frictionModel(friction::kDefaultModel);
    auto manifestOf = [](const std::string &text) {
        host::Manifest m;
        std::string err;
        EXPECT_TRUE(host::parseManifest(text, &m, &err)) << err;
        m.baseDir = kSample;
        return m;
    };
    const host::Manifest images =
        manifestOf("id,image,n,k_mpa,mm_per_px,mu_ref\na,images/synth-0002.jpg,0.1742,647,0.0153924,0.16\n");
    host::RecordMeasurer measurer(*model, reading::SpecimenSpec{});
    host::loop::LoopRecord fromImage;
    std::string why;
    ASSERT_TRUE(host::loop::readLoopRecord(images.rows.at(0), images, measurer, &fromImage, &why)) << why;
    host::RecordReading measured;
    measurer.measure(images.rows.at(0), images, &measured);
    ASSERT_TRUE(measured.reading.hasValue());
    EXPECT_EQ(fromImage.uMm, measured.reading.face.uMm);
    EXPECT_EQ(fromImage.muModel, measured.reading.declared.mu);
    EXPECT_GT(fromImage.diagnostics.count("diag_reduction_est"), 0u) << "the image's diagnostics are kept";

    char row[256];
    std::snprintf(row, sizeof row, "id,r_inner_mm,r_outer_mm,n,k_mpa,mu_ref\nb,%.17g,%.17g,0.1742,647,0.16\n",
                  measured.reading.face.rInnerMm, measured.reading.face.rOuterMm);
    const host::Manifest radii = manifestOf(row);
    host::loop::LoopRecord fromRadii;
    ASSERT_TRUE(host::loop::readLoopRecord(radii.rows.at(0), radii, measurer, &fromRadii, &why)) << why;
    EXPECT_NEAR(fromRadii.uMm, fromImage.uMm, 1e-12);
    EXPECT_NEAR(fromRadii.muModel, fromImage.muModel, 1e-9);
    EXPECT_EQ(fromRadii.diagnostics.count("diag_reduction_est"), 0u);
}
