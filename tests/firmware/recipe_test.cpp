// Recipes and their audit trail: the canonical text and its hash, the config's rules reused,
// the trail's chain finding an edited, removed or cut entry, and the device naming the
// version in effect in every record.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "firmware/audit_log.h"
#include "firmware/device.h"
#include "firmware/recipe.h"
#include "firmware/recipe_book.h"
#include "firmware/recipe_camera.h"
#include "firmware/recipe_desk.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/file_camera.h"
#include "hal/file/file_led.h"
#include "hal/file/file_trigger.h"
#include "hal/file/folder_storage.h"
#include "hal/file/scripted_light.h"
#include "reading/record_line.h"
#include "tests/support/recording_serial.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    std::string path;
    TempDir()
    {
        char t[] = "/tmp/icacam-recipe-test-XXXXXX";
        path = ::mkdtemp(t);
    }
    ~TempDir() { fs::remove_all(path); }
};

fw::Config specimen(double n)
{
    fw::Config c;
    c.n = n;
    c.mmPerPx = 0.0125;
    return c;
}

std::string readFile(const std::string &p)
{
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeFile(const std::string &p, const std::string &text)
{
    std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

fw::AuditCheck checkDir(const std::string &dir)
{
    std::vector<fw::AuditEntry> entries;
    return fw::checkAudit(readFile(dir + "/" + fw::kAuditFile), readFile(dir + "/" + fw::kAuditHead), &entries);
}

std::string allProblems(const fw::AuditCheck &c)
{
    std::string out;
    for (const std::string &p : c.problems) out += p + "\n";
    return out;
}

// Three versions in a fresh folder: the first from the config, then n 0.25, then 0.3.
void threeVersions(hal::FolderStorage &storage)
{
    fw::RecipeBook book(storage);
    fw::Config cfg = specimen(0.2);
    std::vector<std::string> problems;
    ASSERT_TRUE(book.start(cfg, &cfg, "2026-01-01T00:00:00Z", &problems).ok());
    for (double n : {0.25, 0.3}) {
        fw::Config trial = cfg;
        trial.n = n;
        ASSERT_TRUE(book.record(trial, "default", "alice (web)", "new batch", "2026-01-02T00:00:00Z").ok());
        cfg = trial;
    }
    EXPECT_TRUE(problems.empty());
}

} // namespace

TEST(Recipe, HashIsSha256OfTheCanonicalText)
{
    // FIPS 180-2's example: the hash really is SHA-256.
    EXPECT_EQ(fw::recipeHash("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    fw::Config a = specimen(0.2), b = specimen(0.2);
    // The same settings written another way are the same recipe.
    ASSERT_EQ(fw::applyRecipeText("specimen.n = 0.20\ntolerance.mu = 1e-2\n", &b), "");
    EXPECT_EQ(fw::recipeText(a), fw::recipeText(b));
    EXPECT_EQ(fw::recipeHash(fw::recipeText(a)), fw::recipeHash(fw::recipeText(b)));
    b.n = 0.21;
    EXPECT_NE(fw::recipeHash(fw::recipeText(a)), fw::recipeHash(fw::recipeText(b)));
    EXPECT_EQ(fw::recipeChanges(fw::recipeText(a), fw::recipeText(b)), "specimen.n: 0.2 -> 0.21");
}

TEST(Recipe, ValidatedByTheConfigsOwnRules)
{
    fw::Config c = specimen(0.2), same = specimen(0.2);
    // A value out of range: the config's own message.
    EXPECT_EQ(fw::applyRecipeText("specimen.n = 5\n", &c), fw::setConfigKey(&same, "specimen.n", "5", false));
    c = specimen(0.2);
    // A rule between keys: the config's cross-key check.
    const std::string heights = fw::applyRecipeText("specimen.h0_mm = 15\nspecimen.h_final_mm = 20\n", &c);
    EXPECT_NE(heights.find("must be below specimen.h0_mm"), std::string::npos) << heights;
    c = specimen(0.2);
    EXPECT_NE(fw::applyRecipeText("camera.red_gain = 1.5\n", &c).find("set together"), std::string::npos);
    c = specimen(0.2);
    EXPECT_NE(fw::applyRecipeText("journal.dir = /\n", &c).find("not a recipe key"), std::string::npos);
    c = specimen(0.2);
    EXPECT_EQ(fw::applyRecipeText("specimen.material = S235\ncamera.exposure_us = 8000\n", &c), "");
    EXPECT_EQ(c.material, "S235");
    EXPECT_EQ(c.exposureUs, 8000);
}

TEST(Audit, AnIntactTrailChecksAndSurvivesARestart)
{
    TempDir dir;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path, 0).ok());
    threeVersions(storage);
    const fw::AuditCheck c = checkDir(dir.path);
    EXPECT_TRUE(c.ok()) << allProblems(c);
    EXPECT_EQ(c.entries, 3);
    // Started again with the same config file: version 3 is in effect, its n applied.
    fw::RecipeBook book(storage);
    fw::Config cfg = specimen(0.2);
    std::vector<std::string> problems;
    ASSERT_TRUE(book.start(specimen(0.2), &cfg, "t", &problems).ok());
    EXPECT_TRUE(problems.empty());
    EXPECT_EQ(book.active().version, 3);
    EXPECT_DOUBLE_EQ(cfg.n, 0.3);
    EXPECT_EQ(book.active().hash, fw::recipeHash(fw::recipeText(cfg)));
}

TEST(Audit, AConfigFileEditedIsANewVersion)
{
    TempDir dir;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path, 0).ok());
    threeVersions(storage);
    fw::RecipeBook book(storage);
    fw::Config cfg = specimen(0.4);
    std::vector<std::string> problems;
    ASSERT_TRUE(book.start(specimen(0.4), &cfg, "t", &problems).ok());
    EXPECT_EQ(book.active().version, 4);
    EXPECT_DOUBLE_EQ(cfg.n, 0.4);
    std::vector<fw::AuditEntry> entries;
    fw::checkAudit(readFile(dir.path + "/" + fw::kAuditFile), readFile(dir.path + "/" + fw::kAuditHead), &entries);
    ASSERT_EQ(entries.size(), 4u);
    EXPECT_EQ(entries.back().who, "config file");
    EXPECT_EQ(entries.back().changes, "specimen.n: 0.3 -> 0.4");
}

TEST(Audit, OneByteChangedIsFound)
{
    TempDir dir;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path, 0).ok());
    threeVersions(storage);
    const std::string file = dir.path + "/" + fw::kAuditFile;
    std::string log = readFile(file);
    // The second entry's reason, one letter changed.
    const size_t at = log.find("new batch");
    ASSERT_NE(at, std::string::npos);
    log[at] = 'N';
    writeFile(file, log);
    const fw::AuditCheck c = checkDir(dir.path);
    ASSERT_FALSE(c.ok());
    EXPECT_NE(allProblems(c).find("line 2 (entry 2): altered"), std::string::npos) << allProblems(c);
}

TEST(Audit, AnEntryRecomputedOrRemovedBreaksTheChain)
{
    TempDir dir;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path, 0).ok());
    threeVersions(storage);
    const std::string file = dir.path + "/" + fw::kAuditFile;
    const std::string log = readFile(file);
    const size_t l1 = log.find('\n') + 1, l2 = log.find('\n', l1) + 1;
    // Entry 2 rewritten by someone who recomputes its own hash: entry 3 no longer follows it.
    fw::AuditEntry forged;
    std::vector<fw::AuditEntry> entries;
    fw::checkAudit(log, readFile(dir.path + "/" + fw::kAuditHead), &entries);
    ASSERT_EQ(entries.size(), 3u);
    forged = entries[1];
    forged.why = "a forged reason";
    writeFile(file, log.substr(0, l1) + fw::auditLine(&forged) + log.substr(l2));
    fw::AuditCheck c = checkDir(dir.path);
    EXPECT_NE(allProblems(c).find("line 3 (entry 3): does not follow"), std::string::npos) << allProblems(c);
    // Entry 2 removed: the chain and the numbering both say so.
    writeFile(file, log.substr(0, l1) + log.substr(l2));
    c = checkDir(dir.path);
    EXPECT_NE(allProblems(c).find("does not follow"), std::string::npos) << allProblems(c);
    EXPECT_NE(allProblems(c).find("entries 2 to 2 are missing"), std::string::npos) << allProblems(c);
    // The last entry removed: only the head can tell.
    writeFile(file, log.substr(0, l2));
    c = checkDir(dir.path);
    EXPECT_NE(allProblems(c).find("entries at its end were removed"), std::string::npos) << allProblems(c);
    // Intact again: no finding.
    writeFile(file, log);
    EXPECT_TRUE(checkDir(dir.path).ok());
}

TEST(Audit, AVersionEditedIsNotUsed)
{
    TempDir dir;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path, 0).ok());
    threeVersions(storage);
    const std::string file = dir.path + "/" + fw::kAuditFile;
    std::string log = readFile(file);
    const size_t at = log.rfind("specimen.n = 0.3");
    ASSERT_NE(at, std::string::npos);
    log.replace(at, 16, "specimen.n = 0.9");
    writeFile(file, log);
    fw::RecipeBook book(storage);
    fw::Config cfg = specimen(0.2);
    std::vector<std::string> problems;
    ASSERT_TRUE(book.start(specimen(0.2), &cfg, "t", &problems).ok());
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems[0].find("altered"), std::string::npos) << problems[0];
    // The newest intact version is the one in effect, never the edited one.
    EXPECT_DOUBLE_EQ(cfg.n, 0.25);
    EXPECT_EQ(book.active().version, 2);
}

namespace {

struct DeviceRig {
    TempDir dir;
    hal::ManualClock clock;
    hal::ScriptedLight light{clock};
    hal::FileTrigger trigger{clock};
    hal::FileLed led{clock, &light};
    struct : hal::Display {
        hal::Error show(const hal::MonoBitmap &) override { return {}; }
    } display;
    test::RecordingSerial serial;
    hal::FolderStorage storage;
    friction::PaperModel model;
    fw::Config cfg;
    std::unique_ptr<fw::RecipeCamera> camera;
    fw::RecipeDesk desk;
    std::unique_ptr<fw::Device> device;
    int made = 0; // cameras made

    DeviceRig()
    {
        fs::create_directories(dir.path + "/frames");
        std::ofstream f(dir.path + "/frames/a.pgm", std::ios::binary);
        f << "P5\n64 64\n255\n" << std::string(64 * 64, char(20));
        f.close();
        EXPECT_TRUE(storage.open(dir.path + "/journal", 0).ok());
        cfg = specimen(0.2);
        cfg.cameraMaxWidth = cfg.cameraMaxHeight = 256;
        cfg.captureTimeoutMs = 500;
        cfg.exposureUs = 5000;
        auto make = [this](const fw::Config &c) -> hal::Result<std::unique_ptr<hal::Camera>> {
            ++made;
            // The file camera reports the controls it was made with on every frame.
            return {std::make_unique<hal::FileCamera>(clock, hal::FileCameraOptions{dir.path + "/frames", 1, true, 0,
                                                                                    fw::cameraControlsOf(c), &light}),
                    {}};
        };
        camera = std::make_unique<fw::RecipeCamera>(make, std::move(make(cfg).value), cfg);
        device = std::make_unique<fw::Device>(
            fw::DeviceHal{*camera, trigger, led, display, serial, storage, clock, nullptr, camera.get()}, cfg, model);
        device->setRecipeDesk(&desk);
    }

    // The newest line of a type the device said.
    reading::FlatObject newest(const std::string &type)
    {
        reading::FlatObject o;
        const std::string key = "{\"type\":\"" + type + "\"";
        const size_t at = serial.out.rfind(key);
        EXPECT_NE(at, std::string::npos) << serial.out;
        if (at != std::string::npos)
            reading::parseFlatObject(serial.out.substr(at, serial.out.find('\n', at) - at), &o);
        return o;
    }
};

std::string textOf(const reading::FlatObject &o, const char *key)
{
    const reading::JsonField *f = o.find(key);
    return f ? f->text : "(absent)";
}

} // namespace

TEST(DeviceRecipe, EveryRecordNamesTheVersionItWasMeasuredWith)
{
    DeviceRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    rig.serial.in = "trigger\n";
    rig.device->tick();
    reading::FlatObject r = rig.newest("result");
    EXPECT_EQ(textOf(r, "recipe"), "default");
    EXPECT_EQ(textOf(r, "recipe_version"), "1");
    EXPECT_EQ(textOf(r, "recipe_hash"), fw::recipeHash(fw::recipeText(rig.device->config())));
    // A setting over serial is version 2, audited as the serial line's, and the next record
    // names it.
    rig.serial.in = "set n 0.3\ntrigger\n";
    rig.device->tick();
    r = rig.newest("result");
    EXPECT_EQ(textOf(r, "recipe_version"), "2");
    EXPECT_EQ(textOf(r, "recipe_hash"), fw::recipeHash(fw::recipeText(rig.device->config())));
    EXPECT_EQ(textOf(r, "n"), "0.3");
    std::vector<fw::AuditEntry> entries;
    const fw::AuditCheck c = fw::checkAudit(readFile(rig.dir.path + "/journal/audit.jsonl"),
                                            readFile(rig.dir.path + "/journal/audit.head"), &entries);
    EXPECT_TRUE(c.ok()) << allProblems(c);
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[1].who, "serial");
    EXPECT_EQ(entries[1].changes, "specimen.n: 0.2 -> 0.3");
    // The journal line carries it too (what MQTT and the web publish).
    EXPECT_NE(readFile(rig.dir.path + "/journal/journal.jsonl").find("\"recipe_version\":2"), std::string::npos);
}

TEST(DeviceRecipe, ASaveFromTheWebNeedsAReasonAndSetsTheCamera)
{
    DeviceRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    const int madeAtStart = rig.made;
    fw::RecipeDesk::Request q;
    q.tag = "w1";
    q.who = "alice (web)";
    q.text = "camera.exposure_us = 8000\nspecimen.material = S235\n";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    EXPECT_EQ(textOf(rig.newest("error"), "code"), "recipe_refused"); // no reason
    EXPECT_EQ(rig.device->recipe().version, 1);
    q.tag = "w2";
    q.why = "longer exposure for the dark steel";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    const reading::FlatObject saved = rig.newest("recipe");
    EXPECT_EQ(textOf(saved, "recipe_version"), "2");
    EXPECT_EQ(textOf(saved, "tag"), "w2");
    EXPECT_EQ(rig.made, madeAtStart); // the exposure set on the running camera, not made again
    rig.serial.in = "trigger\n";
    rig.device->tick();
    const reading::FlatObject r = rig.newest("result");
    EXPECT_EQ(textOf(r, "exposure_us"), "8000"); // what the camera reported for the frame
    EXPECT_EQ(textOf(r, "material"), "S235");
    EXPECT_EQ(textOf(r, "recipe_version"), "2");
    // A value the config refuses is refused the same way, and nothing changes.
    q.tag = "w3";
    q.text = "specimen.n = 7\n";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    EXPECT_NE(textOf(rig.newest("error"), "message").find("specimen.n must be between"), std::string::npos);
    EXPECT_EQ(rig.device->recipe().version, 2);
}

TEST(DeviceRecipe, LiveControlsOnlyWhileAimingAndBackAfter)
{
    DeviceRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    fw::RecipeDesk::Request q;
    q.kind = fw::RecipeDesk::Request::Kind::Live;
    q.tag = "l1";
    q.text = "camera.exposure_us = 12000\n";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    EXPECT_NE(textOf(rig.newest("error"), "message").find("only while aiming"), std::string::npos);
    rig.serial.in = "aim 30\n";
    rig.device->tick();
    q.tag = "l2";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    EXPECT_EQ(textOf(rig.newest("live"), "changes"), "camera.exposure_us: 5000 -> 12000");
    EXPECT_EQ(rig.made, 1); // a slider move is a control on the running camera
    std::string live;
    rig.desk.inEffect(&live);
    EXPECT_EQ(live, "camera.exposure_us: 5000 -> 12000");
    // A measurement ends aiming: the recipe's exposure again, and no version was made.
    rig.serial.in = "trigger\n";
    rig.device->tick();
    const reading::FlatObject r = rig.newest("result");
    EXPECT_EQ(textOf(r, "exposure_us"), "5000");
    EXPECT_EQ(textOf(r, "recipe_version"), "1");
}

TEST(DeviceRecipe, OnlyAWhiteBalanceTemperatureMakesTheCameraAgain)
{
    DeviceRig rig;
    ASSERT_TRUE(rig.device->start().ok());
    const int madeAtStart = rig.made;
    fw::RecipeDesk::Request q;
    q.who = "alice (web)";
    q.why = "test";
    q.text = "camera.exposure_us = 9000\ncamera.analogue_gain = 2\ncamera.lens_position = 3\n";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    EXPECT_EQ(textOf(rig.newest("recipe"), "recipe_version"), "2");
    EXPECT_EQ(rig.made, madeAtStart);
    q.text = "camera.white_balance_k = 4000\n";
    ASSERT_TRUE(rig.desk.post(q));
    rig.device->tick();
    EXPECT_EQ(textOf(rig.newest("recipe"), "recipe_version"), "3");
    EXPECT_EQ(rig.made, madeAtStart + 1);
    // Made again with the whole recipe: the controls set on the run before are not lost.
    rig.serial.in = "trigger\n";
    rig.device->tick();
    const reading::FlatObject r = rig.newest("result");
    EXPECT_EQ(textOf(r, "exposure_us"), "9000");
    EXPECT_EQ(textOf(r, "recipe_version"), "3");
}

TEST(RecipeCamera, ChangedControlsAreTheOnesSetInTheNewConfig)
{
    hal::CameraControls a, b;
    a.exposureUs = 5000;
    a.analogueGain = 1;
    a.redGain = 1.5;
    a.blueGain = 1.6;
    b = a;
    b.exposureUs = 6000;
    b.blueGain = 1.7;
    b.analogueGain = -1; // left unset: not a change to make on the run
    const hal::CameraControls c = fw::changedControls(a, b);
    EXPECT_EQ(c.exposureUs, 6000);
    EXPECT_LT(c.analogueGain, 0);
    EXPECT_EQ(c.redGain, 1.5); // colour gains go as a pair
    EXPECT_EQ(c.blueGain, 1.7);
    EXPECT_FALSE(hal::anyControlSet(fw::changedControls(a, a)));
    fw::Config x, y;
    x.exposureUs = 5000;
    y = x;
    y.exposureUs = -1; // back to the camera's own exposure: only a camera made again does that
    EXPECT_TRUE(fw::RecipeCamera::needsRemake(x, y));
    y = x;
    y.exposureUs = 7000;
    EXPECT_FALSE(fw::RecipeCamera::needsRemake(x, y));
    y.whiteBalanceK = x.whiteBalanceK + 500;
    EXPECT_TRUE(fw::RecipeCamera::needsRemake(x, y));
}
