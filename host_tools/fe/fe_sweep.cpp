#include "host_tools/fe/fe_sweep.h"

#include <iostream>
#include <memory>
#include <set>
#include <stdexcept>

#include "host_tools/fe/fe_local_executor.h"
#include "host_tools/fe/fe_slurm_executor.h"
#include "host_tools/fe/fe_slurm_options.h"
#include "host_tools/fe/fe_sweep_csv.h"

namespace icacam::host::fe {

bool setSweepOption(SweepOptions &o, const std::string &key, const std::string &value)
{
    if (key == "executor") {
        if (value != "local" && value != "slurm")
            throw std::runtime_error("--executor: local or slurm, not '" + value + "'");
        o.executor = value;
    } else if (key == "resubmit-failed")
        o.resubmitFailed = value != "0";
    else if (key == "cancel")
        o.cancel = value != "0";
    else if (key == "slurm-config")
        o.slurmConfig = value;
    else if (isSlurmKey(key))
        o.slurm[key] = value;
    else
        return false;
    return true;
}

namespace {
// The labels a case's rows may carry: its own, or after the runner's retry with the fallback
// stick slope (which enters the label) the retried case's.
std::vector<std::string> rowLabels(const FeCase &c, const RunOptions &run)
{
    std::vector<std::string> l{c.label()};
    if (run.fallbackStickSlope > 0 && run.fallbackStickSlope < c.stickSlope) {
        FeCase retried = c;
        retried.stickSlope = run.fallbackStickSlope;
        l.push_back(retried.label());
    }
    return l;
}

// The grid's cases whose rows in csv say they did not solve: row label → what the solver said.
std::map<std::string, CaseStatus> failedCases(const std::vector<FeCase> &cases, const std::string &csv,
                                              const RunOptions &run)
{
    const auto st = caseStatuses(csv);
    std::map<std::string, CaseStatus> failed;
    for (const FeCase &c : cases)
        for (const std::string &label : rowLabels(c, run)) {
            const auto it = st.find(label);
            if (it != st.end() && it->second.status != "ok") failed[label] = it->second;
        }
    return failed;
}

bool hasRows(const FeCase &c, const RunOptions &run, const std::set<std::string> &done)
{
    for (const std::string &label : rowLabels(c, run))
        if (done.count(label)) return true;
    return false;
}
} // namespace

int runSweep(const std::vector<FeCase> &cases, const std::string &out, const RunOptions &run, const SweepOptions &o)
{
    std::unique_ptr<SweepExecutor> executor;
    SlurmExecutor *slurm = nullptr;
    if (o.executor == "slurm") {
        SlurmOptions so = slurmOptions(o.slurmConfig, o.slurm);
        // Beside the CSV: on the shared filesystem whenever the CSV is.
        if (so.dir.empty()) so.dir = out + ".slurm";
        auto s = std::make_unique<SlurmExecutor>(run, so);
        slurm = s.get();
        executor = std::move(s);
    } else {
        if (o.cancel || !o.slurm.empty() || !o.slurmConfig.empty())
            throw std::runtime_error("--cancel and the Slurm options need --executor slurm");
        executor = std::make_unique<LocalExecutor>(run, o.jobs);
    }
    if (o.cancel) {
        slurm->cancel();
        return 0;
    }
    if (slurm) slurm->lockDirectory(); // before the CSV or the results are touched
    if (o.resubmitFailed) {
        std::set<std::string> again;
        for (const auto &[label, st] : failedCases(cases, out, run)) again.insert(label);
        dropCases(out, again);
        if (slurm)
            for (const FeCase &c : cases)
                if (hasRows(c, run, again)) slurm->forget(c);
        std::cout << "sweep: " << again.size() << " failed cases taken out of " << out << " to run again\n";
    }
    const auto done = casesIn(out);
    std::vector<FeCase> todo;
    size_t unsolved = 0;
    for (const FeCase &c : cases) {
        if (hasRows(c, run, done)) continue;
        if (run.reuseOnly && !hasReusableResults(c, run)) {
            ++unsolved;
            continue;
        }
        todo.push_back(c);
    }
    std::cout << "sweep: " << cases.size() << " cases, " << cases.size() - todo.size() - unsolved << " already in "
              << out << ", " << todo.size() << " to run";
    if (run.reuseOnly) std::cout << " (post-processing only; " << unsolved << " without results left out)";
    std::cout << "\n";
    const size_t lost = executor->solve(todo, [&](const SolvedCase &s) { appendRows(out, s.rows); });
    if (slurm) {
        const auto failed = failedCases(cases, out, run);
        for (const auto &[label, st] : failed)
            std::cout << "failed: " << label << ": " << st.status << (st.message.empty() ? "" : ": " + st.message)
                      << "\n";
        if (!failed.empty())
            std::cout << "sweep: " << failed.size() << " failed cases in " << out
                      << "; --resubmit-failed 1 runs them again (only them)\n";
    }
    return lost ? 1 : 0;
}

} // namespace icacam::host::fe
