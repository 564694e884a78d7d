#pragma once
// An icacam-fw journal folder (docs/firmware.md, "Journal": journal.jsonl, one CRC-closed JSON
// line per result, and the saved frames img-NNNNNN.pgm) joined by record id with a CSV of
// reference values, as a manifest the loop measures like any other: each joined result with a
// saved frame becomes an image record, re-measured with the current pipeline.
#include <cstdint>
#include <string>
#include <vector>

#include "host_tools/manifest.h"

namespace icacam::host::loop {

struct JournalJoin {
    int lines = 0;                    // lines in journal.jsonl
    int results = 0;                  // intact result lines
    int joined = 0;                   // results with a reference row and a saved frame: the manifest's rows
    int scaleChecks = 0;              // scale-check lines (not measurements)
    int calibrated = 0;               // joined results the device measured through a calibration file
    std::vector<std::string> skipped; // "what: why", one per line or reference row left out
    // Where D0 and H0 came from: the result records do not carry them (the reference CSV's
    // d0_mm/h0_mm, else the device's settings.conf as it is now, else 10 and 15 mm).
    std::string geometry;
};

// Columns of the manifest: id (the journal's record id), image (the saved frame), the
// device's settings as it measured (n, k_mpa, mm_per_px, h_final_mm, material, calibration,
// trigger), what the device measured then, prefixed device_ (device_mu, device_u_mm,
// device_r_inner_mm, ..., device_status: symptoms, kept for the ranking and the comparison),
// and every column of the reference CSV (mu_ref and whatever the lab recorded: camera,
// press speed, ...). A reference column the journal also has fills it where the journal's is
// empty (an undeclared h_final_mm of 0 counts as empty) and is kept as ref_<name> otherwise.
// Ids join by number (12 = 000012) or else as text. False only when the journal or the CSV
// cannot be read. The reference's id column is `id` (or `record_id`).
//
// A result the device measured through a calibration file (its `calibration`, the file's
// name) is re-measured through that file, as the device did (the boundaries mapped into the
// end-face plane at h_final_mm, else h0_mm / 2): the file is looked for in calibrationDir
// (empty: the journal folder); a record whose file is not there is left out, with why. The
// plane the device mapped at is kept as device_plane_height_mm.
bool readJournalManifest(const std::string &journalDir, const std::string &referenceCsv, Manifest *out,
                         JournalJoin *info, std::string *error, const std::string &calibrationDir = "");

} // namespace icacam::host::loop
