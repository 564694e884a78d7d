#include "fe_base_data.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "manifest.h"

namespace icacam::host::loop {

namespace {

struct Row {
    std::string mesh;
    FeSnapshot s;
    double k = 0;
};

// Every snapshot row of one sweep CSV with the columns the base data need, by name.
bool readRows(const std::string &path, std::vector<Row> *rows, std::string *error)
{
    std::ifstream f(path);
    if (!f) { *error = "cannot read '" + path + "'"; return false; }
    std::string line;
    std::vector<std::string> header, cells;
    if (!std::getline(f, line) || !splitCsvLine(line, &header)) { *error = "no header in '" + path + "'"; return false; }
    while (std::getline(f, line)) {
        // Rows written before columns were added at the end have fewer cells: those are empty.
        if (!splitCsvLine(line, &cells) || cells.size() > header.size()) continue;
        cells.resize(header.size());
        ManifestRow row;
        for (size_t i = 0; i < header.size(); ++i) row.cells[header[i]] = cells[i];
        const std::string status = row.get("status");
        if (status != "ok" && status != "failed") continue;
        Row r;
        double e = 210000, d0 = 10, h0 = 15, elem = 0, corner = 0;
        if (!parseNumber(row.get("k_mpa"), &r.k) || !parseNumber(row.get("n"), &r.s.n) ||
            !parseNumber(row.get("mu"), &r.s.mu) || !parseNumber(row.get("reduction"), &r.s.reduction) ||
            !parseNumber(row.get("u_interp_mm"), &r.s.uMm) || !parseNumber(row.get("r_i_mm"), &r.s.riMm) ||
            !parseNumber(row.get("r_o_interp_mm"), &r.s.roMm) || !parseNumber(row.get("r_max_mm"), &r.s.rMaxMm))
            continue;
        // The contact edge tracked between the nodes' touchdowns, where the run has it (docs/fe.md).
        if (double ut = -1; parseNumber(row.get("u_track_mm"), &ut) && ut >= 0) {
            r.s.uMm = ut;
            r.s.roMm = r.s.riMm + ut;
        }
        if (!(r.s.reduction > 0)) continue;
        if (row.has("e_mpa") && parseNumber(row.get("e_mpa"), &e) && std::fabs(e - 210000) > 1) continue;
        if (row.has("d0_mm") && parseNumber(row.get("d0_mm"), &d0) && std::fabs(d0 - 10) > 1e-9) continue;
        if (row.has("h0_mm") && parseNumber(row.get("h0_mm"), &h0) && std::fabs(h0 - 15) > 1e-9) continue;
        parseNumber(row.get("elem_mm"), &elem);
        parseNumber(row.get("corner_mm"), &corner);
        char key[96];
        std::snprintf(key, sizeof key, "%s h%g c%g", row.get("element", "CAX4R").c_str(), elem, corner);
        r.mesh = key;
        rows->push_back(std::move(r));
    }
    return true;
}

} // namespace

bool readFeBaseData(const std::vector<std::string> &paths, FeBaseData *out, std::string *error)
{
    if (paths.empty()) { *error = "no FE sweep CSV given"; return false; }
    std::vector<Row> rows;
    for (const std::string &path : paths)
        if (!readRows(path, &rows, error)) return false;
    std::map<std::string, int> meshCount;
    for (const Row &r : rows)
        if (std::fabs(r.s.reduction - 0.5) < 1e-6) ++meshCount[r.mesh];
    if (meshCount.empty()) { *error = "no FE run reached 50 % reduction in the sweep CSV(s) given"; return false; }
    int best = 0;
    for (const auto &[m, c] : meshCount)
        if (c > best) best = c, out->mesh = m;
    std::map<double, int> kCount;
    for (const Row &r : rows)
        if (r.mesh == out->mesh && std::fabs(r.s.reduction - 0.5) < 1e-6) ++kCount[r.k];
    best = 0;
    for (const auto &[k, c] : kCount)
        if (c > best) best = c, out->kMpa = k;
    out->rows.clear();
    for (const Row &r : rows)
        if (r.mesh == out->mesh && r.k == out->kMpa) out->rows.push_back(r.s);
    return true;
}

} // namespace icacam::host::loop
