#include "host_tools/loop/journal_records.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "reading/record_line.h"

namespace icacam::host::loop {

namespace fs = std::filesystem;

namespace {

// One journal line's fields as text (numbers as written, strings unescaped, true/false/null
// as words), read by the record's own line parser (reading/record_line.h).
bool parseFlat(const std::string &s, std::map<std::string, std::string> *out)
{
    static reading::FlatObject object; // large: one, reused line after line
    if (!reading::parseFlatObject(s, &object).empty()) return false;
    for (int i = 0; i < object.count; ++i) {
        const reading::JsonField &f = object.fields[i];
        using Type = reading::JsonField::Type;
        (*out)[f.key] = f.type == Type::Bool ? (f.boolean ? "true" : "false") : f.type == Type::Null ? "null" : f.text;
    }
    return true;
}

// A record id as the join key: the number when it is one (12, 000012, 12.0), else the text.
std::string joinKey(const std::string &id)
{
    double v;
    if (parseNumber(id, &v) && v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string((long long)v);
    return id;
}

// The device's principal results (vision/reading_record.h): renamed device_* so that they
// are symptoms and not taken for a radii record. Its per-edge diagnostics are left out: the
// re-measurement's diag_* carry the current pipeline's.
const char *const kMeasured[] = {"mu",        "mu_sigma",       "u_mm",         "r_inner_mm", "r_outer_mm", "r_max_mm",
                                 "reduction", "reduction_est",  "scale_factor", "status",     "flags",      "message",
                                 "ms",        "plane_height_mm"};
// Settings and conditions the device recorded with each result (the segment frames saved
// beside the image, where the ring was lit in turn, are re-measured with it).
const char *const kConditions[] = {"n",        "k_mpa",       "d0_mm",   "h0_mm",          "mm_per_px",   "h_final_mm",
                                   "material", "calibration", "trigger", "segment_images", "segment0_deg"};

} // namespace

namespace {

// The reference rows by join key; a row the CSV could not read is listed as skipped.
std::map<std::string, const ManifestRow *> referenceById(const Manifest &ref, const std::string &idColumn,
                                                         JournalJoin *info)
{
    std::map<std::string, const ManifestRow *> byId;
    for (const ManifestRow &r : ref.rows) {
        if (!r.error.empty()) {
            info->skipped.push_back("reference line " + std::to_string(r.line) + ": " + r.error);
            continue;
        }
        byId[joinKey(r.get(idColumn))] = &r;
    }
    return byId;
}

// The device's settings as its folder keeps them now (settings.conf, "key = value").
std::map<std::string, std::string> readSettings(const std::string &journalDir)
{
    std::map<std::string, std::string> settings;
    std::ifstream conf(fs::path(journalDir) / "settings.conf");
    std::string l;
    while (std::getline(conf, l)) {
        const size_t eq = l.find(" = ");
        if (eq != std::string::npos) settings[l.substr(0, eq)] = l.substr(eq + 3);
    }
    return settings;
}

// The manifest's columns: the record, the device's conditions, its results as device_*, and
// the reference's columns (ref_<name> where the journal has the name too).
std::vector<std::string> joinedColumns(const Manifest &ref)
{
    std::vector<std::string> columns = {"id", "image"};
    for (const char *c : kConditions) columns.push_back(c);
    for (const char *c : kMeasured) columns.push_back(std::string("device_") + c);
    for (const std::string &c : ref.columns)
        if (c != "id")
            columns.push_back(std::find(columns.begin(), columns.end(), c) == columns.end() ? c : "ref_" + c);
    return columns;
}

// D0 and H0: each result record carries what the device was told; a journal written before
// the records carried them falls back on the reference CSV, then on the device's
// settings.conf as it is now.
struct Geometry {
    bool fromReference = false, fromSettings = false;
    std::map<std::string, std::string> settings;
    int fromRecords = 0, fromElsewhere = 0;

    // What the report says about where the records' D0 and H0 came from.
    std::string note()
    {
        const std::string older = fromReference  ? "from the reference CSV"
                                  : fromSettings ? "from the device's settings.conf as it is now (d0_mm " +
                                                       settings["d0_mm"] + ", h0_mm " + settings["h0_mm"] + ")"
                                                 : "not recorded: 10 and 15 mm assumed";
        return fromElsewhere == 0
                   ? "d0_mm and h0_mm as each record carries them"
                   : "d0_mm and h0_mm as each record carries them; for " + std::to_string(fromElsewhere) + " of " +
                         std::to_string(fromRecords + fromElsewhere) + " records " + older;
    }
};

// One intact result line joined with its reference row: the manifest's row, or why the
// result is left out.
std::string joinResult(std::map<std::string, std::string> &f, const ManifestRow &reference, const std::string &idColumn,
                       int line, const std::string &calibrationDir, Geometry *geometry, ManifestRow *row)
{
    if (f["image"].empty()) return "no saved frame (journal.images none, or an error before capture)";
    std::string calibration;
    if (!f["calibration"].empty()) {
        // The journal names the file; the device read it beside its config.
        const fs::path file = fs::path(calibrationDir) / fs::path(f["calibration"]).filename();
        if (!fs::exists(file))
            return "measured through calibration '" + f["calibration"] + "', which is not in '" + calibrationDir +
                   "' (name its folder with --calibrations)";
        calibration = fs::absolute(file).string();
    }
    row->line = line;
    row->cells["id"] = f["id"];
    row->cells["image"] = f["image"];
    for (const char *c : kConditions) row->cells[c] = f[c];
    row->cells["calibration"] = calibration;
    for (const char *c : kMeasured) row->cells[std::string("device_") + c] = f[c];
    const bool recordGeometry = !f["d0_mm"].empty() && !f["h0_mm"].empty();
    if (recordGeometry)
        ++geometry->fromRecords;
    else
        ++geometry->fromElsewhere;
    if (!recordGeometry && !geometry->fromReference && geometry->fromSettings)
        row->cells["d0_mm"] = geometry->settings["d0_mm"], row->cells["h0_mm"] = geometry->settings["h0_mm"];
    for (const auto &[k, v] : reference.cells) {
        if (k == idColumn) continue;
        const bool journalHas = row->cells.count(k) > 0;
        const bool journalEmpty = journalHas && (row->cells[k].empty() || (k == "h_final_mm" && row->cells[k] == "0"));
        if (!journalHas || journalEmpty)
            row->cells[k] = v;
        else
            row->cells["ref_" + k] = v;
    }
    return "";
}

} // namespace

bool readJournalManifest(const std::string &journalDir, const std::string &referenceCsv, Manifest *out,
                         JournalJoin *info, std::string *error, const std::string &calibrationDir)
{
    const std::string calibrations = calibrationDir.empty() ? journalDir : calibrationDir;
    *info = {};
    Manifest ref;
    if (!readManifest(referenceCsv, &ref, error)) return false;
    const std::string idColumn = ref.hasColumn("id") ? "id" : ref.hasColumn("record_id") ? "record_id" : "";
    if (idColumn.empty()) {
        *error = "reference CSV '" + referenceCsv + "' has no id (or record_id) column";
        return false;
    }
    const std::map<std::string, const ManifestRow *> byId = referenceById(ref, idColumn, info);
    Geometry geometry;
    geometry.settings = readSettings(journalDir);
    geometry.fromReference = ref.hasColumn("d0_mm") && ref.hasColumn("h0_mm");
    geometry.fromSettings = geometry.settings.count("d0_mm") && geometry.settings.count("h0_mm");
    const fs::path journal = fs::path(journalDir) / "journal.jsonl";
    std::ifstream in(journal);
    if (!in) {
        *error = "cannot read the journal '" + journal.string() + "'";
        return false;
    }
    *out = {};
    out->baseDir = journalDir;
    out->columns = joinedColumns(ref);
    std::map<std::string, bool> used;
    std::string line;
    while (std::getline(in, line)) {
        ++info->lines;
        std::map<std::string, std::string> f;
        if (!reading::recordLineIntact(line) || !parseFlat(line, &f)) {
            info->skipped.push_back("journal line " + std::to_string(info->lines) + ": damaged (CRC or JSON)");
            continue;
        }
        if (f["type"] == "scalecheck") {
            ++info->scaleChecks;
            continue;
        }
        if (f["type"] != "result") continue;
        ++info->results;
        const std::string what = "journal record " + f["id"];
        const auto it = byId.find(joinKey(f["id"]));
        if (it == byId.end()) {
            info->skipped.push_back(what + ": no row in the reference CSV");
            continue;
        }
        used[it->first] = true;
        ManifestRow row;
        if (const std::string why = joinResult(f, *it->second, idColumn, info->lines, calibrations, &geometry, &row);
            !why.empty()) {
            info->skipped.push_back(what + ": " + why);
            continue;
        }
        info->calibrated += row.get("calibration").empty() ? 0 : 1;
        out->rows.push_back(std::move(row));
        ++info->joined;
    }
    for (const auto &[key, row] : byId)
        if (!used.count(key)) info->skipped.push_back("reference id " + row->get(idColumn) + ": not in the journal");
    info->geometry = geometry.note();
    return true;
}

} // namespace icacam::host::loop
