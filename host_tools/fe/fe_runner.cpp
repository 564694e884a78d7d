#include "host_tools/fe/fe_runner.h"

#include "host_tools/fe/fe_contact_track.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace icacam::host::fe {

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path &p)
{
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}
// The former lateral nodes of one frame (mid-plane … corner): gap to the platen and radius.
SideFrame sideFrame(const FeCase &c, const FeMesh &m, const NodeXY &coords, const NodeXY &disp, double reduction)
{
    SideFrame f;
    f.reduction = reduction;
    f.nodesPerEdge = m.q;
    const double zPlaten = c.h0Mm / 2 * (1 - reduction);
    for (int j = 0; j < m.rows(); ++j) {
        const int id = m.lateralNode(j);
        const auto ci = coords.find(id);
        const auto di = disp.find(id);
        if (ci == coords.end() || di == disp.end()) throw std::runtime_error("fe: node missing in results");
        f.gapMm.push_back(zPlaten - (ci->second.second + di->second.second));
        f.rMm.push_back(ci->second.first + di->second.first);
    }
    return f;
}
std::string shellQuote(const std::string &s)
{
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}
} // namespace

std::vector<double> snapshotReductions(const FeCase &c)
{
    std::vector<double> r;
    for (int k = 1; k * 0.05 <= c.reductionMax + 1e-9; ++k) r.push_back(std::round(k * 0.05 * 1e6) / 1e6);
    for (double x : c.reductions)
        if (x > 0 && x <= c.reductionMax + 1e-9) r.push_back(x);
    r.push_back(c.reductionMax);
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end(), [](double a, double b) { return std::fabs(a - b) < 1e-9; }), r.end());
    return r;
}

RunResult runOnce(FeCase c, const RunOptions &o);

bool hasReusableResults(const FeCase &caseIn, const RunOptions &o)
{
    FeCase c = caseIn;
    c.reductions = snapshotReductions(c);
    const fs::path dir = fs::path(o.workDir) / c.label();
    return fs::exists(dir / "job.frd") && fs::exists(dir / "ccx.log") && fs::exists(dir / "wall_s") &&
           slurp(dir / "job.inp") == makeDeck(c);
}

RunResult runCase(FeCase &c, const RunOptions &o)
{
    RunResult r = runOnce(c, o);
    if (r.status == "failed" && o.fallbackStickSlope > 0 && o.fallbackStickSlope < c.stickSlope) {
        const double wall = r.wallS;
        const std::string why = r.message;
        c.stickSlope = o.fallbackStickSlope;
        r = runOnce(c, o);
        r.wallS += wall;
        r.message = "retried with stick slope " + std::to_string(int(c.stickSlope)) + " after: " + why;
        for (char &ch : r.message)
            if (ch == ',') ch = ';';
    }
    return r;
}

RunResult runOnce(FeCase c, const RunOptions &o)
{
    RunResult res;
    c.reductions = snapshotReductions(c);
    const FeMesh mesh = meshFor(c);
    const fs::path dir = fs::path(o.workDir) / c.label();
    res.dir = dir.string();
    fs::create_directories(dir);
    const std::string deckText = makeDeck(c);
    const bool reuse = o.reuse && hasReusableResults(c, o);
    int rc = 0;
    if (reuse) {
        res.wallS = std::strtod(slurp(dir / "wall_s").c_str(), nullptr);
    } else {
        {
            std::ofstream deck(dir / "job.inp");
            deck << deckText;
        }
        for (const char *ext : {".frd", ".dat", ".sta", ".cvg"}) fs::remove(dir / (std::string("job") + ext));
        const std::string cmd = "cd " + shellQuote(dir.string()) +
                                " && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 timeout " +
                                std::to_string(o.timeoutS) + " " + o.ccx + " -i job > ccx.log 2>&1";
        const auto t0 = std::chrono::steady_clock::now();
        rc = std::system(cmd.c_str());
        res.wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::ofstream(dir / "wall_s") << res.wallS << "\n"; // for a later --reuse
    }
    const std::string log = slurp(dir / "ccx.log");
    if (!fs::exists(dir / "job.frd")) {
        res.status = "error";
        res.message = "ccx produced no .frd (exit " + std::to_string(rc) + ")";
        return res;
    }
    const FrdResults frd = readFrd((dir / "job.frd").string());
    const auto forces = parseDatTotals(slurp(dir / "job.dat"));
    const bool finished = log.find("Job finished") != std::string::npos;
    // A run that stopped on divergence writes its "best solution" (not converged) as the
    // last block: never use it, even if its time happens to equal a snapshot's.
    const bool bestSolution = log.find("best solution and residuals are in the frd file") != std::string::npos;
    const size_t usable = !bestSolution || frd.steps.empty() ? frd.steps.size() : frd.steps.size() - 1;
    std::vector<SideFrame> frames;
    std::vector<size_t> snapshotFrame;
    const double toReduction = c.reductionMax / stepTime(c); // 1 for a *STATIC step
    for (size_t k = 0; k < usable; ++k) {
        const FrdStep &s = frd.steps[k];
        const double red = s.time * toReduction;
        if (c.trackStep > 0) frames.push_back(sideFrame(c, mesh, frd.coords, s.disp, red));
        // Rows only for the snapshots; the tracking frames in between feed roTrackMm.
        const bool snapshot =
            std::any_of(c.reductions.begin(), c.reductions.end(), [&](double x) { return std::fabs(x - red) < 1e-6; });
        if (!snapshot) continue;
        res.radii.push_back(computeRadii(c, mesh, frd.coords, s.disp, red));
        snapshotFrame.push_back(frames.size() - 1);
    }
    std::string trackNote;
    if (c.trackStep > 0) {
        const auto touchdown = touchdownReductions(frames, kGapTolMm);
        for (size_t i = 0; i < res.radii.size(); ++i)
            res.radii[i].roTrackMm =
                std::max(res.radii[i].riMm, trackedContactEdge(frames, touchdown, snapshotFrame[i], kGapTolMm));
        // Say so in the rows when the contact zone was broken (never silently a lagging edge).
        int broken = 0;
        double from = 0, to = 0;
        for (const SideFrame &f : frames)
            if (contactZoneBroken(f, kGapTolMm)) {
                if (broken++ == 0) from = f.reduction;
                to = f.reduction;
            }
        if (broken > 0) {
            char b[200];
            std::snprintf(
                b, sizeof b,
                "contact zone broken by a lifted node in %d frames from %.0f to %.0f %%: the tracked edge lags there",
                broken, 100 * from, 100 * to);
            trackNote = b;
        }
    }
    for (ForcePoint f : forces) {
        // Axisymmetric elements: CalculiX reports forces for a 2° segment.
        f.fx *= 180.0 / 1000.0;
        f.fy *= -180.0 / 1000.0; // compressive force on the specimen, positive, kN
        f.time *= toReduction;
        res.force.push_back(f);
    }
    const bool complete = !res.radii.empty() && std::fabs(res.radii.back().reduction - c.reductionMax) < 1e-6;
    res.status = finished && complete ? "ok" : "failed";
    if (!finished) {
        // The last error line of the log says why (e.g. too many cutbacks).
        const auto at = log.rfind("*ERROR");
        res.message = at == std::string::npos ? "ccx did not finish" : log.substr(at, log.find('\n', at) - at);
        for (char &ch : res.message)
            if (ch == ',') ch = ';';
    }
    if (!trackNote.empty()) res.message = res.message.empty() ? trackNote : res.message + "; " + trackNote;
    if (!o.keep) fs::remove_all(dir);
    return res;
}

void printRunResult(const FeCase &c, const RunResult &r)
{
    std::printf("%s: %s in %g s%s\n", c.label().c_str(), r.status.c_str(), r.wallS,
                r.message.empty() ? "" : (" (" + r.message + ")").c_str());
    for (const Radii &x : r.radii) {
        double f = 0;
        for (const auto &p : r.force)
            if (std::fabs(p.time - x.reduction) < 1e-6) f = p.fy;
        std::printf("  reduction %.3f  R_i %.4f  R_o %.4f  R_max %.4f  u %.4f (interp %.4f, tracked %.4f)  F %.2f kN\n",
                    x.reduction, x.riMm, x.roMm, x.rMaxMm, x.uMm(), x.uInterpMm(), x.uTrackMm(), f);
    }
    std::fflush(stdout);
}

std::string csvHeader()
{
    return "case,status,k_mpa,n,mu,e_mpa,nu,d0_mm,h0_mm,reduction_max,reduction,elem_mm,corner_mm,element,"
           "contact,contact_slope,stick_slope,inc_max,r_i_mm,r_o_mm,r_o_interp_mm,r_max_mm,u_mm,"
           "u_interp_mm,contact_nodes,force_kn,wall_s,solver,message,track_step,r_o_track_mm,u_track_mm";
}

std::vector<std::string> csvRows(const FeCase &c, const RunResult &r)
{
    std::vector<std::string> rows;
    auto row = [&](const Radii *x, double force) {
        char b[1024];
        std::snprintf(b, sizeof b,
                      "%s,%s,%g,%g,%g,%g,%g,%g,%g,%g,%.4f,%g,%g,%s,%s-to-surface penalty,%g,%g,%g,"
                      "%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%d,%.3f,%.1f,CalculiX 2.20 OMP=1,%s,%g,%.5f,%.5f",
                      c.label().c_str(), r.status.c_str(), c.kMpa, c.n, c.mu, c.eMpa, c.nu, c.d0Mm, c.h0Mm,
                      c.reductionMax, x ? x->reduction : 0.0, c.elemMm, c.cornerMm, c.element.c_str(),
                      c.contact.c_str(), c.contactSlope, c.stickSlope, c.incMax, x ? x->riMm : 0.0, x ? x->roMm : 0.0,
                      x ? x->roInterpMm : 0.0, x ? x->rMaxMm : 0.0, x ? x->uMm() : 0.0, x ? x->uInterpMm() : 0.0,
                      x ? x->contactNodes : 0, force, r.wallS, r.message.c_str(), c.trackStep, x ? x->roTrackMm : -1.0,
                      x ? x->uTrackMm() : -1.0);
        rows.emplace_back(b);
    };
    for (const Radii &x : r.radii) {
        double f = 0;
        for (const ForcePoint &p : r.force)
            if (std::fabs(p.time - x.reduction) < 1e-6) f = p.fy;
        row(&x, f);
    }
    if (r.radii.empty()) row(nullptr, 0);
    return rows;
}

} // namespace icacam::host::fe
