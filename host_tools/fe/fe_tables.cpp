#include "host_tools/fe/fe_tables.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "host_tools/cli_options.h"
#include "host_tools/fe/fe_aspect.h"
#include "host_tools/fe/fe_fit.h"
#include "host_tools/fe/reduction_table.h"
#include "host_tools/number_text.h"

namespace icacam::host::fe {

namespace fs = std::filesystem;

namespace {

const char *kUsage =
    "usage: icacam fe tables --base CSV [--k-family CSV]... [--aspect CSV]... [--out friction] [--reduction 0.5]\n"
    "Writes every generated table the friction models read, from one FE base (run from the repository's top):\n"
    "  fe_model_table.h   u, R_i, R_o, R_max of the base at 30-60 % reduction, and the K carry: the\n"
    "                     differences in K within the --k-family runs (one family at several K, the\n"
    "                     base's K among them)\n"
    "  reduction_table.h  du/dr at 50 % from the base's snapshots (the reduction carry; `icacam loop`'s FE data)\n"
    "  aspect_table.h     u(H0/D0)/u(1.5) and R_max(H0/D0)/R_max(1.5) within the --aspect runs (other H0\n"
    "                     and their 1.5 reference of the same family)\n"
    "Each header names this command and its input files; tests/friction check them against the CSVs.\n";

// A file as the repository names it: relative to the working directory where it lies under it.
std::string repositoryName(const std::string &path)
{
    std::error_code ec;
    const fs::path rel = fs::relative(path, fs::current_path(), ec);
    if (!ec && !rel.empty() && rel.native().rfind("..", 0) != 0) return rel.generic_string();
    return path;
}

} // namespace

TablesRequest parseTablesArgs(const std::vector<std::string> &args)
{
    TablesRequest r;
    cli::OptionReader opts(args, kUsage);
    while (opts.next()) {
        if (opts.isHelp())
            throw cli::UsageError("--help is answered by the command", kUsage);
        else if (opts.is("--base")) {
            const std::string v = opts.value();
            if (!r.src.base.empty()) opts.fail("one --base: the tables stand on one FE base");
            r.src.base = repositoryName(v);
        } else if (opts.is("--k-family"))
            r.src.kFamily.push_back(repositoryName(opts.value()));
        else if (opts.is("--aspect"))
            r.src.aspect.push_back(repositoryName(opts.value()));
        else if (opts.is("--out"))
            r.outDir = opts.value();
        else if (opts.is("--reduction")) {
            r.reduction = opts.number();
            if (!(r.reduction > 0 && r.reduction < 1)) opts.fail("a height reduction between 0 and 1 (exclusive)");
        } else
            opts.unknown();
    }
    if (r.src.base.empty()) opts.missing("--base CSV");
    std::string c = "icacam fe tables --base " + r.src.base;
    for (const std::string &f : r.src.kFamily) c += " --k-family " + f;
    for (const std::string &f : r.src.aspect) c += " --aspect " + f;
    if (r.reduction != 0.5) c += " --reduction " + numberText("%g", r.reduction);
    r.src.command = c;
    return r;
}

std::vector<TableText> tablesText(const TablesRequest &request, const std::string &sourceDir)
{
    std::vector<TableText> out(3);
    out[0].file = "fe_model_table.h";
    out[0].text = feModelTableText(request.src, sourceDir, request.reduction, &out[0].summary);
    out[1].file = "reduction_table.h";
    std::string error;
    out[1].text = reductionTableText(request.src, sourceDir, &error);
    if (out[1].text.empty()) throw std::runtime_error("reduction table: " + error);
    out[1].summary = "du/dr at 50 % from " + request.src.base;
    out[2].file = "aspect_table.h";
    if (request.src.aspect.empty()) throw std::runtime_error("--aspect CSV is needed: the slenderness carry's runs");
    out[2].text = aspectTableText(request.src, sourceDir, &out[2].summary);
    return out;
}

int tablesCommand(const std::vector<std::string> &args)
{
    for (const std::string &a : args)
        if (a == "-h" || a == "--help") {
            std::cout << kUsage;
            return 0;
        }
    const TablesRequest request = parseTablesArgs(args);
    // Every text first: a failing input leaves the committed tables as they are.
    const std::vector<TableText> tables = tablesText(request, "");
    for (const TableText &t : tables) {
        const fs::path path = fs::path(request.outDir) / t.file;
        std::ofstream f(path, std::ios::binary);
        if (!(f << t.text)) throw std::runtime_error("cannot write " + path.string());
        std::cout << t.file << ": " << t.summary << " -> " << path.string() << "\n";
    }
    return 0;
}

} // namespace icacam::host::fe
