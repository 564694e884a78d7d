// The generated tables (friction/*_table.h) are exactly what their command makes from the
// committed CSVs: each header names `icacam fe tables` and its inputs; that command, run again
// here over the same files, must write the same bytes (else: rerun it, data/fe/README.md).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "friction/aspect_table.h"
#include "friction/fe_model_table.h"
#include "friction/reduction_table.h"
#include "host_tools/fe/fe_tables.h"

using namespace icacam;

namespace {
std::vector<std::string> words(const std::string &command)
{
    std::vector<std::string> w;
    std::istringstream s(command);
    for (std::string x; s >> x;) w.push_back(x);
    return w;
}
} // namespace

TEST(GeneratedTables, AllNameOneCommandAndOneBase)
{
    EXPECT_STREQ(friction::fe_table::kProvenance, friction::reduction_table::kProvenance);
    EXPECT_STREQ(friction::fe_table::kProvenance, friction::aspect_table::kProvenance);
    EXPECT_STREQ(friction::fe_table::kBase, friction::reduction_table::kFeSources);
    const auto w = words(friction::fe_table::kProvenance);
    ASSERT_GE(w.size(), 5u);
    EXPECT_EQ(w[0] + " " + w[1] + " " + w[2], "icacam fe tables");
}

TEST(GeneratedTables, AreWhatTheCommandMakesFromTheCommittedData)
{
    const auto w = words(friction::fe_table::kProvenance);
    ASSERT_GE(w.size(), 3u);
    const host::fe::TablesRequest request = host::fe::parseTablesArgs({w.begin() + 3, w.end()});
    EXPECT_EQ(request.src.command, friction::fe_table::kProvenance) << "the command is written in its canonical form";
    const auto tables = host::fe::tablesText(request, std::string(ICACAM_SOURCE_DIR) + "/");
    ASSERT_EQ(tables.size(), 3u);
    for (const auto &t : tables) {
        std::ifstream f(std::string(ICACAM_SOURCE_DIR) + "/friction/" + t.file, std::ios::binary);
        ASSERT_TRUE(f) << t.file;
        std::stringstream committed;
        committed << f.rdbuf();
        EXPECT_EQ(committed.str(), t.text) << "stale table friction/" << t.file << ": rerun `"
                                           << friction::fe_table::kProvenance << "` (data/fe/README.md)";
    }
}

TEST(GeneratedTables, TheCommandRefusesASecondBaseOrNone)
{
    EXPECT_THROW(host::fe::parseTablesArgs({"--base", "a.csv", "--base", "b.csv"}), std::runtime_error);
    EXPECT_THROW(host::fe::parseTablesArgs({"--aspect", "a.csv"}), std::runtime_error);
    EXPECT_THROW(host::fe::parseTablesArgs({"--base", "a.csv", "--reduction", "1.5"}), std::runtime_error);
    EXPECT_THROW(host::fe::parseTablesArgs({"--base", "a.csv", "--bogus", "x"}), std::runtime_error);
    host::fe::TablesRequest missing =
        host::fe::parseTablesArgs({"--base", "/nonexistent/base.csv", "--aspect", "x.csv"});
    EXPECT_THROW(host::fe::tablesText(missing, ""), std::runtime_error);
}
