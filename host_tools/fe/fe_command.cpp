// `icacam fe`: deck generation, ccx runs, sweeps, the model fit and the report.
#include "fe_command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "fe_compare.h"
#include "fe_report.h"
#include "fe_runner.h"
#include "fe_slurm_script.h"
#include "fe_sweep.h"
#include "fe_sweep_csv.h"

namespace icacam::host {

namespace fs = std::filesystem;
using namespace icacam::host::fe;

namespace {

const char *kUsage =
    "usage: icacam fe <run|sweep|tables|report|compare|deck> [options]\n"
    "  deck    --k MPa --n N --mu MU [case options]           print the CalculiX deck\n"
    "  run     [case options] [--out CSV] [--work DIR]       one case: ccx, R_i R_o R_max u force\n"
    "  sweep   --grid 'k=500;n=0.25,0.05;mu=0.05,0.1' [case options] --out CSV [--jobs 1]\n"
    "          resumable: cases already in CSV are skipped; grid keys: k n mu e d0 h0 red elem\n"
    "          [--executor local|slurm] [--resubmit-failed 1] (the cases whose rows say failed, alone)\n"
    "          slurm (docs/fe-cluster.md): one job array, a case per task, results in <CSV>.slurm/:\n"
    "          [--partition P] [--time 30:00] [--cpus-per-task 1] [--sbatch '--account=x --mem=2G']\n"
    "          [--setup 'module load calculix'] [--slurm-config FILE (key = value, the same keys)]\n"
    "          [--slurm-dir DIR] [--icacam PATH] [--array-limit N] [--poll 15] [--cancel 1]\n"
    "  tables  --base CSV [--k-family CSV]... [--aspect CSV]... [--out vision/model]\n"
    "          every generated table of the friction models from one FE base (icacam fe tables --help)\n"
    "  report  --in CSV --out DIR                             Table 1 / Fig. 3 comparison\n"
    "  compare --in REF.csv --in OTHER.csv [--out MD] [--min-u 0.1] [--bar 0.05] [--edge interp|track]\n"
    "          [--across-material 1] (K and E left out of the match: the independence checks)\n"
    "          u of the same cases on other meshes/solvers (mesh study, independent model)\n"
    "case options: --k 500 --n 0.25 --mu 0.2 --e 210000 --d0 10 --h0 15 --reduction 0.5\n"
    "              --elem 0.2 --corner 0 --contact-slope 1e5 --stick-slope 1e4 --fallback-stick-slope 1e3\n"
    "              --inc-max 0.01 --element CAX4R|CAX8R --platen 0 (master segment, mm)\n"
    "              --fold-zone 0 (mm of side kept at the corner size)\n"
    "              --contact node|surface (NODE TO SURFACE, the base; SURFACE TO SURFACE)\n"
    "              --track-step 0 (reduction between frames that track the contact edge, e.g. 0.01)\n"
    "              --ccx ccx --timeout 3600 --work /tmp/icacam-fe\n"
    "              --reuse 1|only (post-process the work directory's results of the same deck again;\n"
    "              only: cases without such results are left out, never run)\n";

struct Parsed {
    FeCase c;
    RunOptions run;
    std::vector<std::string> in;
    std::string out, grid;
    double reduction = 0.5;
    double minU = 0.1, bar = 0.05; // compare: judged where u > minU mm, within bar (relative)
    std::string edge = "interp";   // compare: which contact edge (interp | track)
    bool acrossMaterial = false;   // compare: match regardless of K and E
    int jobs = 1;
    SweepOptions sweep;            // sweep: executor, Slurm settings
};

double toDouble(const std::string &key, const std::string &v)
{
    size_t pos = 0;
    double x = 0;
    try { x = std::stod(v, &pos); } catch (...) { pos = 0; }
    if (pos != v.size() || !std::isfinite(x)) throw std::runtime_error(key + ": not a number: '" + v + "'");
    return x;
}

bool setCaseKey(FeCase &c, const std::string &key, double v)
{
    if (key == "k") c.kMpa = v;
    else if (key == "n") c.n = v;
    else if (key == "mu") c.mu = v;
    else if (key == "e") c.eMpa = v;
    else if (key == "d0") c.d0Mm = v;
    else if (key == "h0") c.h0Mm = v;
    else if (key == "reduction" || key == "red") c.reductionMax = v;
    else if (key == "elem") c.elemMm = v;
    else if (key == "corner") c.cornerMm = v;
    else if (key == "platen") c.platenMm = v;
    else if (key == "fold-zone") c.foldZoneMm = v;
    else if (key == "contact-slope") c.contactSlope = v;
    else if (key == "stick-slope") c.stickSlope = v;
    else if (key == "inc-max") c.incMax = v;
    else if (key == "track-step") c.trackStep = v;
    else return false;
    return true;
}

Parsed parse(const std::vector<std::string> &args, size_t from)
{
    Parsed p;
    for (size_t i = from; i < args.size(); ++i) {
        const std::string &a = args[i];
        if (a == "-h" || a == "--help") { std::cout << kUsage; std::exit(0); }
        if (a.rfind("--", 0) != 0 || i + 1 >= args.size())
            throw std::runtime_error("bad or incomplete option '" + a + "'\n" + kUsage);
        const std::string key = a.substr(2), v = args[++i];
        if (key == "out") p.out = v;
        else if (key == "in") p.in.push_back(v);
        else if (key == "grid") p.grid = v;
        else if (key == "work") p.run.workDir = v;
        else if (key == "ccx") p.run.ccx = v;
        else if (key == "timeout") p.run.timeoutS = int(toDouble(key, v));
        else if (key == "fallback-stick-slope") p.run.fallbackStickSlope = toDouble(key, v);
        else if (key == "reuse") {
            p.run.reuse = v != "0";
            p.run.reuseOnly = v == "only";
        }
        else if (key == "jobs") p.jobs = std::clamp(int(toDouble(key, v)), 1, 2);
        else if (key == "snapshot-reduction") p.reduction = toDouble(key, v);
        else if (key == "element") p.c.element = v;
        else if (key == "contact") p.c.contact = v;
        else if (key == "min-u") p.minU = toDouble(key, v);
        else if (key == "bar") p.bar = toDouble(key, v);
        else if (key == "across-material") p.acrossMaterial = v != "0";
        else if (key == "edge") {
            if (v != "interp" && v != "track") throw std::runtime_error("--edge: interp or track, not '" + v + "'");
            p.edge = v;
        }
        else if (setSweepOption(p.sweep, key, v)) {}
        else if (!setCaseKey(p.c, key, toDouble(key, v)))
            throw std::runtime_error("unknown option '" + a + "'\n" + kUsage);
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
    if (p.out.empty() || (p.grid.empty() && !p.sweep.cancel)) throw std::runtime_error("sweep needs --grid and --out");
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
    if (args.empty() || args[0] == "-h" || args[0] == "--help") { std::cout << kUsage; return args.empty() ? 2 : 0; }
    const std::string sub = args[0];
    const Parsed p = parse(args, 1);
    if (sub == "deck") { std::cout << makeDeck(p.c); return 0; }
    if (sub == "run") {
        FeCase c = p.c;
        const RunResult r = runCase(c, p.run);
        printRunResult(c, r);
        if (!p.out.empty()) appendRows(p.out, csvRows(c, r));
        return r.status == "ok" ? 0 : 1;
    }
    if (sub == "sweep") return sweep(p);
    if (sub == "fit" || sub == "aspect")
        throw std::runtime_error("the generated tables are made by `icacam fe tables` from one FE base (data/fe/README.md)");
    if (sub == "compare") return compareCommand(p.in, p.out, p.minU, p.bar, p.edge == "track", p.acrossMaterial);
    if (sub == "report") {
        if (p.in.empty() || p.out.empty()) throw std::runtime_error("report needs --in and --out");
        return reportCommand(p.in, p.out, p.reduction);
    }
    throw std::runtime_error("unknown fe subcommand '" + sub + "'\n" + kUsage);
}

} // namespace icacam::host
