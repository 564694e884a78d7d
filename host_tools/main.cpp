// icacam: the PC side of the instrument. One binary, subcommands (like git).
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "host_tools/calibrate_command.h"
#include "host_tools/cli_options.h"
#include "host_tools/ctl_command.h"
#include "host_tools/fe/fe_command.h"
#include "host_tools/fe/fe_tables.h"
#include "host_tools/loop/loop_command.h"
#include "host_tools/measure_command.h"
#include "host_tools/outline_table.h"
#include "host_tools/score_command.h"
#include "host_tools/synth_command.h"

namespace {
const char *kHelp = "usage: icacam <command> [options]\n"
                    "commands:\n"
                    "  measure   measure μ from saved end-face images listed in a manifest\n"
                    "  synth     render synthetic end-face images with ground truth\n"
                    "  score     judge measured results against a truth file, per condition\n"
                    "  calibrate camera intrinsics, distortion and fixture pose from board photos\n"
                    "  fe        CalculiX upsetting runs, sweeps and the μ model built from them\n"
                    "  loop      residuals against measured records: rank causes, correct, report\n"
                    "  ctl       talk to the device over its serial line (status, trigger, settings, results)\n"
                    "Run 'icacam <command> --help' for the options of one command.\n";
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::cerr << "icacam: a command is needed\n" << kHelp;
        return 2;
    }
    const std::string cmd = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    try {
        if (cmd == "measure") return icacam::host::measureCommand(args);
        if (cmd == "synth") return icacam::host::synthCommand(args);
        if (cmd == "score") return icacam::host::scoreCommand(args);
        if (cmd == "calibrate") return icacam::host::calibrateCommand(args);
        // `fe tables` needs the loop's du/dr fit as well as the FE readers: linked here, above both.
        if (cmd == "fe" && !args.empty() && args[0] == "tables")
            return icacam::host::fe::tablesCommand({args.begin() + 1, args.end()});
        // `fe outline-table` reads the photographic bench's barrel profiles (the host library).
        if (cmd == "fe" && !args.empty() && args[0] == "outline-table")
            return icacam::host::outlineTableCommand({args.begin() + 1, args.end()});
        if (cmd == "fe") return icacam::host::feCommand(args);
        if (cmd == "loop") return icacam::host::loopCommand(args);
        if (cmd == "ctl") return icacam::host::ctlCommand(args);
        if (cmd == "-h" || cmd == "--help" || cmd == "help") {
            std::cout << kHelp;
            return 0;
        }
        std::cerr << "icacam: unknown command '" << cmd << "'\n" << kHelp;
        return 2;
    } catch (const icacam::host::cli::UsageError &e) {
        // A mistake on the command line: what it is, then how the command is used.
        std::cerr << "icacam " << cmd << ": error: " << e.what() << "\n" << e.usage();
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "icacam " << cmd << ": error: " << e.what() << "\n";
        return 1;
    }
}
