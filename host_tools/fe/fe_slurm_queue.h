#pragma once
// Slurm's own commands, run as they are installed (sbatch, squeue, sacct, scancel): the
// cluster's configuration and authentication are theirs (SLURM_CONF and munge included).
#include <map>
#include <string>
#include <vector>

namespace icacam::host::fe {

struct CommandOutput {
    int exitCode = -1; // -1: could not be run
    std::string text;  // stdout and stderr
};
CommandOutput runCommand(const std::vector<std::string> &argv);

// Submits a batch script with these sbatch options (--parsable added); returns the job id.
// Throws with sbatch's message when it refuses.
std::string submitBatch(const std::vector<std::string> &sbatchOptions, const std::string &script);

// One array task in the queue: "123" and 4 for 123_4, its state (PENDING, RUNNING, …) and reason.
struct QueuedTask {
    std::string jobId;
    int index = -1;
    std::string state, reason;
};
// The tasks of the jobs named jobName still in the queue (pending, running, completing, …),
// one per array element. ok is false when squeue did not answer (then tasks says nothing).
struct QueueView {
    bool ok = false;
    std::string error;
    std::vector<QueuedTask> tasks;
};
QueueView queuedTasks(const std::string &jobName);

// How an array task that left the queue ended: sacct's State and ExitCode where the cluster
// keeps accounting, else squeue's memory of finished jobs (MinJobAge), else "unknown".
std::string endedState(const std::string &jobId, int index);

// scancel of these jobs (every task of each array); returns scancel's message when it fails.
std::string cancelJobs(const std::vector<std::string> &jobIds);

} // namespace icacam::host::fe
