// The sweep's pieces that need no solver and no cluster: the Slurm options and config file,
// a case written as `fe run` options, the batch script, the CSV as a store of cases.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "host_tools/fe/fe_runner.h"
#include "host_tools/fe/fe_slurm_options.h"
#include "host_tools/fe/fe_slurm_script.h"
#include "host_tools/fe/fe_sweep_csv.h"

using namespace icacam::host::fe;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string &name)
{
    const fs::path d = fs::temp_directory_path() / ("icacam-fe-sweep-test-" + std::to_string(getpid()));
    fs::create_directories(d);
    return d / name;
}
} // namespace

TEST(SlurmOptions, ConfigFileThenOptions)
{
    const fs::path conf = scratch("slurm.conf");
    std::ofstream(conf) << "# a lab's defaults\npartition = short\ntime = 30:00\ncpus-per-task = 2\n"
                           "setup = module load calculix # the site's module\nsbatch = --account=fe --mem=2G\n";
    const SlurmOptions o = slurmOptions(conf.string(), {{"partition", "long"}, {"poll", "2"}});
    EXPECT_EQ(o.partition, "long") << "an option given wins over the file";
    EXPECT_EQ(o.timeLimit, "30:00");
    EXPECT_EQ(o.cpusPerTask, 2);
    EXPECT_EQ(o.setup, "module load calculix # the site's module") << "a '#' inside a value is the value's";
    EXPECT_EQ(o.sbatchExtra, "--account=fe --mem=2G");
    EXPECT_DOUBLE_EQ(o.pollS, 2);
    std::ofstream(conf) << "partitoin = short\n";
    EXPECT_THROW(slurmOptions(conf.string(), {}), std::runtime_error) << "a misspelt key is an error, not ignored";
    EXPECT_THROW(slurmOptions("", {{"cpus-per-task", "0"}}), std::runtime_error);
    EXPECT_THROW(slurmOptions((conf.string() + ".missing"), {}), std::runtime_error);
    fs::remove_all(conf.parent_path());
}

TEST(SlurmScript, CaseOptionsReadBackExactly)
{
    FeCase c;
    c.mu = 0.1 + 0.2; // not 0.3: needs 17 digits
    c.n = 0.125;
    c.element = "CAX8R";
    const auto a = caseOptions(c);
    auto value = [&](const std::string &key) {
        for (size_t i = 0; i + 1 < a.size(); ++i)
            if (a[i] == "--" + key) return a[i + 1];
        return std::string();
    };
    EXPECT_EQ(std::stod(value("mu")), c.mu);
    EXPECT_EQ(value("n"), "0.125") << "short where short reads back";
    EXPECT_EQ(value("element"), "CAX8R");
    EXPECT_EQ(value("press-speed"), "") << "a rate-independent case's options are the ones it always had";
    FeCase r = c;
    r.pressSpeedMmS = 0.5;
    r.m = 0.05;
    r.rate0 = 0.01;
    const auto b = caseOptions(r);
    auto valueOf = [&](const std::string &key) {
        for (size_t i = 0; i + 1 < b.size(); ++i)
            if (b[i] == "--" + key) return std::stod(b[i + 1]);
        return -1.0;
    };
    EXPECT_EQ(valueOf("press-speed"), 0.5);
    EXPECT_EQ(valueOf("m"), 0.05);
    EXPECT_EQ(valueOf("rate0"), 0.01);
    EXPECT_EQ(valueOf("creep-tol"), r.creepTol);
}

TEST(SlurmScript, OneCasePerArrayTask)
{
    JobScript js;
    js.icacam = "/opt/icacam/bin/icacam";
    js.setup = "module load calculix";
    js.resultsDir = "/shared/sweep.csv.slurm/results";
    FeCase a, b;
    b.mu = 0.3;
    js.cases = {a, b};
    const std::string t = jobScriptText(js);
    EXPECT_NE(t.find("module load calculix\n"), std::string::npos);
    EXPECT_NE(t.find("0) label='" + a.label() + "'"), std::string::npos);
    EXPECT_NE(t.find("1) label='" + b.label() + "'"), std::string::npos);
    EXPECT_EQ(t.find("2) label="), std::string::npos);
    EXPECT_NE(t.find("'/opt/icacam/bin/icacam' fe run"), std::string::npos);
    EXPECT_EQ(resultFile(js.resultsDir, b), js.resultsDir + "/" + b.label() + ".csv");
}

TEST(SweepCsv, CasesStatusesAndDropping)
{
    const fs::path csv = scratch("sweep.csv");
    FeCase ok, bad;
    bad.mu = 0.3;
    RunResult r;
    r.status = "ok";
    r.radii.resize(2);
    r.radii[1].reduction = 0.5;
    appendRows(csv.string(), csvRows(ok, r));
    RunResult f;
    f.status = "failed";
    f.message = "*ERROR: too many cutbacks";
    appendRows(csv.string(), csvRows(bad, f));
    EXPECT_EQ(casesIn(csv.string()), (std::set<std::string>{ok.label(), bad.label()}));
    const auto st = caseStatuses(csv.string());
    EXPECT_EQ(st.at(bad.label()).status, "failed");
    EXPECT_EQ(st.at(bad.label()).message, "*ERROR: too many cutbacks");
    EXPECT_EQ(st.at(ok.label()).status, "ok");
    dropCases(csv.string(), {bad.label()});
    EXPECT_EQ(casesIn(csv.string()), (std::set<std::string>{ok.label()}));
    EXPECT_EQ(readRows(csv.string()).size(), 2u) << "the other case's rows stay, all of them";
    fs::remove_all(csv.parent_path());
}
