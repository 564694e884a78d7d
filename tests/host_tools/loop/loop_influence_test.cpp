// icacam loop and a record that carries an effect (docs/loop-method.md, "Records that carry an
// effect"): on a radii record set with no hidden effect (`icacam synth --effect null --radii`),
// a measured quantity (a column `diag_outer_coverage`, a symptom) that weakly tracks each
// record's residual, as a pipeline diagnostic does, and one record far off in it with a large
// residual (a blurred image whose reference value is off). That one record makes the
// diagnostic's regression significant over the family: the loop must name the record and add
// nothing. The same excursion on several records is an effect the records carry: it is added.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "friction/reduction_table.h"
#include "host_tools/loop/loop_command.h"
#include "host_tools/manifest.h"
#include "host_tools/number_text.h"
#include "host_tools/synth_loop_set.h"
#include "tests/support/table_inputs.h"

namespace fs = std::filesystem;
using namespace icacam::host;
using namespace icacam::host::loop;

namespace {

const std::vector<std::string> kSweep = icacam::test::repositoryPaths(icacam::friction::reduction_table::kFeSources);

RankingOptions options()
{
    RankingOptions ro;
    ro.folds = 5;
    ro.seed = 1;
    return ro;
}

std::string readText(const fs::path &p)
{
    std::ifstream f(p);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

// A null radii set with a diagnostic column that tracks each record's residual weakly (a
// correlation of about `track`), and `odd` records far off in it:
// coverage 0.60–0.70 where the rest lie near 0.985, and μ_ref raised by `shift` (their
// residual lowered by as much), spread over the run (every 60/odd-th record, from the first,
// so that no recorded condition, the sequence among them, groups them). Returns the loop's summary; *dir keeps the
// report.
LoopSummary runWithExcursion(const std::string &name, uint32_t seed, int odd, double shift, double track, fs::path *dir,
                             std::vector<std::string> *oddIds)
{
    *dir = fs::temp_directory_path() / ("icacam_loop_influence_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(*dir);
    LoopSetOptions opt;
    opt.effect = LoopEffect::Null;
    opt.seed = seed;
    opt.count = 60;
    opt.radii = true;
    const std::string manifestPath = writeLoopSet(dir->string(), opt);
    // The residual each record has as the model reads it: from a first run, which adds nothing.
    const LoopSummary plain = runLoop(manifestPath, (*dir / "plain").string(), "paper", options(), kSweep);
    EXPECT_TRUE(plain.effects.empty()) << "the null set alone adds " << plain.chosen;
    Manifest records, manifest;
    std::string err;
    EXPECT_TRUE(readManifest((*dir / "plain" / "records.csv").string(), &records, &err)) << err;
    EXPECT_TRUE(readManifest(manifestPath, &manifest, &err)) << err;
    std::map<std::string, double> residual;
    double sum = 0, sumSq = 0;
    for (const ManifestRow &r : records.rows) {
        double v = 0;
        EXPECT_TRUE(parseNumber(r.get("residual"), &v));
        residual[r.get("id")] = v;
        sum += v, sumSq += v * v;
    }
    const double n = double(records.rows.size());
    const double mean = sum / n, sd = std::sqrt(sumSq / n - mean * mean);
    std::ostringstream out;
    for (const std::string &c : manifest.columns) out << c << ",";
    out << "diag_outer_coverage\n";
    int k = 0;
    const int every = int(manifest.rows.size()) / std::max(odd, 1);
    for (const ManifestRow &row : manifest.rows) {
        const std::string id = row.get("id");
        const bool isOdd = k % every == 0 && k / every < odd;
        // Unit-variance scatter independent of the residual (a fixed sequence: the same everywhere).
        const double scatter = std::sqrt(2.0) * std::sin(2.3999 * double(k + 1) + 0.7);
        double coverage = 0.985 + 0.006 * (track * (residual[id] - mean) / sd + std::sqrt(1 - track * track) * scatter);
        for (const std::string &c : manifest.columns) {
            std::string v = row.get(c);
            if (c == "mu_ref" && isOdd) {
                double ref = 0;
                EXPECT_TRUE(parseNumber(v, &ref));
                v = numberText("%.5f", ref + shift);
            }
            out << v << ",";
        }
        if (isOdd) {
            coverage = 0.60 + 0.10 * double(k / every) / double(std::max(odd - 1, 1));
            oddIds->push_back(id);
        }
        out << numberText("%.4f", coverage) << "\n";
        ++k;
    }
    std::ofstream(manifestPath) << out.str();
    return runLoop(manifestPath, (*dir / "report").string(), "paper", options(), kSweep);
}

const RecordFinding *findingOn(const LoopSummary &s, const std::string &candidate)
{
    for (const RecordFinding &f : s.carried)
        if (f.candidate == candidate) return &f;
    return nullptr;
}

} // namespace

// One image far off in a diagnostic, with a residual ten times the reference's scatter: the
// diagnostic's regression is significant over the family with it and nothing without it.
TEST(LoopInfluence, OneRecordThatCarriesADiagnosticIsNamedNotAdded)
{
    fs::path dir;
    std::vector<std::string> odd;
    const LoopSummary s = runWithExcursion("one", 3, 1, 0.03, 0.25, &dir, &odd);
    ASSERT_EQ(odd.size(), 1u);
    for (const LoopEffectStep &e : s.effects) EXPECT_NE(e.name, "diag_outer_coverage") << "added as " << e.reading;
    EXPECT_TRUE(s.effects.empty()) << "added " << s.effects.front().name;
    const RecordFinding *f = findingOn(s, "diag_outer_coverage");
    ASSERT_NE(f, nullptr) << "the record that carries the diagnostic is not named";
    EXPECT_GT(f->z, f->zFamily) << "the excursion did not make the diagnostic significant: the test shows nothing";
    EXPECT_LT(f->zWithout, f->zFamily);
    ASSERT_EQ(f->records.size(), 1u);
    EXPECT_EQ(f->records[0].id, odd[0]);
    EXPECT_LT(f->records[0].residual, -0.02);
    EXPECT_EQ(f->records[0].value, "0.6");
    const std::string report = readText(dir / "report" / "report.md");
    EXPECT_NE(report.find("## Records that carry an effect"), std::string::npos);
    EXPECT_NE(report.find("| " + odd[0] + " |"), std::string::npos);
    const std::string ranking = readText(dir / "report" / "ranking.csv");
    EXPECT_NE(ranking.find(",diag_outer_coverage,"), std::string::npos);
    EXPECT_NE(ranking.find("," + odd[0] + ","), std::string::npos);
    fs::remove_all(dir);
}

// The same excursion on eight records across the run (the diagnostic tracks a fault several images share):
// the records carry the effect, the influence check leaves it standing, and it is added.
TEST(LoopInfluence, AnEffectSeveralRecordsCarryIsStillAdded)
{
    fs::path dir;
    std::vector<std::string> odd;
    const LoopSummary s = runWithExcursion("several", 3, 8, 0.012, 0.25, &dir, &odd);
    ASSERT_FALSE(s.effects.empty()) << "nothing added; stopped: " << s.stopped;
    EXPECT_EQ(s.effects.front().name, "diag_outer_coverage");
    EXPECT_EQ(s.effects.front().reading, "patch");
    EXPECT_EQ(findingOn(s, "diag_outer_coverage"), nullptr);
    ASSERT_FALSE(s.ranking.empty());
    const RankedCandidate &lead = s.ranking.front();
    ASSERT_EQ(lead.influential.size(), 1u);
    EXPECT_GT(lead.zWithout, lead.zFamily);
    EXPECT_FALSE(lead.carried);
    fs::remove_all(dir);
}
