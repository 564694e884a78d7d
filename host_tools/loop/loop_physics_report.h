#pragma once
// The report's account of the chosen effect in its physical form (report.md's section and
// physical.csv), and of the symptoms that pointed to it.
#include <ostream>
#include <string>

#include "host_tools/loop/loop_command.h"

namespace icacam::host::loop {

// physical.csv: one row per fitted group (candidate, reading, level, records, declared, value,
// sigma, expanded (k = 2), verdict); for a process variable one row with its slope.
void writePhysicalCsv(const std::string &path, const LoopSummary &s);

// report.md: what the chosen effect is physically, its estimates with their uncertainty, the
// recommendation (recalibrate a camera, revise a material's n, the FE study to run next).
// first: the first effect (its table starts from the model as is), else one added after others.
void writePhysicalSection(std::ostream &f, const LoopEffectStep &e, bool first, const LoopSummary &s);

// report.md: which measured quantities pointed to the chosen cause, and which it was ranked
// ahead of.
void writeSymptomNote(std::ostream &f, const LoopSummary &s);

// One line per estimate for the command's standard output.
void printPhysical(std::ostream &out, const LoopSummary &s);

} // namespace icacam::host::loop
