#pragma once
// One loop record from one manifest row, read through the instrument as `icacam measure`
// reads it (host_tools/record_measurer.h): an image row measured and interpreted, a radii row
// (r_inner_mm, r_outer_mm, optionally r_bulge_mm) interpreted. The record keeps the face at
// the declared scale and the model's estimate there (the loop looks for what was not
// declared, so the reading's own silhouette correction stays out), and an image's diagnostics.
#include <string>

#include "host_tools/loop/loop_analysis.h"
#include "host_tools/manifest.h"
#include "host_tools/record_measurer.h"

namespace icacam::host::loop {

// False with *why set when the row cannot be used (no mu_ref, no n, neither image nor radii,
// or the image not measured).
bool readLoopRecord(const ManifestRow &row, const Manifest &manifest, RecordMeasurer &measurer, LoopRecord *r,
                    std::string *why);

} // namespace icacam::host::loop
