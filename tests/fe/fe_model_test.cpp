// The generated model (vision/fe_model_table.h) against the committed FE data
// (the CSVs its provenance names): the table is current, and μ is reproduced within 1 % in range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>
#include <filesystem>
#include <map>

#include "fe_rows.h"
#include "../table_inputs.h"
#include "vision/fe_model.h"
#include "vision/fe_model_table.h"

using namespace icacam;
namespace t = icacam::vision::fe_table;

namespace {
std::vector<std::string> tableInputs() { return test::provenanceInputs(t::kProvenance); }

// (n, μ) → u of the base data at one reduction, selected exactly as `icacam fe fit` selects it.
std::map<std::pair<double, double>, double> baseU(double reduction)
{
    std::map<std::pair<double, double>, double> out;
    for (const auto &[k, p] : host::fe::basePoints(tableInputs(), reduction)) out[k] = p.u;
    return out;
}

bool haveInputs()
{
    const auto in = tableInputs();
    return !in.empty() && std::all_of(in.begin(), in.end(), [](const std::string &p) { return std::filesystem::exists(p); });
}
} // namespace

TEST(FeModel, TableMatchesCommittedData)
{
    ASSERT_TRUE(haveInputs()) << "the table's inputs are not in the tree: " << t::kProvenance;
    int found = 0;
    for (int r = 0; r < t::kRCount; ++r) {
        const auto base = baseU(t::kR[r]);
        size_t inTable = 0;
        for (int i = 0; i < t::kNCount; ++i)
            for (int j = 0; j < t::kMuCount; ++j) {
                if (t::kU[r][i][j] < 0) continue;
                const auto it = base.find({t::kN[i], t::kMu[j]});
                ASSERT_NE(it, base.end()) << "table point n=" << t::kN[i] << " mu=" << t::kMu[j] << " r=" << t::kR[r]
                                          << " not in CSV";
                EXPECT_NEAR(t::kU[r][i][j], it->second, 2e-5) << "stale table: rerun icacam fe fit";
                ++found;
                ++inTable;
            }
        EXPECT_EQ(inTable, base.size()) << "the CSV has points the table lacks at r=" << t::kR[r] << ": rerun icacam fe fit";
    }
    EXPECT_GE(found, 1);
}

TEST(FeModel, ReproducesFeDataWithinOnePercent)
{
    ASSERT_TRUE(haveInputs()) << "the table's inputs are not in the tree: " << t::kProvenance;
    vision::FeModel model;
    int checked = 0;
    for (int r = 0; r < t::kRCount; ++r)
        for (const auto &[key, u] : baseU(t::kR[r])) {
            vision::ModelInputs in;
            in.n = key.first;
            in.uMm = u;
            in.hFinalMm = in.h0Mm * (1 - t::kR[r]);
            const auto e = model.estimate(in);
            if (e.range != vision::kModelInRange) continue; // e.g. u = 0: no fold-over, μ unresolved
            EXPECT_NEAR(e.mu, key.second, 0.01 * key.second) << "n=" << key.first << " u=" << u << " r=" << t::kR[r];
            EXPECT_GT(e.dMuDu, 0);
            ++checked;
        }
    EXPECT_GE(checked, 10);
}

TEST(FeModel, FlagsOutsideTheRange)
{
    vision::FeModel model;
    vision::ModelInputs in;
    in.n = t::kN[0] - 0.02;
    in.uMm = 0.5;
    EXPECT_TRUE(model.estimate(in).range & vision::kModelNBelow);
    in.n = t::kN[t::kNCount - 1] + 0.05;
    EXPECT_TRUE(model.estimate(in).range & vision::kModelNAbove);
    in.n = t::kN[0];
    in.uMm = 5.0;
    EXPECT_NE(model.estimate(in).range, 0u);
    in.uMm = 0.5;
    in.kMpa = 5000;
    EXPECT_TRUE(model.estimate(in).range & vision::kModelKOutside);
    in.kMpa = 0;
    // Height reduction: inside the snapshots no flag, outside (or no upset at all) a flag.
    in.hFinalMm = 15 * (1 - 0.5 * (t::kR[0] + t::kR[t::kRCount - 1]));
    EXPECT_FALSE(model.estimate(in).range & vision::kModelReductionOutside);
    in.hFinalMm = 15 * (1 - t::kR[t::kRCount - 1] - 0.03);
    EXPECT_TRUE(model.estimate(in).range & vision::kModelReductionOutside);
    in.hFinalMm = 15 * (1 - t::kR[0] + 0.03);
    EXPECT_TRUE(model.estimate(in).range & vision::kModelReductionOutside);
    in.hFinalMm = 16;
    EXPECT_TRUE(model.estimate(in).range & vision::kModelReductionOutside);
    in.hFinalMm = 0;
    // Geometric similarity: u at D0 = 20 mm is twice u at 10 mm for the same μ.
    vision::ModelInputs a, b;
    a.n = b.n = t::kN[0];
    a.uMm = 0.4;
    b.uMm = 0.8;
    b.d0Mm = 20;
    EXPECT_NEAR(model.estimate(a).mu, model.estimate(b).mu, 1e-12);
    const auto r = model.radii(t::kN[0], t::kMu[0], 20);
    const auto r10 = model.radii(t::kN[0], t::kMu[0], 10);
    EXPECT_NEAR(r.rMaxMm, 2 * r10.rMaxMm, 1e-9);
}

TEST(FeModel, BaseRunsTrackedACleanContactZone)
{
    // The runner says in a run's message when a node inside the contact zone lifted off (the
    // tracked edge lags there, fe_contact_track.h). The model's base must not contain such runs.
    ASSERT_TRUE(haveInputs()) << t::kProvenance;
    const auto rows = host::fe::readSweepCsvs(tableInputs());
    int checked = 0;
    for (int r = 0; r < t::kRCount; ++r) {
        const auto base = host::fe::chooseBase(rows, t::kR[r]);
        for (const auto &row : rows) {
            if (!base.includes(row, t::kR[r])) continue;
            EXPECT_EQ(row.message.find("contact zone broken"), std::string::npos) << row.caseId << ": " << row.message;
            ++checked;
        }
    }
    EXPECT_GE(checked, t::kRCount * 30);
}
