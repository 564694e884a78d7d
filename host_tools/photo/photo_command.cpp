#include "host_tools/photo/photo_command.h"

#include <iostream>

#include "host_tools/cli_options.h"
#include "host_tools/photo/barrel_profile.h"
#include "host_tools/photo/photo_bench.h"

#ifndef ICACAM_PHOTOBENCH_PROFILES
#define ICACAM_PHOTOBENCH_PROFILES "data/photobench/fe_profiles.csv"
#endif

namespace icacam::host::photo {

namespace {

std::string usage()
{
    const PhotoBenchOptions d;
    return "usage: icacam synth --renderer povray --out DIR [--condition LIST|all] [--count N] [--seed S]\n"
           "                    [--first K] [--profile LIST|all] [--small|--large] [--quality 'POV-Ray options']\n"
           "                    [--profiles CSV] [--flat-barrel Q] [--povray PATH] [--keep-render] [--labels]\n"
           "                    [--encoding sensor|png|jpeg] [--segments N] [--quiet]\n"
           "       icacam synth --renderer povray --make-profiles CSV --fe-work DIR [--ccx PATH]\n"
           "Photographs rendered with real light transport (POV-Ray): a ring light of 12-32 LEDs about the\n"
           "lens, metallic finishes with gloss, turning grooves, stains, the barrel through the FE's free\n"
           "surface, shadows on the fixture, a pinhole 45-95 mm above the end face; then lens blur,\n"
           "vignetting, shot and read noise, JPEG or PNG. DIR/manifest.csv says what a lab would declare,\n"
           "DIR/truth.csv what was rendered (`icacam score` reads it), DIR/scenes/ the scenes.\n"
           "  --condition   " +
           conditionNames() + " (default straight)\n" + "  --profile     the zones' order of brightness, in turn (" +
           profileNames() +
           "; default all)\n"
           "  --count N     records per condition (default " +
           std::to_string(d.countPerCondition) +
           "); --first K numbers them from K (a record is the same at any count)\n"
           "  --small       640 x 480 (the CI size); --large 2028 x 1520; else 1456 x 1088 (lowres: 640 x 480\n"
           "                or 1280 x 720)\n"
           "  --quality     POV-Ray's anti-aliasing options (default '" +
           d.quality +
           "')\n"
           "  --labels      also DIR/labels/<id>.png: the zones as flat greys (face 255, ring 170, barrel 85,\n"
           "                fixture 0) through the same camera, to check the truth's projections against\n"
           "  --encoding    sensor (default: JPEG 80-95 or PNG as drawn), png (every photograph), jpeg\n"
           "                (every photograph; a PNG draw at quality 92)\n"
           "  --segments N  also N frames under a segmented ring light, one segment lit in each (0: none,\n"
           "                the default; 2, 3, 4, 6 or 8): DIR/images/<id>-s<k>.<ext>, segment k centred at\n"
           "                image azimuth k*360/N degrees from +x (right) towards +y (down), the exposure\n"
           "                locked at N x the full frame's; listed in the manifest's column segment_images\n"
           "  --quiet       no line per record on stderr\n"
           "  --keep-render keep POV-Ray's linear 16-bit render in DIR/scenes/\n"
           "  --profiles    the FE barrel profiles (default " ICACAM_PHOTOBENCH_PROFILES ")\n"
           "  --flat-barrel Q  the side flattened about its widest section: each FE point at zeta^(1/Q) of\n"
           "                the half height from the mid-plane (default 1, the FE's shape; 3-4 reach R_max\n"
           "                within 1-2 mm of the end face, as a parametric barrel does)\n"
           "  --make-profiles CSV --fe-work DIR: solve (or reuse in DIR) the FE cases of the profile grid\n"
           "                with CalculiX and write their free surfaces to CSV\n";
}

} // namespace

bool wantsPovray(const std::vector<std::string> &args)
{
    for (size_t i = 0; i < args.size(); ++i)
        if ((args[i] == "--renderer" && i + 1 < args.size() && args[i + 1] == "povray") ||
            args[i] == "--renderer=povray")
            return true;
    return false;
}

int photoSynthCommand(const std::vector<std::string> &args)
{
    PhotoBenchOptions opt;
    opt.profilesCsv = ICACAM_PHOTOBENCH_PROFILES;
    std::string outDir, makeProfiles, feWork, ccx = "ccx";
    cli::OptionReader opts(args, usage());
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << usage();
            return 0;
        } else if (opts.is("--renderer")) {
            if (opts.value() != "povray") opts.fail("povray here");
        } else if (opts.is("--out"))
            outDir = opts.value();
        else if (opts.is("--condition")) {
            if (!parseConditions(opts.value(), &opt.conditions)) opts.fail("all, or a list of " + conditionNames());
        } else if (opts.is("--profile")) {
            if (!parseProfiles(opts.value(), &opt.profiles)) opts.fail("all, or a list of " + profileNames());
        } else if (opts.is("--count"))
            opt.countPerCondition = int(opts.wholeNumber(1, 100000));
        else if (opts.is("--seed"))
            opt.seed = uint32_t(opts.wholeNumber(0, 4294967295L));
        else if (opts.is("--first"))
            opt.first = int(opts.wholeNumber(1, 1000000));
        else if (opts.is("--small") || opts.is("--large")) {
            const PhotoFrame frame = opts.is("--small") ? PhotoFrame::Small : PhotoFrame::Large;
            opts.flag();
            if (opt.frame != PhotoFrame::Full && opt.frame != frame) opts.fail("one frame size: --small or --large");
            opt.frame = frame;
        } else if (opts.is("--quality"))
            opt.quality = opts.value();
        else if (opts.is("--profiles"))
            opt.profilesCsv = opts.value();
        else if (opts.is("--flat-barrel"))
            opt.barrelFlatness = opts.number(1, 10);
        else if (opts.is("--povray"))
            opt.povray = opts.value();
        else if (opts.is("--keep-render"))
            opt.keepRender = opts.flag();
        else if (opts.is("--labels"))
            opt.labels = opts.flag();
        else if (opts.is("--encoding")) {
            const std::string v = opts.value();
            if (v == "sensor")
                opt.encoding = PhotoBenchOptions::Encoding::Sensor;
            else if (v == "png")
                opt.encoding = PhotoBenchOptions::Encoding::Png;
            else if (v == "jpeg")
                opt.encoding = PhotoBenchOptions::Encoding::Jpeg;
            else
                opts.fail("sensor, png or jpeg, not '" + v + "'");
        } else if (opts.is("--segments")) {
            opt.segments = int(opts.wholeNumber(0, 8));
            if (opt.segments == 1 || opt.segments == 5 || opt.segments == 7) opts.fail("0, 2, 3, 4, 6 or 8");
        } else if (opts.is("--quiet"))
            opt.quiet = opts.flag();
        else if (opts.is("--make-profiles"))
            makeProfiles = opts.value();
        else if (opts.is("--fe-work"))
            feWork = opts.value();
        else if (opts.is("--ccx"))
            ccx = opts.value();
        else
            opts.unknown();
    }
    if (!makeProfiles.empty()) {
        if (feWork.empty()) opts.missing("--fe-work (where the FE cases are solved or found)");
        makeBarrelProfiles(makeProfiles, feWork, ccx);
        std::cerr << "icacam synth: wrote " << makeProfiles << "\n";
        return 0;
    }
    if (outDir.empty()) opts.missing("--out");
    const std::string manifest = writePhotoSet(outDir, opt);
    std::cerr << "icacam synth: wrote " << opt.countPerCondition * int(opt.conditions.size())
              << " photographs: " << manifest << "\n";
    return 0;
}

} // namespace icacam::host::photo
