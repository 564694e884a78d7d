// The generated model (friction/fe_model_table.h) against the committed FE data
// (the base and K family it names): the table is current, and μ is reproduced within 1 % in range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

#include "friction/fe_model.h"
#include "friction/fe_model_table.h"
#include "host_tools/fe/fe_rows.h"
#include "tests/support/table_inputs.h"

using namespace icacam;
namespace t = icacam::friction::fe_table;

namespace {
// The files the table names: its base, and the base with the K family (the carry's runs).
std::vector<std::string> baseFile()
{
    return test::repositoryPaths(t::kBase);
}
std::vector<std::string> tableInputs()
{
    std::vector<std::string> in = baseFile();
    for (const std::string &f : test::repositoryPaths(t::kKFamily)) in.push_back(f);
    return in;
}

// (n, μ) → u of the base data at one reduction, selected exactly as `icacam fe tables` selects it.
std::map<std::pair<double, double>, double> baseU(double reduction)
{
    std::map<std::pair<double, double>, double> out;
    for (const auto &[k, p] : host::fe::basePoints(baseFile(), reduction)) out[k] = p.u;
    return out;
}

bool haveInputs()
{
    const auto in = tableInputs();
    return in.size() >= 2 &&
           std::all_of(in.begin(), in.end(), [](const std::string &p) { return std::filesystem::exists(p); });
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
                if (std::isnan(t::kU[r][i][j])) continue;
                const auto it = base.find({t::kN[i], t::kMu[j]});
                ASSERT_NE(it, base.end())
                    << "table point n=" << t::kN[i] << " mu=" << t::kMu[j] << " r=" << t::kR[r] << " not in CSV";
                EXPECT_NEAR(t::kU[r][i][j], it->second, 2e-5) << "stale table: rerun icacam fe tables";
                ++found;
                ++inTable;
            }
        EXPECT_EQ(inTable, base.size()) << "the CSV has points the table lacks at r=" << t::kR[r]
                                        << ": rerun icacam fe tables";
    }
    EXPECT_GE(found, 1);
}

TEST(FeModel, KCarryMatchesCommittedData)
{
    // The K carry (u and the radii at K minus at the base's K) is what `fe tables` takes from the
    // CSVs: a stale table or a changed selection fails here.
    ASSERT_TRUE(haveInputs()) << t::kProvenance;
    const auto rows = host::fe::readSweepCsvs(tableInputs());
    const auto baseRows = host::fe::readSweepCsvs(baseFile());
    int checked = 0;
    for (int r = 0; r < t::kRCount; ++r) {
        const auto c = host::fe::kCarry(rows, t::kR[r], host::fe::chooseBase(baseRows, t::kR[r]));
        ASSERT_TRUE(c.found) << "the committed data hold the factorial: a K carry is expected";
        ASSERT_EQ(int(c.k.size()), t::kKCount);
        for (int q = 0; q < t::kKCount; ++q) {
            ASSERT_EQ(c.k[q], t::kK[q]);
            for (int i = 0; i < t::kNCount; ++i)
                for (int j = 0; j < t::kMuCount; ++j) {
                    const auto &d = c.delta.at(t::kK[q]);
                    const auto it = d.find({t::kN[i], t::kMu[j]});
                    if (it == d.end()) continue;
                    EXPECT_NEAR(t::kDU[q][r][i][j], it->second.u, 2e-5) << "stale table: rerun icacam fe tables";
                    EXPECT_NEAR(t::kDRi[q][r][i][j], it->second.ri, 2e-5);
                    EXPECT_NEAR(t::kDRmax[q][r][i][j], it->second.rMax, 2e-5);
                    ++checked;
                }
        }
    }
    EXPECT_GE(checked, t::kRCount * t::kKCount * 30);
}

TEST(FeModel, ReadsUAtTheSpecimensK)
{
    // At each factorial K, u at a simulated (n, μ) is the base's plus the carry, and μ read
    // back at that K is the simulated μ within 1 %; K not given is the base's K.
    friction::FeModel model;
    int checked = 0, moved = 0;
    for (int q = 0; q < t::kKCount; ++q)
        for (int r = 0; r < t::kRCount; ++r)
            for (int i = 0; i < t::kNCount; ++i)
                for (int j = 0; j < t::kMuCount; ++j) {
                    if (std::isnan(t::kU[r][i][j])) continue;
                    const double u = model.uAt(t::kN[i], t::kMu[j], t::kR[r], t::kK[q]);
                    EXPECT_NEAR(u, std::max(0.0, t::kU[r][i][j] + t::kDU[q][r][i][j]), 1e-12);
                    const auto rad = model.radii(t::kN[i], t::kMu[j], 10, t::kR[r], t::kK[q]);
                    EXPECT_NEAR(rad.roMm - rad.riMm, t::kU[r][i][j] + t::kDU[q][r][i][j], 1e-9);
                    friction::ModelInputs in;
                    in.n = t::kN[i];
                    in.uMm = u;
                    in.kMpa = t::kK[q];
                    in.hFinalMm = in.h0Mm * (1 - t::kR[r]);
                    const auto e = model.estimate(in);
                    if (e.range != friction::kModelInRange) continue;
                    EXPECT_NEAR(e.mu, t::kMu[j], 0.01 * t::kMu[j])
                        << "K " << t::kK[q] << " n " << t::kN[i] << " r " << t::kR[r] << " u " << u;
                    ++checked;
                    // The same u read without K (the base's) gives another μ where the carry moved u.
                    in.kMpa = 0;
                    if (std::fabs(model.estimate(in).mu - e.mu) > 1e-4) ++moved;
                }
    EXPECT_GE(checked, 100);
    EXPECT_GE(moved, 20) << "the K carry should move μ near the fold-over's onset";
    EXPECT_NEAR(model.uAt(0.25, 0.1), model.uAt(0.25, 0.1, 0, 500), 1e-12);
}

TEST(FeModel, ReproducesFeDataWithinOnePercent)
{
    ASSERT_TRUE(haveInputs()) << "the table's inputs are not in the tree: " << t::kProvenance;
    friction::FeModel model;
    int checked = 0;
    for (int r = 0; r < t::kRCount; ++r)
        for (const auto &[key, u] : baseU(t::kR[r])) {
            friction::ModelInputs in;
            in.n = key.first;
            in.uMm = u;
            in.hFinalMm = in.h0Mm * (1 - t::kR[r]);
            const auto e = model.estimate(in);
            if (e.range != friction::kModelInRange) continue; // e.g. u = 0: no fold-over, μ unresolved
            EXPECT_NEAR(e.mu, key.second, 0.01 * key.second) << "n=" << key.first << " u=" << u << " r=" << t::kR[r];
            EXPECT_GT(e.dMuDu, 0);
            ++checked;
        }
    EXPECT_GE(checked, 10);
}

TEST(FeModel, FlagsOutsideTheRange)
{
    friction::FeModel model;
    friction::ModelInputs in;
    in.n = t::kN[0] - 0.02;
    in.uMm = 0.5;
    EXPECT_TRUE(model.estimate(in).range & friction::kModelNBelow);
    in.n = t::kN[t::kNCount - 1] + 0.05;
    EXPECT_TRUE(model.estimate(in).range & friction::kModelNAbove);
    in.n = t::kN[0];
    in.uMm = 5.0;
    EXPECT_NE(model.estimate(in).range, 0u);
    in.uMm = 0.5;
    in.kMpa = 5000;
    EXPECT_TRUE(model.estimate(in).range & friction::kModelKOutside);
    in.kMpa = 0;
    // Height reduction: inside the snapshots no flag, outside (or no upset at all) a flag.
    in.hFinalMm = 15 * (1 - 0.5 * (t::kR[0] + t::kR[t::kRCount - 1]));
    EXPECT_FALSE(model.estimate(in).range & friction::kModelReductionOutside);
    in.hFinalMm = 15 * (1 - t::kR[t::kRCount - 1] - 0.03);
    EXPECT_TRUE(model.estimate(in).range & friction::kModelReductionOutside);
    in.hFinalMm = 15 * (1 - t::kR[0] + 0.03);
    EXPECT_TRUE(model.estimate(in).range & friction::kModelReductionOutside);
    in.hFinalMm = 16;
    EXPECT_TRUE(model.estimate(in).range & friction::kModelReductionOutside);
    in.hFinalMm = 0;
    // Geometric similarity: u at D0 = 20 mm is twice u at 10 mm for the same μ.
    friction::ModelInputs a, b;
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
    const auto rows = host::fe::readSweepCsvs(baseFile());
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
