#pragma once
// How a sweep runs on Slurm: from `--key value` options of `icacam fe sweep`, or a config file
// of `key = value` lines with the same keys (options win over the file).
#include <map>
#include <string>

namespace icacam::host::fe {

struct SlurmOptions {
    std::string partition;   // sbatch --partition; empty: the cluster's default
    std::string timeLimit;   // sbatch --time per case (Slurm's formats, e.g. 30:00, 1-00:00:00)
    int cpusPerTask = 1;     // sbatch --cpus-per-task (ccx runs one thread: a reservation only)
    std::string sbatchExtra; // further sbatch options, split on blanks (e.g. --account=x --mem=2G)
    std::string setup;       // a shell line run before each case (e.g. module load calculix)
    std::string dir;         // shared directory of scripts, results and logs; empty: <CSV>.slurm
    std::string icacam;      // this program as the nodes see it; empty: this executable's path
    int arrayLimit = 0;      // > 0: at most this many tasks at once (--array=…%N)
    double pollS = 15;       // squeue every pollS while waiting
};

// Keys of the options and of the config file: partition, time, cpus-per-task, sbatch, setup,
// slurm-dir, icacam, array-limit, poll.
bool isSlurmKey(const std::string &key);

// The options from the config file (may be empty: none) overlaid by the options given.
// Throws on an unknown key or an unreadable file.
SlurmOptions slurmOptions(const std::string &configFile, const std::map<std::string, std::string> &given);

} // namespace icacam::host::fe
