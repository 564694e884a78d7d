#pragma once
// `icacam fe tables`: every generated table the models read (friction/fe_model_table.h,
// reduction_table.h, aspect_table.h) by one command from one named FE base, each header saying
// the command and its input files (docs/fe.md, data/fe/README.md).
#include <string>
#include <vector>

#include "host_tools/fe/fe_table_sources.h"

namespace icacam::host::fe {

struct TablesRequest {
    TableSources src; // src.command: the canonical command (no --out)
    std::string outDir = "friction";
    double reduction = 0.5; // the FE model's own reduction when none is declared
};

// `--base CSV [--k-family CSV]... [--aspect CSV]... [--reduction 0.5] [--out DIR]`: files named
// as given, relative to the working directory (the repository's top) where they lie under it.
// Throws on a bad or missing option.
TablesRequest parseTablesArgs(const std::vector<std::string> &args);

struct TableText {
    std::string file; // the header's name in outDir
    std::string text;
    std::string summary; // one line on what it holds
};
// The three headers' texts, the files read under sourceDir ("" or a path ending in '/').
// Throws when an input cannot be read or holds no usable runs.
std::vector<TableText> tablesText(const TablesRequest &request, const std::string &sourceDir);

int tablesCommand(const std::vector<std::string> &args);

} // namespace icacam::host::fe
