// `icacam fe`: deck generation, ccx runs, sweeps, the model fit and the report.
#include "host_tools/fe/fe_command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "host_tools/cli_options.h"
#include "host_tools/fe/fe_base_setup.h"
#include "host_tools/fe/fe_compare.h"
#include "host_tools/fe/fe_report.h"
#include "host_tools/fe/fe_runner.h"
#include "host_tools/fe/fe_slurm_options.h"
#include "host_tools/fe/fe_slurm_script.h"
#include "host_tools/fe/fe_sweep.h"
#include "host_tools/fe/fe_sweep_csv.h"
#include "host_tools/number_text.h"

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::host::fe;

namespace {

std::string g(double v)
{
    return numberText("%g", v);
}

// A setup's case and run settings as options (the numbers as %g prints them).
std::string settingsText(const FeCase &c, const RunOptions &run)
{
    return "--element " + c.element + " --corner " + g(c.cornerMm) + " --elem " + g(c.elemMm) + " --reduction " +
           g(c.reductionMax) + " --inc-max " + g(c.incMax) + " --stick-slope " + g(c.stickSlope) + " --track-step " +
           g(c.trackStep) + " --fallback-stick-slope " + g(run.fallbackStickSlope);
}

std::string usage()
{
    const FeCase c;
    const RunOptions run;
    const SlurmOptions slurm;
    return "usage: icacam fe <deck|run|sweep|tables|outline-table|report|compare> [options]\n"
           "  deck    [case options]                                  print the CalculiX deck\n"
           "  run     [case options] [--out CSV] [--work DIR]         one case: ccx, R_i R_o R_max u force\n"
           "  sweep   --grid 'k=500;n=0.25,0.05;mu=0.05,0.1' [case options] --out CSV [--jobs 1]\n"
           "          resumable: cases already in CSV are skipped; grid keys: the case options' numbers\n"
           "          (k n mu e d0 h0 red elem corner stick-slope …), the first key outermost\n"
           "          [--executor local|slurm] (default local) [--resubmit-failed 1] (the cases whose rows\n"
           "          say failed, alone)\n"
           "          slurm (docs/fe-cluster.md): one job array, a case per task, results in <CSV>.slurm/:\n"
           "          [--partition P] [--time LIMIT] (default: the partition's) [--cpus-per-task " +
           std::to_string(slurm.cpusPerTask) +
           "]\n"
           "          [--sbatch '--account=x --mem=2G'] [--setup 'module load calculix']\n"
           "          [--slurm-config FILE (key = value, the same keys)] [--slurm-dir DIR (default <CSV>.slurm)]\n"
           "          [--icacam PATH] [--array-limit N] [--poll " +
           g(slurm.pollS) +
           "] [--cancel 1]\n"
           "  tables  --base CSV [--k-family CSV]... [--aspect CSV]... [--out friction]\n"
           "          every generated table of the friction models from one FE base (icacam fe tables --help)\n"
           "  outline-table [--profiles CSV] [--out HEADER]           the outline a close camera sees, over\n"
           "          n, mu, the reduction and D0/W, from the photo bench's barrel profiles\n"
           "  report  --in CSV --out DIR [--snapshot-reduction 0.5]    Table 1 / Fig. 3 comparison\n"
           "  compare --in REF.csv --in OTHER.csv [--out MD] [--min-u 0.1] [--bar 0.05] [--edge interp|track]\n"
           "          [--across-material 1] (K and E left out of the match: the independence checks)\n"
           "          u of the same cases on other meshes/solvers (mesh study, independent model)\n"
           "Options take their value as --name value or --name=value.\n"
           "case options, with their defaults (the coarse setup of the first sweeps: seconds a case):\n"
           "  --k " +
           g(c.kMpa) + " --n " + g(c.n) + " --mu " + g(c.mu) + " --e " + g(c.eMpa) + " --d0 " + g(c.d0Mm) + " --h0 " +
           g(c.h0Mm) + " --reduction " + g(c.reductionMax) +
           " (snapshots every 0.05 to it)\n"
           "  --element " +
           c.element + " (CAX4R|CAX8R) --elem " + g(c.elemMm) + " (element, mm) --corner " + g(c.cornerMm) +
           " (> 0: graded to this at the end-face corner, mm)\n"
           "  --contact-slope " +
           g(c.contactSlope) + " --stick-slope " + g(c.stickSlope) + " (N/mm³) --inc-max " + g(c.incMax) +
           "\n"
           "  --contact " +
           c.contact +
           " (node: NODE TO SURFACE, the base; surface: SURFACE TO SURFACE)\n"
           "  --platen " +
           g(c.platenMm) + " (master segment, mm; 0: max(corner, elem / 2)) --fold-zone " + g(c.foldZoneMm) +
           " (mm of side kept at the corner size)\n"
           "  --track-step " +
           g(c.trackStep) +
           " (reduction between frames that track the contact edge; 0: none)\n"
           "  --press-speed " +
           g(c.pressSpeedMmS) + " (mm/s; > 0: a *VISCO step at this speed, the material σ = K ε^n (ε̇/ε̇₀)^m) --m " +
           g(c.m) + " --rate0 " + g(c.rate0) + " (ε̇₀, 1/s) --creep-tol " + g(c.creepTol) +
           " (*VISCO CETOL)\n"
           "  --preset coarse|base (default coarse): base starts from the setup of the models' FE base\n"
           "  (data/fe/README.md), minutes a case: " +
           settingsText(baseSetupCase(), baseSetupRun()) +
           ";\n"
           "  options given beside it win. `icacam fe sweep --preset base --grid 'n=…;mu=…'` adds to the base.\n"
           "run options: --ccx " +
           run.ccx + " --timeout " + std::to_string(run.timeoutS) + " --work " + run.workDir +
           " --fallback-stick-slope " + g(run.fallbackStickSlope) +
           " (rerun a case that stops with this stick slope; 0: no rerun)\n"
           "  --reuse 0|1|only (default 0; 1: post-process the work directory's results of the same deck again;\n"
           "  only: cases without such results are left out, never run)\n";
}

struct Parsed {
    bool help = false;
    FeCase c;
    RunOptions run;
    std::vector<std::string> in;
    std::string out, grid;
    double reduction = 0.5;
    double minU = 0.1, bar = 0.05; // compare: judged where u > minU mm, within bar (relative)
    std::string edge = "interp";   // compare: which contact edge (interp | track)
    bool acrossMaterial = false;   // compare: match regardless of K and E
    int jobs = 1;
    SweepOptions sweep; // sweep: executor, Slurm settings
};

double toDouble(const std::string &key, const std::string &v)
{
    double x = 0;
    if (!cli::parseFinite(v, &x)) throw cli::UsageError(key + ": not a number: '" + v + "'", usage());
    return x;
}

bool setCaseKey(FeCase &c, const std::string &key, double v)
{
    if (key == "k")
        c.kMpa = v;
    else if (key == "n")
        c.n = v;
    else if (key == "mu")
        c.mu = v;
    else if (key == "e")
        c.eMpa = v;
    else if (key == "d0")
        c.d0Mm = v;
    else if (key == "h0")
        c.h0Mm = v;
    else if (key == "reduction" || key == "red")
        c.reductionMax = v;
    else if (key == "elem")
        c.elemMm = v;
    else if (key == "corner")
        c.cornerMm = v;
    else if (key == "platen")
        c.platenMm = v;
    else if (key == "fold-zone")
        c.foldZoneMm = v;
    else if (key == "contact-slope")
        c.contactSlope = v;
    else if (key == "stick-slope")
        c.stickSlope = v;
    else if (key == "inc-max")
        c.incMax = v;
    else if (key == "track-step")
        c.trackStep = v;
    else if (key == "press-speed")
        c.pressSpeedMmS = v;
    else if (key == "m")
        c.m = v;
    else if (key == "rate0")
        c.rate0 = v;
    else if (key == "creep-tol")
        c.creepTol = v;
    else
        return false;
    return true;
}

// Every option `icacam fe` knows (all of them take a value), so an unknown one is named as
// such rather than as one missing its value.
bool knownKey(const std::string &key)
{
    static const std::set<std::string> kCommandKeys = {"out",
                                                       "in",
                                                       "grid",
                                                       "work",
                                                       "ccx",
                                                       "timeout",
                                                       "fallback-stick-slope",
                                                       "reuse",
                                                       "jobs",
                                                       "snapshot-reduction",
                                                       "element",
                                                       "contact",
                                                       "min-u",
                                                       "bar",
                                                       "across-material",
                                                       "edge",
                                                       "executor",
                                                       "resubmit-failed",
                                                       "cancel",
                                                       "slurm-config",
                                                       "preset"};
    FeCase scratch;
    return kCommandKeys.count(key) || isSlurmKey(key) || setCaseKey(scratch, key, 0);
}

// The options after the verb (args[from…]); --help sets help and stops.
Parsed parse(const std::vector<std::string> &args, size_t from)
{
    Parsed p;
    // --preset first, wherever it stands: the options given beside it win.
    for (size_t i = from; i < args.size(); ++i) {
        std::string preset;
        if (args[i] == "--preset" && i + 1 < args.size())
            preset = args[i + 1];
        else if (args[i].rfind("--preset=", 0) == 0)
            preset = args[i].substr(9);
        else
            continue;
        if (preset == "base")
            p.c = baseSetupCase(), p.run = baseSetupRun();
        else if (preset != "coarse")
            throw cli::UsageError("--preset: coarse or base, not '" + preset + "'", usage());
    }
    cli::OptionReader opts(args, usage(), from);
    while (opts.next()) {
        if (opts.isHelp()) {
            p.help = true;
            return p;
        }
        if (!opts.isOption() || opts.name().rfind("--", 0) != 0) opts.unknown();
        const std::string key = opts.name().substr(2);
        if (!knownKey(key)) opts.unknown();
        const std::string v = opts.value();
        if (key == "preset") {
        } // applied above
        else if (key == "out")
            p.out = v;
        else if (key == "in")
            p.in.push_back(v);
        else if (key == "grid")
            p.grid = v;
        else if (key == "work")
            p.run.workDir = v;
        else if (key == "ccx")
            p.run.ccx = v;
        else if (key == "timeout")
            p.run.timeoutS = int(toDouble(opts.name(), v));
        else if (key == "fallback-stick-slope")
            p.run.fallbackStickSlope = toDouble(opts.name(), v);
        else if (key == "reuse") {
            p.run.reuse = v != "0";
            p.run.reuseOnly = v == "only";
        } else if (key == "jobs")
            p.jobs = std::clamp(int(toDouble(opts.name(), v)), 1, 2);
        else if (key == "snapshot-reduction")
            p.reduction = toDouble(opts.name(), v);
        else if (key == "element") {
            if (v != "CAX4R" && v != "CAX8R") opts.fail("CAX4R or CAX8R, not '" + v + "'");
            p.c.element = v;
        } else if (key == "contact")
            p.c.contact = v;
        else if (key == "min-u")
            p.minU = toDouble(opts.name(), v);
        else if (key == "bar")
            p.bar = toDouble(opts.name(), v);
        else if (key == "across-material")
            p.acrossMaterial = v != "0";
        else if (key == "edge") {
            if (v != "interp" && v != "track") opts.fail("interp or track, not '" + v + "'");
            p.edge = v;
        } else if (setSweepOption(p.sweep, key, v)) {
        } else if (!setCaseKey(p.c, key, toDouble(opts.name(), v)))
            opts.unknown();
    }
    if (p.reduction <= 0) p.reduction = p.c.reductionMax;
    return p;
}

// "k=500;n=0.25,0.05;mu=0.05,0.1" → the cases, the first key outermost.
std::vector<FeCase> expandGrid(const FeCase &base, const std::string &grid)
{
    std::vector<FeCase> cases{base};
    std::istringstream g(grid);
    std::string part;
    while (std::getline(g, part, ';')) {
        if (part.empty()) continue;
        const auto eq = part.find('=');
        if (eq == std::string::npos) throw std::runtime_error("grid: expected key=v1,v2: " + part);
        const std::string key = part.substr(0, eq);
        std::vector<double> values;
        std::istringstream vs(part.substr(eq + 1));
        std::string v;
        while (std::getline(vs, v, ',')) values.push_back(toDouble(key, v));
        std::vector<FeCase> next;
        for (const FeCase &c : cases)
            for (double x : values) {
                FeCase d = c;
                if (!setCaseKey(d, key, x)) throw std::runtime_error("grid: unknown key " + key);
                next.push_back(d);
            }
        cases = next;
    }
    return cases;
}

int sweep(const Parsed &p)
{
    // --cancel only needs to know the sweep (its CSV or directory), not its cases.
    if (p.out.empty() || (p.grid.empty() && !p.sweep.cancel))
        throw cli::UsageError("sweep needs --grid and --out", usage());
    const auto cases = expandGrid(p.c, p.grid);
    // A case leaves this process as `icacam fe run` options (Slurm tasks): they must make
    // the same case again.
    if (p.sweep.executor != "local")
        for (const FeCase &c : cases) {
            std::vector<std::string> args{"run"};
            for (const auto &a : caseOptions(c)) args.push_back(a);
            if (parse(args, 1).c.label() != c.label())
                throw std::runtime_error("sweep: case " + c.label() + " does not survive its own options");
        }
    SweepOptions o = p.sweep;
    o.jobs = p.jobs;
    return runSweep(cases, p.out, p.run, o);
}

} // namespace

int feCommand(const std::vector<std::string> &args)
{
    if (args.empty()) throw cli::UsageError("a verb is needed", usage());
    if (args[0] == "-h" || args[0] == "--help") {
        std::cout << usage();
        return 0;
    }
    const std::string sub = args[0];
    static const std::set<std::string> kVerbs = {"deck", "run", "sweep", "report", "compare", "fit", "aspect"};
    if (!kVerbs.count(sub)) throw cli::UsageError("unknown verb '" + sub + "'", usage());
    const Parsed p = parse(args, 1);
    if (p.help) {
        std::cout << usage();
        return 0;
    }
    if (sub == "deck") {
        std::cout << makeDeck(p.c);
        return 0;
    }
    if (sub == "run") {
        FeCase c = p.c;
        const RunResult r = runCase(c, p.run);
        printRunResult(c, r);
        if (!p.out.empty()) appendRows(p.out, csvRows(c, r));
        return r.status == "ok" ? 0 : 1;
    }
    if (sub == "sweep") return sweep(p);
    if (sub == "fit" || sub == "aspect")
        throw std::runtime_error(
            "the generated tables are made by `icacam fe tables` from one FE base (data/fe/README.md)");
    if (sub == "compare") return compareCommand(p.in, p.out, p.minU, p.bar, p.edge == "track", p.acrossMaterial);
    if (sub == "report") {
        if (p.in.empty() || p.out.empty()) throw cli::UsageError("report needs --in and --out", usage());
        return reportCommand(p.in, p.out, p.reduction);
    }
    throw cli::UsageError("unknown verb '" + sub + "'", usage());
}

} // namespace icacam::host
