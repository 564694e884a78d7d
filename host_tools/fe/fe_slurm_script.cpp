#include "host_tools/fe/fe_slurm_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace icacam::host::fe {

namespace {
std::string quote(const std::string &s)
{
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

// The shortest %g text that reads back to x.
std::string exact(double x)
{
    char b[40];
    for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(b, sizeof b, "%.*g", digits, x);
        if (std::strtod(b, nullptr) == x) break;
    }
    return b;
}
} // namespace

std::vector<std::string> caseOptions(const FeCase &c)
{
    const std::pair<const char *, double> numbers[] = {{"k", c.kMpa},
                                                       {"n", c.n},
                                                       {"mu", c.mu},
                                                       {"e", c.eMpa},
                                                       {"d0", c.d0Mm},
                                                       {"h0", c.h0Mm},
                                                       {"reduction", c.reductionMax},
                                                       {"elem", c.elemMm},
                                                       {"corner", c.cornerMm},
                                                       {"platen", c.platenMm},
                                                       {"fold-zone", c.foldZoneMm},
                                                       {"contact-slope", c.contactSlope},
                                                       {"stick-slope", c.stickSlope},
                                                       {"inc-max", c.incMax},
                                                       {"track-step", c.trackStep}};
    std::vector<std::string> a;
    for (const auto &[key, v] : numbers) {
        a.push_back(std::string("--") + key);
        a.push_back(exact(v));
    }
    a.insert(a.end(), {"--element", c.element, "--contact", c.contact});
    if (c.rateSensitive())
        a.insert(a.end(), {"--press-speed", exact(c.pressSpeedMmS), "--m", exact(c.m), "--rate0", exact(c.rate0),
                           "--creep-tol", exact(c.creepTol)});
    return a;
}

std::vector<std::string> runOptionArgs(const RunOptions &o)
{
    std::vector<std::string> a{"--ccx",
                               o.ccx,
                               "--timeout",
                               std::to_string(o.timeoutS),
                               "--fallback-stick-slope",
                               exact(o.fallbackStickSlope),
                               "--work",
                               o.workDir};
    if (o.reuse) a.insert(a.end(), {"--reuse", "1"});
    return a;
}

std::string resultFile(const std::string &resultsDir, const FeCase &c)
{
    return (std::filesystem::path(resultsDir) / (c.label() + ".csv")).string();
}

std::string jobScriptText(const JobScript &s)
{
    std::string t = "#!/bin/bash\n"
                    "# icacam fe sweep on Slurm: array task i solves case i (`icacam fe run`), its rows\n"
                    "# go to results/<case>.csv once complete (a killed task leaves none).\n";
    if (!s.setup.empty()) t += "# the environment (setup):\n" + s.setup + "\n";
    t += "results=" + quote(s.resultsDir) + "\n";
    t += "case \"${SLURM_ARRAY_TASK_ID:-}\" in\n";
    const auto runArgs = runOptionArgs(s.run);
    for (size_t i = 0; i < s.cases.size(); ++i) {
        t += std::to_string(i) + ") label=" + quote(s.cases[i].label()) + "; set --";
        for (const auto &a : caseOptions(s.cases[i])) t += " " + quote(a);
        for (const auto &a : runArgs) t += " " + quote(a);
        t += " ;;\n";
    }
    t += "*) echo \"no case for array task ${SLURM_ARRAY_TASK_ID:-(none)}\" >&2; exit 2 ;;\n"
         "esac\n"
         "echo \"case $label on $(hostname), job ${SLURM_ARRAY_JOB_ID:-}_${SLURM_ARRAY_TASK_ID:-}\"\n"
         "part=\"$results/$label.csv.part.${SLURM_JOB_ID:-$$}\"\n"
         "rm -f \"$part\"\n";
    t += quote(s.icacam) + " fe run \"$@\" --out \"$part\"\n";
    t += "rc=$?\n"
         "if [ -s \"$part\" ]; then mv -f \"$part\" \"$results/$label.csv\"; else rm -f \"$part\"; echo \"no rows "
         "(exit $rc)\" >&2; fi\n"
         "exit $rc\n";
    return t;
}

} // namespace icacam::host::fe
