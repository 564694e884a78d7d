#include "host_tools/score_command.h"

#include <iostream>
#include <stdexcept>

#include "host_tools/cli_options.h"
#include "host_tools/coverage_score.h"
#include "host_tools/manifest.h"
#include "host_tools/number_text.h"
#include "host_tools/score_comparison.h"

namespace icacam::host {

namespace {
std::string usage()
{
    const ScoreOptions d;
    return "usage: icacam score --results FILE --truth FILE [--tolerance ABS[,REL]] [--k K]\n"
           "                    [--model-sigma auto|keep|drop] [--markdown] [--against FILE]\n"
           "Per condition (the truth's 'condition' column; one line without it): records measured,\n"
           "status ok, silent wrong answers (ok with |dmu| > max(ABS, REL * mu); default " +
           numberText("%g", d.toleranceAbs) + "," + numberText("%g", d.toleranceRel) +
           "),\nthe fraction within K sigma (default " + numberText("%g", d.k) +
           "), the median |dmu|/sigma and |dmu|, the worst dmu.\n"
           "sigma: mu_sigma; with the budget columns and a paper model measured against the paper's\n"
           "truth, sqrt(mu_sigma^2 - sigma_model^2) (--model-sigma auto, the default; keep or drop to\n"
           "force). --markdown: the table as Markdown.\n"
           "--against FILE: an earlier run of the same records (another firmware, model, calibration\n"
           "or pipeline): the readings whose status, mu or flags differ, each run's dmu and whether it\n"
           "is right, and both runs' counts (measured, right, ok on right, silent wrong).\n"
           "See docs/uncertainty.md.\n";
}
} // namespace

int scoreCommand(const std::vector<std::string> &args)
{
    std::string resultsPath, truthPath, againstPath;
    ScoreOptions opt;
    bool markdown = false;
    cli::OptionReader opts(args, usage());
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << usage();
            return 0;
        } else if (opts.is("--results"))
            resultsPath = opts.value();
        else if (opts.is("--truth"))
            truthPath = opts.value();
        else if (opts.is("--against"))
            againstPath = opts.value();
        else if (opts.is("--markdown"))
            markdown = opts.flag();
        else if (opts.is("--k")) {
            opt.k = opts.number();
            if (!(opt.k > 0)) opts.fail("a positive number");
        } else if (opts.is("--tolerance")) {
            const std::string v = opts.value();
            const size_t comma = v.find(',');
            if (!cli::parseFinite(v.substr(0, comma), &opt.toleranceAbs) || opt.toleranceAbs < 0 ||
                (comma != std::string::npos &&
                 (!cli::parseFinite(v.substr(comma + 1), &opt.toleranceRel) || opt.toleranceRel < 0)))
                opts.fail("ABS or ABS,REL (non-negative numbers), not '" + v + "'");
        } else if (opts.is("--model-sigma")) {
            const std::string v = opts.value();
            if (v == "auto")
                opt.modelSigma = ModelSigma::Auto;
            else if (v == "keep")
                opt.modelSigma = ModelSigma::Keep;
            else if (v == "drop")
                opt.modelSigma = ModelSigma::Drop;
            else
                opts.fail("auto, keep or drop, not '" + v + "'");
        } else
            opts.unknown();
    }
    if (resultsPath.empty() || truthPath.empty()) opts.missing("--results and --truth (both are needed)");
    Manifest results, truth;
    std::string err;
    if (!readManifest(resultsPath, &results, &err)) throw std::runtime_error("--results: " + err);
    if (!readManifest(truthPath, &truth, &err)) throw std::runtime_error("--truth: " + err);
    ScoreReport report;
    if (!scoreResults(results, truth, opt, &report, &err)) throw std::runtime_error(err);
    std::cout << formatScore(report, opt, markdown);
    for (const std::string &n : report.notes) std::cerr << "icacam score: " << n << "\n";
    if (!againstPath.empty()) {
        Manifest before;
        if (!readManifest(againstPath, &before, &err)) throw std::runtime_error("--against: " + err);
        ComparisonReport cmp;
        if (!compareResults(before, results, truth, opt, &cmp, &err))
            throw std::runtime_error("--against (before) and --results (after): " + err);
        std::cout << "\nagainst " << againstPath << ": " << formatComparison(cmp);
    }
    return 0;
}

} // namespace icacam::host
