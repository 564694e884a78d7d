#include "host_tools/calibrate_command.h"

#include <iostream>

#include "host_tools/camera_calibrator.h"
#include "host_tools/cli_options.h"

namespace icacam::host {

namespace {

const char *kUsage = "usage: icacam calibrate --images DIR --board chessboard:COLSxROWS:SQUARE_MM\n"
                     "                        --flat PHOTO --out FILE [--board-thickness MM]\n"
                     "                        [--max-rms PX] [--max-blur PX] [--free-k3]\n"
                     "  --images DIR   photos of the board in different poses (png/jpg/tif/bmp/pgm)\n"
                     "  --board        chessboard:COLSxROWS:SQUARE_MM (inner corners, square side) or\n"
                     "                 circles:COLSxROWS:SPACING_MM (symmetric grid of dark dots)\n"
                     "  --flat PHOTO   the photo with the board lying flat on the fixture (path, or a name\n"
                     "                 in DIR): gives the fixture plane's pose\n"
                     "  --board-thickness MM  the board's surface above the fixture (default 0)\n"
                     "  --max-rms PX   refuse a calibration whose RMS reprojection error is above this\n"
                     "                 (default 0.5: the corners are not found to the accuracy a scale needs)\n"
                     "  --max-blur PX  also refuse views whose board edges (squares or dots) are wider than\n"
                     "                 this (default: no limit; views are judged by their reprojection error)\n"
                     "  --free-k3      also fit k3 (default: fixed at 0, ill-determined in a narrow field)\n"
                     "Needs at least 5 usable views. A view whose corners do not fit the calibration (its\n"
                     "reprojection error 4 times the median view's and above 0.3 px: the board moved, bent\n"
                     "or was misdetected) is dropped with a message. See docs/calibration.md.\n";

} // namespace

int calibrateCommand(const std::vector<std::string> &args)
{
    CameraCalibrationInputs in;
    std::string outPath;
    cli::OptionReader opts(args, kUsage);
    auto number = [&](double *v) {
        *v = opts.number();
        if (*v < 0) opts.fail("a non-negative number");
    };
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << kUsage;
            return 0;
        } else if (opts.is("--images"))
            in.imagesDir = opts.value();
        else if (opts.is("--board"))
            in.board = opts.value();
        else if (opts.is("--flat"))
            in.flatPhoto = opts.value();
        else if (opts.is("--out"))
            outPath = opts.value();
        else if (opts.is("--board-thickness"))
            number(&in.boardThicknessMm);
        else if (opts.is("--max-blur"))
            number(&in.maxBlurPx);
        else if (opts.is("--max-rms"))
            number(&in.maxRmsPx);
        else if (opts.is("--free-k3"))
            in.freeK3 = opts.flag();
        else
            opts.unknown();
    }
    if (in.imagesDir.empty() || in.board.empty() || in.flatPhoto.empty() || outPath.empty())
        opts.missing("--images, --board, --flat and --out (all are needed)");
    writeCameraCalibration(in, outPath);
    return 0;
}

} // namespace icacam::host
