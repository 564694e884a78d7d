// icacam loop on the device's own records: a device (icacam-fw's Device on the file-backed
// HAL) measures rendered end faces and journals them with their frames; `icacam loop
// --journal DIR --reference CSV` joins the journal with the lab's reference values by record
// id, re-measures the saved frames with the current pipeline and finds the effect nobody
// declared (lens L25 calibrated at L16's scale, 8 % large).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "calibration/calibration_file.h"
#include "firmware/device.h"
#include "friction/paper_model.h"
#include "friction/reduction_table.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/scripted_light.h"
#include "host_tools/calibration_renderer.h"
#include "host_tools/loop/journal_records.h"
#include "host_tools/loop/loop_command.h"
#include "host_tools/manifest.h"
#include "host_tools/model_inverse.h"
#include "host_tools/synth_loop_set.h"
#include "reading/record_line.h"
#include "tests/support/recording_serial.h"
#include "tests/support/table_inputs.h"

namespace fs = std::filesystem;
using namespace icacam;
using namespace icacam::host;
using namespace icacam::host::loop;

namespace {

// Rewrites the journal of a lab session through `edit` (a test's damage or an older format).
template <typename Edit> void editJournal(const fs::path &dir, Edit edit)
{
    const fs::path path = dir / "journal" / "journal.jsonl";
    std::string text;
    {
        std::ifstream f(path);
        text.assign(std::istreambuf_iterator<char>(f), {});
    }
    edit(text);
    std::ofstream(path) << text;
}

// Reads the joined manifest of a lab session's journal and its reference CSV.
void joinJournal(const fs::path &dir, Manifest *joined, JournalJoin *info)
{
    std::string err;
    ASSERT_TRUE(readJournalManifest((dir / "journal").string(), (dir / "reference.csv").string(), joined, info, &err))
        << err;
}

const std::vector<std::string> kSweep = icacam::test::repositoryPaths(icacam::friction::reduction_table::kFeSources);

struct NullDisplay final : hal::Display {
    hal::Error show(const hal::MonoBitmap &) override { return {}; }
};

// The lab's session: a rendered record set measured one by one on the device, each after
// the operator set that specimen's n, K, scale, final height and material over serial.
// Writes DIR/journal (the device's journal and frames) and DIR/reference.csv (the lab's
// reference μ and what it recorded, by the device's record id). Returns the record count.
int labSession(const fs::path &dir, LoopEffect effect, uint32_t seed, int count)
{
    LoopSetOptions opt;
    opt.effect = effect;
    opt.seed = seed;
    opt.count = count;
    const std::string manifestPath = writeLoopSet((dir / "set").string(), opt);
    Manifest set;
    std::string err;
    EXPECT_TRUE(readManifest(manifestPath, &set, &err)) << err;

    hal::ManualClock clock;
    hal::ScriptedLight light{clock}; // the file LED lights the file camera's frames
    hal::FileCamera camera(clock, hal::FileCameraOptions{(dir / "set" / "images").string(), 1, false, 0, {}, &light});
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    EXPECT_TRUE(storage.open((dir / "journal").string()).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.02;
    cfg.cameraMaxWidth = 800, cfg.cameraMaxHeight = 600;
    fw::Device device(fw::DeviceHal{camera, trigger, led, display, serial, storage, clock}, cfg, model);
    EXPECT_TRUE(device.start().ok());
    auto say = [&](const std::string &line) {
        serial.in += line + "\n";
        device.tick();
    };
    std::ofstream ref(dir / "reference.csv");
    ref << "id,mu_ref,lens,camera_id,operator,press_speed_mm_s,ambient_c\n";
    int id = 0;
    for (const ManifestRow &r : set.rows) { // the frames are taken in the manifest's order
        for (const char *key : {"n", "k_mpa", "mm_per_px", "h_final_mm", "material"})
            say(std::string("set ") + key + " " + r.get(key));
        say("trigger");
        ++id;
        ref << id << "," << r.get("mu_ref") << "," << r.get("lens") << "," << r.get("camera_id") << ","
            << r.get("operator") << "," << r.get("press_speed_mm_s") << "," << r.get("ambient_c") << "\n";
    }
    ref << "999,0.1,L16,cam-1,A,2,20\n"; // a reference row the journal does not have
    return id;
}

} // namespace

TEST(LoopJournal, DeviceRecordsReMeasuredAndTheLensFound)
{
    const fs::path dir = fs::temp_directory_path() / ("icacam_loop_journal_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const int count = labSession(dir, LoopEffect::Optical, 3, 40);
    ASSERT_TRUE(fs::exists(dir / "journal" / "journal.jsonl"));
    ASSERT_TRUE(fs::exists(dir / "journal" / "img-000001.pgm"));
    // A torn line in the middle of the journal (a byte flipped): skipped with its reason, the
    // batch goes on.
    editJournal(dir, [](std::string &text) {
        const size_t second = text.find('\n') + 1;
        text[text.find("\"mu\"", second) + 2] = 'v';
    });
    Manifest joined;
    JournalJoin join;
    joinJournal(dir, &joined, &join);
    EXPECT_EQ(join.results, count - 1);
    EXPECT_EQ(join.joined, count - 1);
    int damaged = 0, notInJournal = 0;
    for (const std::string &s : join.skipped) {
        damaged += s.find("damaged") != std::string::npos;
        notInJournal += s.find("reference id 999: not in the journal") != std::string::npos;
    }
    EXPECT_EQ(damaged, 1);
    EXPECT_EQ(notInJournal, 1);
    // The device's settings and results come through, its results as device_* (symptoms), and
    // the frame, not the device's radii, is what the loop measures.
    ASSERT_FALSE(joined.rows.empty());
    const ManifestRow &first = joined.rows.front();
    EXPECT_EQ(first.get("image"), "img-000001.pgm");
    EXPECT_FALSE(first.get("device_mu").empty());
    EXPECT_FALSE(first.get("mm_per_px").empty());
    EXPECT_FALSE(first.get("lens").empty());
    EXPECT_FALSE(first.has("r_inner_mm"));
    // D0 and H0: each record carries what the device was told.
    EXPECT_EQ(first.get("d0_mm"), "10");
    EXPECT_EQ(join.geometry, "d0_mm and h0_mm as each record carries them");
    EXPECT_TRUE(isSymptom("device_mu") && isSymptom("device_r_outer_mm"));

    RankingOptions ro;
    ro.folds = 5;
    ro.seed = 11;
    const LoopSummary s = runJournalLoop((dir / "journal").string(), (dir / "reference.csv").string(),
                                         (dir / "report").string(), "paper", ro, kSweep);
    EXPECT_GE(s.usable, count - 4) << "most frames re-measured";
    ASSERT_FALSE(s.ranking.empty());
    EXPECT_EQ(s.ranking.front().name, "lens");
    ASSERT_EQ(s.chosen, "lens");
    EXPECT_EQ(s.reading, "scale");
    EXPECT_LT(s.cvRmsAfter, 0.7 * s.rmsBefore) << s.rmsBefore << " -> " << s.cvRmsAfter;
    for (const GroupFit &g : s.grouping.groups) {
        std::printf("journal: lens %s factor %.4f +- %.4f (k=2)\n", g.level.c_str(), g.value, 2 * g.sigma);
        EXPECT_NEAR(g.value, g.level == "L25" ? 1.08 : 1.0, 2 * g.sigma) << g.level;
    }
    std::string report;
    {
        std::ifstream f(dir / "report" / "report.md");
        report.assign(std::istreambuf_iterator<char>(f), {});
    }
    EXPECT_NE(report.find("Journal: `"), std::string::npos);
    EXPECT_NE(report.find("damaged"), std::string::npos);
    fs::remove_all(dir);
}

TEST(LoopJournal, CrcIsTheJournalsCrc32)
{
    // The IEEE CRC-32 check value.
    EXPECT_EQ(reading::recordCrc32("123456789"), 0xCBF43926u);
}

// A record written without D0 and H0 (an older journal) takes them from the device's saved
// settings, and the join says for how many records it did.
TEST(LoopJournal, ARecordWithoutGeometryTakesTheSavedSettings)
{
    const fs::path dir = fs::temp_directory_path() / ("icacam_loop_geometry_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const int count = labSession(dir, LoopEffect::Null, 5, 6);
    editJournal(dir, [](std::string &text) {
        // The first result record without its d0_mm and h0_mm fields, its CRC made again.
        const size_t begin = text.find("{\"type\":\"result\"");
        ASSERT_NE(begin, std::string::npos);
        const size_t end = text.find('\n', begin);
        std::string line = text.substr(begin, end - begin);
        for (const char *key : {"\"d0_mm\":", "\"h0_mm\":"}) {
            const size_t at = line.find(key);
            ASSERT_NE(at, std::string::npos) << key;
            line.erase(at, line.find(',', at) + 1 - at);
        }
        const size_t crc = line.rfind(",\"crc32\":\"");
        char hex[9];
        std::snprintf(hex, sizeof hex, "%08x", reading::recordCrc32(line.substr(0, crc)));
        line = line.substr(0, crc) + ",\"crc32\":\"" + hex + "\"}";
        text.replace(begin, end - begin, line);
    });
    Manifest joined;
    JournalJoin join;
    joinJournal(dir, &joined, &join);
    EXPECT_EQ(join.joined, count);
    EXPECT_NE(join.geometry.find("for 1 of " + std::to_string(count) + " records"), std::string::npos) << join.geometry;
    EXPECT_NE(join.geometry.find("settings.conf"), std::string::npos) << join.geometry;
    ASSERT_FALSE(joined.rows.empty());
    EXPECT_EQ(joined.rows.front().get("d0_mm"), "10");
    EXPECT_EQ(joined.rows.back().get("d0_mm"), "10");
    fs::remove_all(dir);
}

// A device that measures through a camera calibration file (a tilted, distorting camera, no
// mm_per_px) journals the file's name with each result; the loop re-measures those frames
// through the same file, as the device did, and gets the device's μ. Without the file at
// hand the records are left out with why, and the join goes on.
TEST(LoopJournal, FramesMeasuredThroughACalibrationAreReMeasuredThroughIt)
{
    const fs::path dir = fs::temp_directory_path() / ("icacam_loop_calibrated_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "frames");
    const host::CameraModel cam = host::exampleTiltedCamera();
    calibration::CalibrationFile file;
    file.plane = host::toPlaneCalibration(cam);
    file.imageWidth = cam.width, file.imageHeight = cam.height;
    file.board = "chessboard:9x7:1.4";
    ASSERT_EQ(calibration::writeCalibrationFile((dir / "cam.cal").string(), file), "");
    const host::BoardPhotoRenderer renderer(cam);
    const friction::PaperModel paper;
    const double n = 0.2;
    const int count = 6; // the fewest records the loop takes
    std::ofstream ref(dir / "reference.csv");
    ref << "id,mu_ref,operator\n";
    for (int i = 0; i < count; ++i) {
        const double mu = 0.08 + 0.02 * i;
        host::EndFaceScene s;
        const double u = host::uForMu(paper, mu, n);
        s.rOuterMm = 6.85 - 0.95 * u, s.rInnerMm = s.rOuterMm - u;
        s.rMaxMm = 5.0 * std::sqrt(2.0) * (1.008 + 0.034 * u);
        char name[32];
        std::snprintf(name, sizeof name, "f%02d.png", i);
        cv::imwrite((dir / "frames" / name).string(),
                    renderer.endFace(s, 0.3 * (i % 3) - 0.3, -0.2, 7.5, 0.9, 2.0, uint32_t(10 + i)));
        ref << i + 1 << "," << mu + 0.002 * ((i % 3) - 1) << ","
            << "ABC"[i % 3] << "\n";
    }
    ref.close();

    hal::ManualClock clock;
    hal::ScriptedLight light{clock};
    hal::FileCamera camera(clock, hal::FileCameraOptions{(dir / "frames").string(), 1, false, 0, {}, &light});
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    NullDisplay display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open((dir / "journal").string()).ok());
    fw::Config cfg;
    cfg.n = n;
    cfg.h0Mm = 15, cfg.hFinalMm = 7.5; // the end face 7.5 mm above the fixture
    cfg.cameraMaxWidth = 1600, cfg.cameraMaxHeight = 1200;
    cfg.baseDir = dir.string();
    cfg.calibrationFile = "cam.cal"; // no mm_per_px: the calibration scales
    fw::Device device(fw::DeviceHal{camera, trigger, led, display, serial, storage, clock}, cfg, paper);
    ASSERT_TRUE(device.start().ok());
    for (int i = 0; i < count; ++i) {
        serial.in += "trigger\n";
        device.tick();
    }

    // The folder the calibration is in: every result joined, through it.
    Manifest joined;
    JournalJoin join;
    std::string err;
    ASSERT_TRUE(readJournalManifest((dir / "journal").string(), (dir / "reference.csv").string(), &joined, &join, &err,
                                    dir.string()))
        << err;
    EXPECT_EQ(join.joined, count);
    EXPECT_EQ(join.calibrated, count);
    ASSERT_FALSE(joined.rows.empty());
    EXPECT_EQ(fs::path(joined.rows.front().get("calibration")).filename(), "cam.cal");
    EXPECT_EQ(joined.rows.front().get("device_plane_height_mm"), "7.5");

    RankingOptions ro;
    ro.folds = 5;
    const LoopSummary s = runJournalLoop((dir / "journal").string(), (dir / "reference.csv").string(),
                                         (dir / "report").string(), "paper", ro, kSweep, dir.string());
    EXPECT_EQ(s.usable, count);
    // The re-measurement's μ (records.csv) is the device's own (the journal's device_mu).
    Manifest records;
    ASSERT_TRUE(readManifest((dir / "report" / "records.csv").string(), &records, &err)) << err;
    std::map<std::string, double> deviceMu;
    for (const ManifestRow &r : joined.rows) parseNumber(r.get("device_mu"), &deviceMu[r.get("id")]);
    ASSERT_EQ(records.rows.size(), size_t(count));
    for (const ManifestRow &r : records.rows) {
        double mu = 0;
        ASSERT_TRUE(parseNumber(r.get("mu_model"), &mu));
        ASSERT_TRUE(deviceMu.count(r.get("id"))) << r.get("id");
        EXPECT_NEAR(mu, deviceMu[r.get("id")], 5e-4) << r.get("id");
    }

    // Without the file: each record left out, saying so.
    Manifest none;
    JournalJoin missing;
    ASSERT_TRUE(
        readJournalManifest((dir / "journal").string(), (dir / "reference.csv").string(), &none, &missing, &err));
    EXPECT_EQ(missing.joined, 0);
    int notThere = 0;
    for (const std::string &why : missing.skipped)
        notThere += why.find("'cam.cal', which is not in") != std::string::npos;
    EXPECT_EQ(notThere, count);
    fs::remove_all(dir);
}
