#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "firmware/debouncer.h"
#include "firmware/journal.h"
#include "hal/file/folder_storage.h"
#include "reading/record_line.h"
#include "tests/support/temp_dir.h"

using namespace icacam;
namespace fs = std::filesystem;

namespace {

using test::TempDir;

std::string record(long id)
{
    return "{\"type\":\"result\",\"id\":" + std::to_string(id) + ",\"mu\":0.1}\n";
}

} // namespace

TEST(Journal, AppendsAndRecoversAcrossRestarts)
{
    TempDir dir;
    hal::FolderStorage st;
    ASSERT_TRUE(st.open(dir.path).ok());
    {
        fw::Journal j(st, 4);
        fw::JournalRecovery rec;
        ASSERT_TRUE(j.recover(&rec).ok());
        EXPECT_EQ(rec.records, 0);
        for (long id = 1; id <= 6; ++id) ASSERT_TRUE(j.append(record(id)).ok());
        EXPECT_EQ(j.recentCount(), 4u);
        EXPECT_EQ(fw::Journal::checkLine(j.recent(0)), 3);
    }
    fw::Journal j(st, 4);
    fw::JournalRecovery rec;
    ASSERT_TRUE(j.recover(&rec).ok());
    EXPECT_EQ(rec.records, 6);
    EXPECT_EQ(rec.lastId, 6);
    EXPECT_EQ(rec.cutBytes, 0u);
    EXPECT_EQ(fw::Journal::checkLine(j.recent(j.recentCount() - 1)), 6);
}

TEST(Journal, TornTailAndCorruptLineAreCutAndKept)
{
    TempDir dir;
    hal::FolderStorage st;
    ASSERT_TRUE(st.open(dir.path).ok());
    {
        fw::Journal j(st, 8);
        fw::JournalRecovery rec;
        ASSERT_TRUE(j.recover(&rec).ok());
        for (long id = 1; id <= 3; ++id) ASSERT_TRUE(j.append(record(id)).ok());
    }
    // A power loss in the middle of record 4, and a leftover temporary image.
    ASSERT_TRUE(st.append(fw::Journal::kFile, "{\"type\":\"result\",\"id\":4,\"mu\":0.").ok());
    ASSERT_TRUE(st.append("img-000004.pgm.tmp", "P5").ok());
    fw::Journal j(st, 8);
    fw::JournalRecovery rec;
    ASSERT_TRUE(j.recover(&rec).ok());
    EXPECT_EQ(rec.records, 3);
    EXPECT_EQ(rec.lastId, 3);
    EXPECT_GT(rec.cutBytes, 0u);
    EXPECT_EQ(rec.tempFilesRemoved, 1);
    EXPECT_FALSE(fs::exists(dir.path + "/img-000004.pgm.tmp"));
    // A flipped byte inside a complete line is caught by its CRC.
    auto text = st.read(fw::Journal::kFile).value;
    text[text.find("0.1")] = '9';
    ASSERT_TRUE(st.writeAtomic(fw::Journal::kFile, text).ok());
    fw::Journal j2(st, 8);
    ASSERT_TRUE(j2.recover(&rec).ok());
    EXPECT_EQ(rec.records, 0);
    ASSERT_TRUE(j2.append(record(1)).ok());
}

TEST(Journal, FullStorageIsAnErrorNotACrash)
{
    TempDir dir;
    hal::FolderStorage st;
    ASSERT_TRUE(st.open(dir.path, 200).ok());
    fw::Journal j(st, 8);
    fw::JournalRecovery rec;
    ASSERT_TRUE(j.recover(&rec).ok());
    hal::Error e;
    int written = 0;
    for (long id = 1; id <= 10 && e.ok(); ++id)
        if ((e = j.append(record(id))).ok()) ++written;
    EXPECT_EQ(e.code, hal::Errc::Full);
    EXPECT_GT(written, 0);
    EXPECT_EQ(j.saveImage("img.pgm", std::string(500, 'x')).code, hal::Errc::Full);
}

TEST(Journal, Crc32KnownValue)
{
    EXPECT_EQ(icacam::reading::recordCrc32("123456789"), 0xCBF43926u);
}

TEST(Debouncer, BounceShortAndLong)
{
    fw::Debouncer d(30, 1500);
    using fw::Press;
    // Contact bounce: short pulses are ignored; the settled press counts once on release.
    EXPECT_EQ(d.onEdge({0, true}), Press::None);
    EXPECT_EQ(d.onEdge({3, false}), Press::None);
    EXPECT_EQ(d.onEdge({5, true}), Press::None);
    EXPECT_EQ(d.onEdge({7, false}), Press::None);
    EXPECT_EQ(d.onEdge({9, true}), Press::None);
    EXPECT_EQ(d.poll(100), Press::None);
    EXPECT_EQ(d.onEdge({140, false}), Press::Short);
    EXPECT_EQ(d.onEdge({142, true}), Press::None); // release bounce
    EXPECT_EQ(d.onEdge({144, false}), Press::None);
    // Long press fires while held, and not again on release.
    EXPECT_EQ(d.onEdge({1000, true}), Press::None);
    EXPECT_EQ(d.poll(2400), Press::None);
    EXPECT_EQ(d.poll(2500), Press::Long);
    EXPECT_EQ(d.poll(2600), Press::None);
    EXPECT_EQ(d.onEdge({3000, false}), Press::None);
}
