#include "host_tools/fe/fe_base_data.h"

#include <exception>

#include "host_tools/fe/fe_rows.h"

namespace icacam::host::fe {

bool readFeBaseData(const std::vector<std::string> &paths, FeBaseData *out, std::string *error)
{
    if (paths.empty()) {
        *error = "no FE sweep CSV given";
        return false;
    }
    std::vector<FeRow> rows;
    try {
        rows = readSweepCsvs(paths);
    } catch (const std::exception &e) {
        *error = e.what();
        return false;
    }
    // The same choice as the FE model's table (fe_rows.h), made at 50 %; every snapshot of that
    // mesh and K is kept.
    const BaseChoice base = chooseBase(rows, 0.5);
    if (!base.found) {
        *error = "no FE run reached 50 % reduction in the sweep CSV(s) given";
        return false;
    }
    out->mesh = base.mesh;
    out->kMpa = base.kMpa;
    out->rows.clear();
    for (const FeRow &r : rows) {
        if (!reachedSnapshot(r, r.reduction) || !isPaperSpecimen(r) || meshKey(r) != base.mesh || r.kMpa != base.kMpa)
            continue;
        FeSnapshot s;
        s.n = r.n;
        s.mu = r.mu;
        s.reduction = r.reduction;
        s.uMm = r.uBest();
        s.riMm = r.ri;
        s.roMm = r.uTrack >= 0 ? r.ri + r.uTrack : r.roInterp;
        s.rMaxMm = r.rMax;
        out->rows.push_back(s);
    }
    return true;
}

} // namespace icacam::host::fe
