#include "score_command.h"

#include <iostream>
#include <stdexcept>

#include "coverage_score.h"
#include "manifest.h"

namespace icacam::host {

namespace {
const char *kUsage =
    "usage: icacam score --results FILE --truth FILE [--tolerance ABS[,REL]] [--k K]\n"
    "                    [--model-sigma auto|keep|drop] [--markdown]\n"
    "Per condition (the truth's 'condition' column; one line without it): records measured,\n"
    "status ok, silent wrong answers (ok with |dmu| > max(ABS, REL * mu); default 0.01,0.05),\n"
    "the fraction within K sigma (default 2), the median |dmu|/sigma and |dmu|, the worst dmu.\n"
    "sigma: mu_sigma; with the budget columns and a paper model measured against the paper's\n"
    "truth, sqrt(mu_sigma^2 - sigma_model^2) (--model-sigma auto; keep or drop to force).\n"
    "See docs/uncertainty.md.\n";
}

int scoreCommand(const std::vector<std::string> &args)
{
    std::string resultsPath, truthPath;
    ScoreOptions opt;
    bool markdown = false;
    for (size_t i = 0; i < args.size(); ++i) {
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) throw std::runtime_error(args[i] + " needs a value");
            return args[++i];
        };
        if (args[i] == "--results") resultsPath = value();
        else if (args[i] == "--truth") truthPath = value();
        else if (args[i] == "--markdown") markdown = true;
        else if (args[i] == "--k") {
            if (!parseNumber(value(), &opt.k) || !(opt.k > 0)) throw std::runtime_error("--k needs a positive number");
        } else if (args[i] == "--tolerance") {
            const std::string v = value();
            const size_t comma = v.find(',');
            if (!parseNumber(v.substr(0, comma), &opt.toleranceAbs) || opt.toleranceAbs < 0 ||
                (comma != std::string::npos && (!parseNumber(v.substr(comma + 1), &opt.toleranceRel) || opt.toleranceRel < 0)))
                throw std::runtime_error("--tolerance needs ABS or ABS,REL (non-negative numbers)");
        } else if (args[i] == "--model-sigma") {
            const std::string v = value();
            if (v == "auto") opt.modelSigma = ModelSigma::Auto;
            else if (v == "keep") opt.modelSigma = ModelSigma::Keep;
            else if (v == "drop") opt.modelSigma = ModelSigma::Drop;
            else throw std::runtime_error("--model-sigma: auto, keep or drop");
        } else if (args[i] == "-h" || args[i] == "--help") { std::cout << kUsage; return 0; }
        else throw std::runtime_error("unknown option '" + args[i] + "'\n" + kUsage);
    }
    if (resultsPath.empty() || truthPath.empty())
        throw std::runtime_error(std::string("--results and --truth are required\n") + kUsage);
    Manifest results, truth;
    std::string err;
    if (!readManifest(resultsPath, &results, &err)) throw std::runtime_error("--results: " + err);
    if (!readManifest(truthPath, &truth, &err)) throw std::runtime_error("--truth: " + err);
    ScoreReport report;
    if (!scoreResults(results, truth, opt, &report, &err)) throw std::runtime_error(err);
    std::cout << formatScore(report, opt, markdown);
    for (const std::string &n : report.notes) std::cerr << "icacam score: " << n << "\n";
    return 0;
}

} // namespace icacam::host
