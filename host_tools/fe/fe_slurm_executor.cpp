#include "host_tools/fe/fe_slurm_executor.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "host_tools/fe/fe_slurm_queue.h"
#include "host_tools/fe/fe_slurm_script.h"
#include "host_tools/fe/fe_sweep_csv.h"

namespace icacam::host::fe {

namespace fs = std::filesystem;

namespace {
// A name the cluster shows for every submission of this sweep directory (and only those).
std::string jobNameFor(const std::string &dir)
{
    unsigned long h = 1469598103934665603ul; // FNV-1a
    for (unsigned char ch : dir) h = (h ^ ch) * 1099511628211ul;
    char b[32];
    std::snprintf(b, sizeof b, "icacam-fe-%08lx", h & 0xffffffffu);
    return b;
}

std::vector<std::string> words(const std::string &s)
{
    std::vector<std::string> w;
    std::istringstream in(s);
    std::string x;
    while (in >> x) w.push_back(x);
    return w;
}

std::string elapsed(double s)
{
    char b[32];
    const int t = int(s);
    if (t >= 3600)
        std::snprintf(b, sizeof b, "%dh%02dm", t / 3600, t / 60 % 60);
    else
        std::snprintf(b, sizeof b, "%dm%02ds", t / 60, t % 60);
    return b;
}

std::string taskKey(const std::string &jobId, int index)
{
    return jobId + "_" + std::to_string(index);
}
} // namespace

SlurmExecutor::SlurmExecutor(const RunOptions &run, const SlurmOptions &slurm) : run_(run), slurm_(slurm)
{
    if (slurm_.dir.empty()) throw std::runtime_error("slurm: no sweep directory");
    dir_ = fs::weakly_canonical(fs::absolute(slurm_.dir)).string();
    jobName_ = jobNameFor(dir_);
    if (slurm_.icacam.empty()) slurm_.icacam = fs::read_symlink("/proc/self/exe").string();
    for (const char *sub : {"results", "logs", "jobs"}) fs::create_directories(fs::path(dir_) / sub);
}

void SlurmExecutor::lockDirectory()
{
    if (lock_ >= 0) return;
    const std::string lockFile = (fs::path(dir_) / "sweep.lock").string();
    lock_ = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock_ < 0) throw std::runtime_error("cannot open " + lockFile);
    if (::flock(lock_, LOCK_EX | LOCK_NB) != 0) {
        const int why = errno;
        if (why == EWOULDBLOCK) {
            ::close(lock_);
            lock_ = -1;
            throw std::runtime_error("another sweep command watches " + dir_ + " (" + lockFile + " is locked)");
        }
        // A filesystem without flock (some parallel filesystems): say so and go on unguarded.
        std::cout << "slurm: " << lockFile << " cannot be locked here (" << std::strerror(why)
                  << "): run one sweep command per directory at a time\n";
    }
}

SlurmExecutor::~SlurmExecutor()
{
    if (lock_ >= 0) ::close(lock_);
}

std::string SlurmExecutor::resultsDir() const
{
    return (fs::path(dir_) / "results").string();
}

std::map<std::string, std::string> SlurmExecutor::submittedLabels() const
{
    std::map<std::string, std::string> m;
    for (const auto &e : fs::directory_iterator(fs::path(dir_) / "jobs")) {
        if (e.path().extension() != ".cases") continue;
        const std::string job = e.path().stem().string();
        std::ifstream f(e.path());
        std::string line;
        while (std::getline(f, line)) {
            const auto tab = line.find('\t');
            if (tab != std::string::npos) m[job + "_" + line.substr(0, tab)] = line.substr(tab + 1);
        }
    }
    return m;
}

std::vector<SlurmExecutor::Task> SlurmExecutor::submit(const std::vector<FeCase> &cases)
{
    const fs::path jobs = fs::path(dir_) / "jobs";
    JobScript js{slurm_.icacam, slurm_.setup, resultsDir(), cases, run_};
    const fs::path script = jobs / "next.sh", list = jobs / "next.list";
    {
        std::ofstream f(script);
        f << jobScriptText(js);
        std::ofstream l(list);
        for (size_t i = 0; i < cases.size(); ++i) l << i << "\t" << cases[i].label() << "\n";
        if (!f || !l) throw std::runtime_error("cannot write " + jobs.string());
    }
    std::string array = "--array=0-" + std::to_string(cases.size() - 1);
    if (slurm_.arrayLimit > 0) array += "%" + std::to_string(slurm_.arrayLimit);
    std::vector<std::string> opts{
        "--job-name=" + jobName_, array,        "--output=" + (fs::path(dir_) / "logs" / "%A_%a.log").string(),
        "--chdir=" + dir_,        "--ntasks=1", "--cpus-per-task=" + std::to_string(slurm_.cpusPerTask)};
    if (!slurm_.partition.empty()) opts.push_back("--partition=" + slurm_.partition);
    if (!slurm_.timeLimit.empty()) opts.push_back("--time=" + slurm_.timeLimit);
    for (const auto &w : words(slurm_.sbatchExtra)) opts.push_back(w);
    const std::string job = submitBatch(opts, script.string());
    // The task → case list under the job's id: what a restarted sweep finds its tasks by.
    fs::rename(list, jobs / (job + ".cases"));
    fs::rename(script, jobs / (job + ".sh"));
    std::cout << "slurm: submitted job " << job << " (" << jobName_ << "): " << cases.size()
              << (cases.size() == 1 ? " case" : " cases") << ", array " << array.substr(8) << "; script "
              << (jobs / (job + ".sh")).string() << "\n";
    std::vector<Task> tasks;
    for (size_t i = 0; i < cases.size(); ++i) tasks.push_back({job, int(i), cases[i]});
    return tasks;
}

bool SlurmExecutor::gatherIfDone(const FeCase &c, const GatherFn &gather) const
{
    const std::string file = resultFile(resultsDir(), c);
    if (!fs::exists(file)) return false;
    SolvedCase s{c, readRows(file)};
    const auto st = caseStatuses(file);
    const auto it = st.begin();
    std::cout << c.label() << ": " << (it == st.end() ? "?" : it->second.status)
              << (it == st.end() || it->second.message.empty() ? "" : " (" + it->second.message + ")") << "\n";
    gather(s);
    return true;
}

std::string SlurmExecutor::logTail(const Task &t) const
{
    const fs::path log = fs::path(dir_) / "logs" / (taskKey(t.jobId, t.index) + ".log");
    std::ifstream f(log);
    std::string line, last;
    while (std::getline(f, line))
        if (!line.empty()) last = line;
    return f.is_open() ? log.string() + (last.empty() ? "" : ": " + last) : "no log";
}

size_t SlurmExecutor::solve(const std::vector<FeCase> &cases, const GatherFn &gather)
{
    lockDirectory();
    // 1. Results already on the shared filesystem (tasks that finished while no sweep
    // was watching): gathered, never run again.
    std::vector<FeCase> open;
    for (const FeCase &c : cases)
        if (!gatherIfDone(c, gather)) open.push_back(c);
    // 2. This sweep's tasks still in the queue: waited for, not submitted again.
    const QueueView q = queuedTasks(jobName_);
    if (!q.ok) throw std::runtime_error("squeue did not answer: " + q.error);
    const auto labels = submittedLabels();
    std::map<std::string, Task> flying; // case label → its task
    std::vector<FeCase> toSubmit;
    for (const FeCase &c : open) {
        for (const QueuedTask &t : q.tasks) {
            const auto l = labels.find(taskKey(t.jobId, t.index));
            if (l != labels.end() && l->second == c.label()) flying[c.label()] = {t.jobId, t.index, c};
        }
        if (!flying.count(c.label())) toSubmit.push_back(c);
    }
    std::cout << "slurm: " << cases.size() - open.size() << " results gathered from " << resultsDir() << ", "
              << flying.size() << " cases still in the queue, " << toSubmit.size() << " to submit\n";
    // 3. The rest: one job array (several past Slurm's default MaxArraySize, 1001 tasks).
    constexpr size_t kArrayMax = 1000;
    for (size_t from = 0; from < toSubmit.size(); from += kArrayMax) {
        const std::vector<FeCase> part(toSubmit.begin() + long(from),
                                       toSubmit.begin() + long(std::min(toSubmit.size(), from + kArrayMax)));
        for (const Task &t : submit(part)) flying[t.c.label()] = t;
    }
    if (!flying.empty())
        std::cout << "slurm: the tasks run on without this command: run it again to gather them, "
                     "--cancel 1 to stop them\n";
    std::cout.flush();
    // 4. Wait, gathering each result as it appears.
    const size_t total = flying.size();
    size_t gathered = 0, lost = 0;
    std::string lastProgress;
    const auto t0 = std::chrono::steady_clock::now();
    auto lastPrint = t0;
    while (!flying.empty()) {
        for (auto it = flying.begin(); it != flying.end();)
            if (gatherIfDone(it->second.c, gather)) {
                it = flying.erase(it);
                ++gathered;
            } else
                ++it;
        if (flying.empty()) break;
        const QueueView now = queuedTasks(jobName_);
        std::map<std::string, std::string> state; // "job_task" → state (why, while pending)
        if (now.ok)
            for (const QueuedTask &t : now.tasks)
                state[taskKey(t.jobId, t.index)] =
                    t.state +
                    (t.state == "PENDING" && t.reason != "None" && !t.reason.empty() ? " (" + t.reason + ")" : "");
        else
            std::cout << "slurm: squeue did not answer (" << now.error << "); waiting\n";
        std::map<std::string, int> counts;
        for (auto it = flying.begin(); it != flying.end();) {
            const Task &t = it->second;
            const auto s = state.find(taskKey(t.jobId, t.index));
            if (!now.ok || s != state.end()) {
                ++counts[now.ok ? s->second : "?"];
                ++it;
                continue;
            }
            // Left the queue: its rows may have landed since the look above.
            if (gatherIfDone(t.c, gather)) {
                ++gathered;
                it = flying.erase(it);
                continue;
            }
            std::cout << t.c.label() << ": no result: task " << taskKey(t.jobId, t.index) << " ended "
                      << endedState(t.jobId, t.index) << "; log " << logTail(t) << "\n";
            ++lost;
            it = flying.erase(it);
        }
        std::ostringstream p;
        p << "slurm: " << jobName_ << ": " << gathered << "/" << total << " gathered";
        for (const auto &[s, n] : counts) p << ", " << n << " " << s;
        if (lost) p << ", " << lost << " without result";
        const auto tNow = std::chrono::steady_clock::now();
        if (p.str() != lastProgress || tNow - lastPrint > std::chrono::seconds(60)) {
            std::cout << p.str() << " (" << elapsed(std::chrono::duration<double>(tNow - t0).count()) << ")\n";
            lastProgress = p.str();
            lastPrint = tNow;
        }
        std::cout.flush();
        if (!flying.empty()) std::this_thread::sleep_for(std::chrono::duration<double>(slurm_.pollS));
    }
    if (lost)
        std::cout << "slurm: " << lost
                  << " cases without result (listed above): running the same command again "
                     "submits them again\n";
    return lost;
}

size_t SlurmExecutor::cancel()
{
    const QueueView q = queuedTasks(jobName_);
    if (!q.ok) throw std::runtime_error("squeue did not answer: " + q.error);
    std::set<std::string> jobs;
    for (const QueuedTask &t : q.tasks) jobs.insert(t.jobId);
    const std::string err = cancelJobs({jobs.begin(), jobs.end()});
    if (!err.empty()) throw std::runtime_error("scancel: " + err);
    std::cout << "slurm: cancelled " << q.tasks.size() << " tasks of " << jobs.size() << " jobs (" << jobName_ << ")\n";
    return q.tasks.size();
}

void SlurmExecutor::forget(const FeCase &c) const
{
    const std::string file = resultFile(resultsDir(), c);
    if (fs::exists(file)) fs::rename(file, file + ".old");
}

} // namespace icacam::host::fe
