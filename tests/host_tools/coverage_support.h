#pragma once
// Shared by the coverage and photograph tests: render a condition set with `icacam synth`,
// measure it with `icacam measure` as a user would, and score it with `icacam score`'s code.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "host_tools/coverage_score.h"
#include "host_tools/manifest.h"
#include "host_tools/measure_command.h"
#include "host_tools/synth_conditions.h"
#include "tests/host_tools/test_support.h"

namespace icacam::test {

struct ScoredSet {
    std::filesystem::path dir;
    host::Manifest results, truth, manifest;
    host::ScoreReport report;
};

// Adds the columns `declare` (name, value) to every row of a rendered manifest: what the lab
// tells the instrument beyond what `icacam synth` writes.
inline void declareColumns(const std::string &manifest, const std::vector<std::pair<std::string, std::string>> &declare)
{
    std::ifstream in(manifest);
    std::string text, line;
    for (bool header = true; std::getline(in, line); header = false) {
        for (const auto &[name, value] : declare) line += "," + (header ? name : value);
        text += line + "\n";
    }
    in.close();
    std::ofstream(manifest) << text;
}

// Measures a rendered set's manifest with the given `icacam measure` arguments (default model
// unless --model is among them), as a user would, and scores it with `icacam score`'s code.
inline ScoredSet measureAndScore(const std::filesystem::path &dir, const std::string &manifest,
                                 const std::vector<std::string> &measureArgs = {})
{
    ScoredSet s;
    s.dir = dir;
    const std::string results = (dir / "results.csv").string();
    std::vector<std::string> args{"--manifest", manifest, "--out", results};
    args.insert(args.end(), measureArgs.begin(), measureArgs.end());
    testing::internal::CaptureStderr();
    host::measureCommand(args);
    testing::internal::GetCapturedStderr();
    std::string err;
    EXPECT_TRUE(host::readManifest(results, &s.results, &err)) << err;
    EXPECT_TRUE(host::readManifest((dir / "truth.csv").string(), &s.truth, &err)) << err;
    EXPECT_TRUE(host::readManifest(manifest, &s.manifest, &err)) << err;
    EXPECT_TRUE(host::scoreResults(s.results, s.truth, host::ScoreOptions{}, &s.report, &err)) << err;
    std::cout << host::formatScore(s.report, host::ScoreOptions{}, false);
    return s;
}

// Renders `count` records of each condition (seeded), then measures and scores them.
inline ScoredSet renderMeasureScore(const std::string &name, const std::string &conditions, int count, uint32_t seed,
                                    const std::vector<std::string> &measureArgs = {},
                                    const std::vector<std::pair<std::string, std::string>> &declare = {})
{
    const std::filesystem::path dir = tempDir(name);
    host::ConditionSetOptions opt;
    EXPECT_TRUE(host::parseConditions(conditions, &opt.conditions)) << conditions;
    opt.countPerCondition = count;
    opt.seed = seed;
    opt.quiet = true;
    const std::string manifest = host::writeConditionSet(dir.string(), opt);
    if (!declare.empty()) declareColumns(manifest, declare);
    return measureAndScore(dir, manifest, measureArgs);
}

} // namespace icacam::test
