#pragma once
// Two `icacam measure` runs of the same records, side by side against one truth: which
// readings differ (status, μ or flags, field for field) and the counts a change is judged by
// (measured, right, ok on right, silent wrong). For a lab, what a new firmware, model or
// calibration changed on its own reference specimens; for the pipeline's changes, the same
// on the rendered sets (docs/uncertainty.md, "Comparing two runs").
#include <string>
#include <vector>

#include "host_tools/coverage_score.h"
#include "host_tools/manifest.h"

namespace icacam::host {

// One run's reading of a record against the truth.
struct ReadingSide {
    bool present = false; // the run has a row for the record
    std::string status, mu, flags;
    double dmu = 0;     // measured − true (measured readings only)
    bool right = false; // measured and |Δμ| within the tolerance
};

struct ReadingChange {
    std::string id;
    ReadingSide before, after;
};

struct RunCounts {
    int measured = 0, right = 0, okRight = 0, silentWrong = 0;
};

struct ComparisonReport {
    int records = 0; // in the truth
    std::vector<ReadingChange> changed;
    RunCounts before, after;
};

// before, after: `icacam measure` CSVs (id, status, mu; flags where written); truth: id, mu.
// False with a message when a file lacks a column it needs.
bool compareResults(const Manifest &before, const Manifest &after, const Manifest &truth, const ScoreOptions &opt,
                    ComparisonReport *out, std::string *error);

// The changed readings, a line each, and the counts of both runs.
std::string formatComparison(const ComparisonReport &r);

} // namespace icacam::host
