// icacam loop on radii record sets carrying several hidden effects at once (`icacam synth
// --effect camera,material --radii`, host_tools/synth_loop_set.h): the loop must add every
// true effect, each in its physical form, and no other, in at least 9 runs of 10, and the
// estimates it states (fitted together) must lie within their stated uncertainty of the truth
// the generator wrote (truth.csv).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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
#include "host_tools/synth_loop_set.h"
#include "tests/support/table_inputs.h"

namespace fs = std::filesystem;
using namespace icacam::host;
using namespace icacam::host::loop;

namespace {

const std::vector<std::string> kSweep = icacam::test::repositoryPaths(icacam::friction::reduction_table::kFeSources);

struct SetRun {
    LoopSummary summary;
    Manifest truth, manifest, records; // truth.csv, manifest.csv and the report's records.csv
};

// Writes the set, lets `edit` change its manifest's text (a confounded column), runs the loop.
template <typename Edit> SetRun runSet(const std::string &name, LoopEffect effects, uint32_t seed, Edit edit)
{
    // One directory per process: other worktrees run the same suite at the same time.
    const fs::path dir = fs::temp_directory_path() / ("icacam_loop_several_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    LoopSetOptions opt;
    opt.effect = effects;
    opt.seed = seed;
    opt.count = 60;
    opt.radii = true;
    const std::string manifest = writeLoopSet(dir.string(), opt);
    std::string text;
    {
        std::ifstream f(manifest);
        text.assign(std::istreambuf_iterator<char>(f), {});
    }
    edit(text);
    std::ofstream(manifest) << text;
    RankingOptions ro;
    ro.folds = 5;
    ro.seed = 1;
    SetRun run;
    run.summary = runLoop(manifest, (dir / "report").string(), "paper", ro, kSweep);
    std::string err;
    EXPECT_TRUE(readManifest((dir / "truth.csv").string(), &run.truth, &err)) << err;
    EXPECT_TRUE(readManifest(manifest, &run.manifest, &err)) << err;
    EXPECT_TRUE(readManifest((dir / "report" / "records.csv").string(), &run.records, &err)) << err;
    fs::remove_all(dir);
    return run;
}

SetRun runSet(const std::string &name, LoopEffect effects, uint32_t seed)
{
    return runSet(name, effects, seed, [](std::string &) {});
}

// The candidate and reading each hidden effect must be added as.
struct Expected {
    LoopEffect effect;
    const char *candidate;
    const char *reading;
};
constexpr Expected kExpected[] = {{LoopEffect::Camera, "camera_id", "scale"},
                                  {LoopEffect::Material, "material", "n"},
                                  {LoopEffect::Speed, "press_speed_mm_s", "process"},
                                  {LoopEffect::Drift, "sequence", "drift"},
                                  {LoopEffect::Optical, "lens", "scale"},
                                  {LoopEffect::SpeedInMaterial, "press_speed_mm_s_by_material", "process"}};

// Every true effect added in its physical form, and nothing else.
bool foundExactly(const LoopSummary &s, LoopEffect effects, std::string *what)
{
    int found = 0, wanted = 0;
    for (const Expected &e : kExpected) {
        if (!has(effects, e.effect)) continue;
        ++wanted;
        for (const LoopEffectStep &step : s.effects)
            if (step.name == e.candidate && step.reading == e.reading) ++found;
    }
    for (const LoopEffectStep &step : s.effects) *what += step.name + " (" + step.reading + ") ";
    return found == wanted && int(s.effects.size()) == wanted;
}

// The truth per level: the first record's `column` among those with `key` == level.
std::map<std::string, double> truthBy(const Manifest &truth, const std::string &key, const std::string &column)
{
    std::map<std::string, double> out;
    for (const ManifestRow &r : truth.rows) {
        double v;
        if (parseNumber(r.get(column), &v)) out.emplace(r.get(key), v);
    }
    return out;
}

double number(const ManifestRow &row, const std::string &column)
{
    double v = NAN;
    parseNumber(row.get(column), &v);
    return v;
}

// The μ a hidden effect adds to each record (truth.csv), for those the generator writes.
const char *shiftColumn(LoopEffect e)
{
    return e == LoopEffect::Camera                                      ? "mu_camera_shift"
           : e == LoopEffect::Drift                                     ? "mu_drift_shift"
           : e == LoopEffect::Material                                  ? "mu_n_shift"
           : e == LoopEffect::SpeedInMaterial || e == LoopEffect::Speed ? "mu_speed_shift"
                                                                        : nullptr;
}

// What the records can show of one hidden effect: the nested F test's z (Wilson–Hilferty) of its
// plain form (a value per camera or material; a line in the sequence; a line in ln v, within the
// speed-sensitive material for SpeedInMaterial) on the run's residual with every other hidden
// effect's μ taken out exactly. Below the family's critical z no procedure shows it on these
// records.
double zAlone(const SetRun &run, LoopEffect effects, LoopEffect e)
{
    const size_t n = run.records.rows.size();
    std::vector<double> y(n);
    for (size_t i = 0; i < n; ++i) {
        y[i] = number(run.records.rows[i], "residual");
        for (const Expected &other : kExpected)
            if (has(effects, other.effect) && other.effect != e && shiftColumn(other.effect))
                y[i] -= number(run.truth.rows[i], shiftColumn(other.effect));
    }
    double mean = 0;
    for (double v : y) mean += v / double(n);
    double sse0 = 0, sse1 = 0;
    for (double v : y) sse0 += (v - mean) * (v - mean);
    int params = 2;
    if (e == LoopEffect::Camera || e == LoopEffect::Material) {
        const char *key = e == LoopEffect::Camera ? "camera_id" : "material";
        std::map<std::string, std::pair<double, int>> sums;
        for (size_t i = 0; i < n; ++i) {
            auto &[sum, count] = sums[run.truth.rows[i].get(key)];
            sum += y[i], ++count;
        }
        for (size_t i = 0; i < n; ++i) {
            const auto &[sum, count] = sums[run.truth.rows[i].get(key)];
            sse1 += (y[i] - sum / count) * (y[i] - sum / count);
        }
        params = int(sums.size());
    } else {
        // A rate acts about the run's typical speed (the mean of ln v), in the speed-sensitive
        // material only for SpeedInMaterial.
        std::vector<double> x(n);
        double typical = 0;
        for (size_t i = 0; i < n; ++i) {
            x[i] = e == LoopEffect::Drift ? number(run.manifest.rows[i], "sequence")
                                          : std::log(number(run.manifest.rows[i], "press_speed_mm_s"));
            typical += x[i] / double(n);
        }
        if (e == LoopEffect::SpeedInMaterial)
            for (size_t i = 0; i < n; ++i) x[i] = number(run.truth.rows[i], "speed_factor") != 1 ? x[i] - typical : 0;
        double mx = 0;
        for (double v : x) mx += v / double(n);
        double sxx = 0, sxy = 0;
        for (size_t i = 0; i < n; ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - mean);
        sse1 = sse0 - (sxx > 0 ? sxy * sxy / sxx : 0);
    }
    const double d1 = params - 1, d2 = double(n) - params;
    const double f = std::max(0.0, (sse0 - sse1) / d1) / (sse1 / d2), a = 2 / (9 * d1), b = 2 / (9 * d2);
    return ((1 - b) * std::cbrt(f) - (1 - a)) / std::sqrt(b * std::cbrt(f) * std::cbrt(f) + a);
}

struct Tally {
    int runs = 0, exact = 0, estimates = 0, withinU = 0;
    // Runs judged: those whose every hidden effect the records can show (zAlone over the family's
    // critical z), and those where the loop added exactly the hidden effects anyway.
    int judged = 0;
    int falseAdded = 0; // runs with an effect added that is not hidden
};

// The camera factors and materials' n the run states against the truth (k = 2).
void checkEstimates(const SetRun &run, Tally *t)
{
    const auto cameraTruth = truthBy(run.truth, "camera_id", "camera_error");
    const auto nTruth = truthBy(run.truth, "material", "n_true");
    for (const LoopEffectStep &e : run.summary.effects) {
        if (e.reading != "scale" && e.reading != "n") continue;
        for (const GroupFit &g : e.grouping.groups) {
            const auto &truth = e.reading == "scale" ? cameraTruth : nTruth;
            const auto it = truth.find(g.level);
            if (e.name != (e.reading == "scale" ? "camera_id" : "material") || it == truth.end()) continue;
            const double value = e.reading == "scale" ? 1 + it->second : it->second;
            ++t->estimates;
            t->withinU += std::fabs(g.value - value) <= 2 * g.sigma;
            if (std::fabs(g.value - value) > 2 * g.sigma)
                std::printf("  %s %s %.4f +- %.4f, truth %.4f\n", e.name.c_str(), g.level.c_str(), g.value, 2 * g.sigma,
                            value);
        }
    }
}

Tally runSeeds(const std::string &name, LoopEffect effects, uint32_t first, uint32_t last)
{
    Tally t;
    for (uint32_t seed = first; seed <= last; ++seed) {
        const SetRun run = runSet(name, effects, seed);
        std::string what;
        const bool exact = foundExactly(run.summary, effects, &what);
        std::printf("%s seed %u: %s%s\n", name.c_str(), seed, what.c_str(), exact ? "" : " <- not exactly the truth");
        ++t.runs;
        t.exact += exact;
        const double zFamily = run.summary.lastRanking.empty() ? run.summary.ranking.front().zFamily
                                                               : run.summary.lastRanking.front().zFamily;
        bool shown = true;
        for (const Expected &e : kExpected)
            if (has(effects, e.effect) && shiftColumn(e.effect)) {
                const double z = zAlone(run, effects, e.effect);
                if (z < zFamily) std::printf("  %s: z alone %.1f, the family's %.1f\n", e.candidate, z, zFamily);
                shown = shown && z >= zFamily;
            }
        t.judged += shown || exact;
        int added = 0;
        for (const LoopEffectStep &step : run.summary.effects)
            for (const Expected &e : kExpected)
                added += has(effects, e.effect) && step.name == e.candidate && step.reading == e.reading;
        t.falseAdded += added < int(run.summary.effects.size());
        checkEstimates(run, &t);
        // The held-out error falls with every effect added.
        for (const LoopEffectStep &e : run.summary.effects) EXPECT_LT(e.cvRmsAfter, e.cvRmsBefore) << e.name;
    }
    std::printf("%s: exactly the true effects in %d of %d runs (%d judged: the records can show every effect, or "
                "it was found); a false one in %d; %d of %d estimates within U\n",
                name.c_str(), t.exact, t.runs, t.judged, t.falseAdded, t.withinU, t.estimates);
    return t;
}

} // namespace

// The line the loop holds on several effects at once: in at least 9 of 10 of the runs judged
// (every hidden effect shown by the records, zAlone over the family's critical z, or found)
// exactly the hidden effects are added, each in its physical form; a false one in at most 1 run
// of 10; and most runs are judged (the sets are not too weak to test anything).
void expectTheLine(const Tally &t)
{
    EXPECT_GE(t.exact, 0.9 * t.judged);
    EXPECT_LE(t.falseAdded, t.runs / 10);
    EXPECT_GE(t.judged, 0.7 * t.runs);
}

TEST(LoopSeveral, CameraAndMaterialEachInItsPhysicalForm)
{
    const Tally t = runSeeds("camera_material", LoopEffect::Camera | LoopEffect::Material, 1, 10);
    expectTheLine(t);
    EXPECT_GE(t.exact, 9); // of every run, not only those judged: the outline shows a stale camera
    EXPECT_GE(t.withinU, 0.9 * t.estimates);
    EXPECT_GE(t.estimates, 60); // three cameras and four materials in (nearly) every run
}

TEST(LoopSeveral, ThreeEffectsAtOnce)
{
    const Tally t = runSeeds("three", LoopEffect::Camera | LoopEffect::Material | LoopEffect::Speed, 1, 10);
    expectTheLine(t);
    EXPECT_GE(t.exact, 9);
    EXPECT_GE(t.withinU, 0.9 * t.estimates);
}

TEST(LoopSeveral, MaterialAndAScaleDriftingAlongTheRun)
{
    const Tally t = runSeeds("material_drift", LoopEffect::Material | LoopEffect::Drift, 1, 10);
    expectTheLine(t);
    EXPECT_GE(t.exact, 9);
    EXPECT_GE(t.withinU, 0.9 * t.estimates);
}

TEST(LoopSeveral, CameraAndAScaleDriftingAlongTheRun)
{
    expectTheLine(runSeeds("drift_camera", LoopEffect::Drift | LoopEffect::Camera, 1, 10));
}

// Below the line (docs/loop.md: the speed's slope in a material whose n is also off is missed in
// some runs the records could show it in): nothing false is added.
TEST(LoopSeveral, CameraMaterialAndSpeedWithinOneMaterialAddNothingFalse)
{
    const Tally t = runSeeds("camera_material_speed_material",
                             LoopEffect::Camera | LoopEffect::Material | LoopEffect::SpeedInMaterial, 1, 10);
    EXPECT_LE(t.falseAdded, t.runs / 10);
    EXPECT_GE(t.withinU, 0.9 * t.estimates);
}

// A press speed acting within one material only is a slope of that material, not the material.
TEST(LoopSeveral, SpeedWithinOneMaterialIsNotReadAsTheMaterial)
{
    const Tally t = runSeeds("speed_material", LoopEffect::SpeedInMaterial, 1, 10);
    expectTheLine(t);
    EXPECT_GE(t.exact, 9);
}

// Every column of the manifest's text through `cell(header, cells)`.
template <typename Cell> void editCells(std::string &text, Cell cell)
{
    std::istringstream in(text);
    std::string line, out;
    std::vector<std::string> header;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream cs(line);
        for (std::string c; std::getline(cs, c, ',');) cells.push_back(c);
        if (header.empty())
            header = cells;
        else
            cell(header, cells);
        std::string joined;
        for (size_t i = 0; i < cells.size(); ++i) joined += (i ? "," : "") + cells[i];
        out += joined + "\n";
    }
    text = out;
}

size_t columnOf(const std::vector<std::string> &header, const std::string &name)
{
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return i;
    return header.size();
}

// Records without the barrel's outline (r_bulge_mm left empty): μ's residual alone.
void withoutOutline(std::string &text)
{
    editCells(text, [](const std::vector<std::string> &header, std::vector<std::string> &cells) {
        cells[columnOf(header, "r_bulge_mm")].clear();
    });
}

// A camera 4 % off whose records' μ alone cannot show it (seeds 8 and 10 of camera,material: z
// alone 2.2 and 2.3 against the family's 3.6): the barrel's outline, 4 % large on that camera's
// records only, witnesses the factor, μ's held-out error confirms it, and both effects are added.
TEST(LoopSeveral, AStaleCameraTheOutlineWitnessesIsAddedWhereMuAloneCannotShowIt)
{
    for (uint32_t seed : {8u, 10u}) {
        const SetRun alone = runSet("mu_alone", LoopEffect::Camera | LoopEffect::Material, seed, withoutOutline);
        std::string what;
        std::printf("seed %u, μ alone: %s\n", seed,
                    foundExactly(alone.summary, LoopEffect::Camera | LoopEffect::Material, &what) ? "exact"
                                                                                                  : what.c_str());
        const SetRun run = runSet("witnessed", LoopEffect::Camera | LoopEffect::Material, seed);
        what.clear();
        EXPECT_TRUE(foundExactly(run.summary, LoopEffect::Camera | LoopEffect::Material, &what))
            << "seed " << seed << ": " << what;
    }
}

// A camera whose outlines read 2 % small while its lengths are right (a camera closer to the
// specimen sees the barrel's side from nearer; a shadow taken for the outline): the outline
// tells that camera apart, but μ's held-out error does not confirm a length factor, and nothing
// is added to a set with no hidden effect.
TEST(LoopSeveral, AnOutlineTheScaleDoesNotExplainIsNotReadAsACamerasFactor)
{
    int added = 0;
    for (uint32_t seed = 1; seed <= 5; ++seed) {
        const SetRun run = runSet("outline_only", LoopEffect::Null, seed, [](std::string &text) {
            editCells(text, [](const std::vector<std::string> &header, std::vector<std::string> &cells) {
                if (cells[columnOf(header, "camera_id")] != "cam-2") return;
                std::string &bulge = cells[columnOf(header, "r_bulge_mm")];
                char buf[32];
                std::snprintf(buf, sizeof buf, "%.5f", std::stod(bulge) * 0.98);
                bulge = buf;
            });
        });
        for (const LoopEffectStep &e : run.summary.effects) std::printf("seed %u: added %s\n", seed, e.name.c_str());
        added += !run.summary.effects.empty();
    }
    EXPECT_EQ(added, 0);
}

// A camera and a speed within one material that hide each other in μ's residual (seed 26 of the
// set, records without the outline, which would show the camera on its own: neither is
// significant over the family alone): the leading cause is taken out, the camera is then
// significant, and the speed is with the camera taken out; both are added.
TEST(LoopSeveral, TwoEffectsThatHideEachOtherAreBothAdded)
{
    const SetRun run = runSet("masking", LoopEffect::Camera | LoopEffect::SpeedInMaterial, 26, withoutOutline);
    std::string what;
    EXPECT_TRUE(foundExactly(run.summary, LoopEffect::Camera | LoopEffect::SpeedInMaterial, &what)) << what;
    ASSERT_FALSE(run.summary.effects.empty());
    EXPECT_EQ(run.summary.effects.front().given, "camera_id");
}

// The drift alone: read as a length factor moving along the sequence, rising by the
// generator's 8 % over the run within the stated U (k = 2) in at least 8 runs of 10.
TEST(LoopSeveral, DriftReadAsAMovingLengthFactor)
{
    int within = 0;
    for (uint32_t seed = 1; seed <= 10; ++seed) {
        const SetRun run = runSet("drift" + std::to_string(seed), LoopEffect::Drift, seed);
        const LoopSummary &s = run.summary;
        ASSERT_EQ(s.effects.size(), 1u) << "seed " << seed;
        EXPECT_EQ(s.chosen, "sequence");
        EXPECT_EQ(s.reading, "drift");
        EXPECT_TRUE(s.drift.drifts());
        const double rise = s.drift.endFactor / s.drift.startFactor - 1;
        const double u = 2 * s.drift.slopeSigma * (s.drift.xMax - s.drift.xMin);
        std::printf("drift seed %u: rise %.4f +- %.4f (k=2), truth %.2f\n", seed, rise, u, kDriftScaleError);
        within += std::fabs(rise - kDriftScaleError) <= u;
    }
    EXPECT_GE(within, 8);
}

// A camera always used with one lens: the two columns group the records the same way, so the
// records cannot tell which it is. One is added, the other named as inseparable from it.
TEST(LoopSeveral, ConfoundedCameraAndLensNamedAsInseparable)
{
    const SetRun run = runSet("confounded", LoopEffect::Camera, 1, [](std::string &text) {
        editCells(text, [](const std::vector<std::string> &header, std::vector<std::string> &cells) {
            cells[columnOf(header, "lens")] = "L-" + cells[columnOf(header, "camera_id")];
        });
    });
    const LoopSummary &s = run.summary;
    ASSERT_EQ(s.effects.size(), 1u);
    const LoopEffectStep &e = s.effects.front();
    EXPECT_TRUE(e.name == "camera_id" || e.name == "lens") << e.name;
    EXPECT_EQ(e.reading, "scale");
    ASSERT_EQ(e.inseparable.size(), 1u);
    EXPECT_EQ(e.inseparable.front(), e.name == "camera_id" ? "lens" : "camera_id");
}

TEST(LoopSeveral, DatesAreDayNumbers)
{
    EXPECT_EQ(dayNumber("1970-01-01"), 0);
    EXPECT_EQ(dayNumber("2000-02-29"), 11016);
    EXPECT_EQ(dayNumber("2026-11-26"), 20783);
    EXPECT_EQ(dayNumber("2026-11-26T08:15"), 20783);
    EXPECT_TRUE(std::isnan(dayNumber("cam-1")));
    EXPECT_TRUE(std::isnan(dayNumber("2026-13-01")));
}

TEST(LoopSeveral, EffectNamesParseAsAList)
{
    LoopEffect e = LoopEffect::Null;
    ASSERT_TRUE(parseLoopEffect("camera,material", &e));
    EXPECT_TRUE(has(e, LoopEffect::Camera) && has(e, LoopEffect::Material) && !has(e, LoopEffect::Speed));
    EXPECT_EQ(loopEffectNames(e), "camera+material");
    EXPECT_FALSE(parseLoopEffect("camera,lens", &e));
    ASSERT_TRUE(parseLoopEffect("null", &e));
    EXPECT_EQ(e, LoopEffect::Null);
}
