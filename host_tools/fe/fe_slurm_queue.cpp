#include "host_tools/fe/fe_slurm_queue.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <sys/wait.h>

namespace icacam::host::fe {

namespace {
std::string quote(const std::string &s)
{
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

std::string trimmed(std::string s)
{
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

std::vector<std::string> split(const std::string &s, char sep)
{
    std::vector<std::string> out;
    std::istringstream in(s);
    std::string part;
    while (std::getline(in, part, sep)) out.push_back(part);
    return out;
}
} // namespace

CommandOutput runCommand(const std::vector<std::string> &argv)
{
    std::string cmd;
    for (const auto &a : argv) cmd += (cmd.empty() ? "" : " ") + quote(a);
    cmd += " 2>&1";
    CommandOutput out;
    FILE *p = popen(cmd.c_str(), "r");
    if (!p) return out;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.text.append(buf, n);
    const int status = pclose(p);
    out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    // The shell says 127 when the program is not installed.
    if (out.exitCode == 127) out.exitCode = -1;
    return out;
}

std::string submitBatch(const std::vector<std::string> &sbatchOptions, const std::string &script)
{
    std::vector<std::string> argv{"sbatch", "--parsable"};
    argv.insert(argv.end(), sbatchOptions.begin(), sbatchOptions.end());
    argv.push_back(script);
    const CommandOutput r = runCommand(argv);
    if (r.exitCode == -1) throw std::runtime_error("sbatch is not installed here (Debian: slurm-client)");
    // --parsable: "jobid" or "jobid;cluster" on the last line (warnings may come first).
    std::string last;
    for (const auto &line : split(trimmed(r.text), '\n'))
        if (!line.empty()) last = line;
    const std::string id = last.substr(0, last.find(';'));
    if (r.exitCode != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw std::runtime_error("sbatch refused the sweep: " + trimmed(r.text));
    return id;
}

QueueView queuedTasks(const std::string &jobName)
{
    QueueView v;
    const CommandOutput r = runCommand({"squeue", "-h", "-r", "-n", jobName, "-o", "%F|%K|%T|%r"});
    if (r.exitCode != 0) {
        v.error = r.exitCode == -1 ? "squeue is not installed here" : trimmed(r.text);
        return v;
    }
    v.ok = true;
    for (const auto &line : split(r.text, '\n')) {
        const auto f = split(line, '|');
        if (f.size() < 4) continue;
        QueuedTask t;
        t.jobId = f[0];
        try {
            t.index = std::stoi(f[1]);
        } catch (...) {
            continue;
        } // not an array task
        t.state = f[2];
        t.reason = f[3];
        v.tasks.push_back(t);
    }
    return v;
}

std::string endedState(const std::string &jobId, int index)
{
    const std::string task = jobId + "_" + std::to_string(index);
    const CommandOutput acct = runCommand({"sacct", "-n", "-P", "-X", "-j", task, "-o", "State,ExitCode"});
    if (acct.exitCode == 0) {
        const std::string first = trimmed(acct.text).substr(0, trimmed(acct.text).find('\n'));
        const auto f = split(first, '|');
        if (f.size() >= 2) return f[0] + " (exit " + f[1] + ")";
    }
    const CommandOutput q = runCommand({"squeue", "-h", "-t", "all", "-j", task, "-o", "%T|%r"});
    if (q.exitCode == 0 && !trimmed(q.text).empty()) {
        const auto f = split(trimmed(q.text).substr(0, trimmed(q.text).find('\n')), '|');
        if (f.size() >= 2) return f[0] + (f[1] == "None" ? "" : " (" + f[1] + ")");
    }
    return "unknown (no accounting, and gone from squeue)";
}

std::string cancelJobs(const std::vector<std::string> &jobIds)
{
    if (jobIds.empty()) return "";
    std::vector<std::string> argv{"scancel"};
    argv.insert(argv.end(), jobIds.begin(), jobIds.end());
    const CommandOutput r = runCommand(argv);
    return r.exitCode == 0 ? "" : (r.exitCode == -1 ? "scancel is not installed here" : trimmed(r.text));
}

} // namespace icacam::host::fe
