#pragma once
// The sweep on a Slurm cluster: one job array per submission, one case per array task, each
// task writing its rows to <dir>/results/<case>.csv on the shared filesystem; the sweep
// gathers them as they appear. Restarted, it gathers results already there, waits for this
// sweep's tasks still in the queue and submits only the cases that have neither.
//
// <dir> (SlurmOptions::dir): results/ (one CSV per case), logs/<job>_<task>.log,
// jobs/<job>.sh and jobs/<job>.cases ("task<TAB>case" per line: what each submission ran).
#include <map>
#include <string>

#include "host_tools/fe/fe_executor.h"
#include "host_tools/fe/fe_runner.h"
#include "host_tools/fe/fe_slurm_options.h"

namespace icacam::host::fe {

class SlurmExecutor : public SweepExecutor {
public:
    SlurmExecutor(const RunOptions &run, const SlurmOptions &slurm);
    ~SlurmExecutor() override;
    SlurmExecutor(const SlurmExecutor &) = delete;
    SlurmExecutor &operator=(const SlurmExecutor &) = delete;
    // Makes this command the directory's one watcher (flock on <dir>/sweep.lock, held until
    // destruction); throws when another command watches it (both would gather the same
    // results into the CSV). solve() takes it too.
    void lockDirectory();
    size_t solve(const std::vector<FeCase> &cases, const GatherFn &gather) override;
    // scancel this sweep's tasks still in the queue (also while another command watches
    // them); returns how many there were.
    size_t cancel();
    // Moves a case's result aside (results/<case>.csv.old) so the case runs again.
    void forget(const FeCase &c) const;
    const std::string &dir() const { return dir_; }
    const std::string &jobName() const { return jobName_; }

private:
    struct Task {
        std::string jobId;
        int index = -1;
        FeCase c;
    };
    std::string resultsDir() const;
    std::map<std::string, std::string> submittedLabels() const; // "job_task" → case label
    std::vector<Task> submit(const std::vector<FeCase> &cases);
    bool gatherIfDone(const FeCase &c, const GatherFn &gather) const;
    std::string logTail(const Task &t) const;

    RunOptions run_;
    SlurmOptions slurm_;
    std::string dir_, jobName_;
    int lock_ = -1; // flock on <dir>/sweep.lock while this command watches the directory
};

} // namespace icacam::host::fe
