#include "host_tools/loop/fe_base_data.h"

#include <exception>

#include "host_tools/fe/fe_rows.h"

namespace icacam::host::loop {

bool readFeBaseData(const std::vector<std::string> &paths, FeBaseData *out, std::string *error)
{
    if (paths.empty()) {
        *error = "no FE sweep CSV given";
        return false;
    }
    std::vector<fe::FeRow> rows;
    try {
        rows = fe::readSweepCsvs(paths);
    } catch (const std::exception &e) {
        *error = e.what();
        return false;
    }
    // The same choice as `icacam fe fit` (fe_rows.h), made at 50 %; every snapshot of that
    // mesh and K is kept.
    const fe::BaseChoice base = fe::chooseBase(rows, 0.5);
    if (!base.found) {
        *error = "no FE run reached 50 % reduction in the sweep CSV(s) given";
        return false;
    }
    out->mesh = base.mesh;
    out->kMpa = base.kMpa;
    out->rows.clear();
    for (const fe::FeRow &r : rows) {
        if (!fe::reachedSnapshot(r, r.reduction) || !fe::isPaperSpecimen(r) || fe::meshKey(r) != base.mesh ||
            r.kMpa != base.kMpa)
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

} // namespace icacam::host::loop
