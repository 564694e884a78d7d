// `icacam synth`: render a set of synthetic end-face images with a manifest and the truth.
#include "host_tools/synth_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "friction/paper_model.h"
#include "host_tools/cli_options.h"
#include "host_tools/end_face_renderer.h"
#include "host_tools/manifest.h"
#include "host_tools/model_inverse.h"
#include "host_tools/number_text.h"
#include "host_tools/photo/photo_command.h"
#include "host_tools/synth_conditions.h"
#include "host_tools/synth_loop_set.h"

namespace icacam::host {

namespace fs = std::filesystem;

namespace {
// The image count unless --count says otherwise (per condition with --condition).
constexpr double kDefaultCount = 10;

std::string usage()
{
    return "usage: icacam synth --out DIR [--count N] [--seed S] [--hard]\n"
           "       icacam synth --out DIR --condition all|NAME[,NAME...] [--count N] [--seed S] [--hard]\n"
           "       icacam synth --renderer povray --out DIR ... (photographs: icacam synth --renderer povray --help)\n"
           "       icacam synth --out DIR --effect "
           "process|optical|camera|material|speed|drift|speed_material|rate|null[,...]\n"
           "                    [--radii] [--count N] [--seed S]\n"
           "  --out DIR     where DIR/images/*, DIR/manifest.csv and DIR/truth.csv are written\n"
           "  --count N     records (default " +
           numberText("%g", kDefaultCount) +
           "; per condition with --condition)\n"
           "  --seed S      the random seed (default 1): the same seed, the same set\n"
           "  --hard        the rendering nuisances (blur, noise, contrast …) at their limits\n"
           "  --effect E    a record set for `icacam loop` (mu_ref and recorded columns) carrying that\n"
           "                hidden effect (or several: camera,material), as images or (--radii) as\n"
           "                measured radii (docs/loop.md)\n"
           "  --condition   records under conditions a manifest does not declare (" +
           conditionNames() +
           "),\n"
           "                truth.csv naming the condition and its true parameters; score a measurement\n"
           "                with `icacam score` (docs/uncertainty.md)\n";
}
} // namespace

int synthCommand(const std::vector<std::string> &args)
{
    // The photographic bench renders with POV-Ray and has options of its own.
    if (photo::wantsPovray(args)) return photo::photoSynthCommand(args);
    std::string outDir, effect, conditions;
    double count = kDefaultCount, seed = 1;
    bool hard = false, radii = false;
    cli::OptionReader opts(args, usage());
    while (opts.next()) {
        if (opts.isHelp()) {
            std::cout << usage();
            return 0;
        } else if (opts.is("--out"))
            outDir = opts.value();
        else if (opts.is("--count"))
            count = double(opts.wholeNumber(1, 100000));
        else if (opts.is("--seed"))
            seed = double(opts.wholeNumber(0, 4294967295L));
        else if (opts.is("--hard"))
            hard = opts.flag();
        else if (opts.is("--effect"))
            effect = opts.value();
        else if (opts.is("--radii"))
            radii = opts.flag();
        else if (opts.is("--condition"))
            conditions = opts.value();
        else
            opts.unknown();
    }
    if (outDir.empty()) opts.missing("--out");
    if (radii && effect.empty()) throw cli::UsageError("--radii applies to --effect sets", usage());
    if (!effect.empty() && !conditions.empty())
        throw cli::UsageError("--effect and --condition do not combine", usage());
    if (!effect.empty()) {
        LoopSetOptions opt;
        if (!parseLoopEffect(effect, &opt.effect))
            throw cli::UsageError(
                "--effect: process, optical, camera, material, speed, drift, speed_material, rate or null, "
                "or a comma list of "
                "them, not '" +
                    effect + "'",
                usage());
        if (hard) throw cli::UsageError("--hard does not apply to --effect sets", usage());
        opt.count = int(count);
        opt.seed = uint32_t(seed);
        opt.radii = radii;
        const std::string manifest = writeLoopSet(outDir, opt);
        std::cerr << "icacam synth: wrote " << opt.count << " records with the " << effect << " effect: " << manifest
                  << "\n";
        return 0;
    }
    if (!conditions.empty()) {
        ConditionSetOptions opt;
        if (!parseConditions(conditions, &opt.conditions))
            throw cli::UsageError("--condition: all, or a comma-separated list of " + conditionNames(), usage());
        opt.countPerCondition = int(count);
        opt.seed = uint32_t(seed);
        opt.hard = hard;
        const std::string manifest = writeConditionSet(outDir, opt);
        std::cerr << "icacam synth: wrote " << opt.countPerCondition * int(opt.conditions.size()) << " records ("
                  << conditions << "): " << manifest << "\n";
        return 0;
    }
    fs::create_directories(fs::path(outDir) / "images");
    std::ofstream man(fs::path(outDir) / "manifest.csv"), truth(fs::path(outDir) / "truth.csv");
    man << "id,image,n,k_mpa,d0_mm,h0_mm,mm_per_px\n";
    truth << "id,mu,u_mm,r_inner_mm,r_outer_mm,r_bulge_mm,u_px,blur_px,noise,contrast\n";
    std::mt19937 rng{uint32_t(seed)};
    auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    friction::PaperModel model;
    for (int i = 0; i < int(count); ++i) {
        const double n = U(0.05, 0.5), mu = U(0.06, 0.29);
        const double u = uForMu(model, mu, n);
        const double rOuter = 6.85 - 0.95 * u + U(-0.05, 0.05);
        const double rMax = 5.0 * std::sqrt(2.0) * (1.008 + 0.034 * u);
        EndFaceScene s = randomScene(rng, u, rOuter, rMax, hard);
        const cv::Mat img = renderEndFace(s);
        const auto bytes = encodeEndFace(s, img);
        char id[32];
        std::snprintf(id, sizeof id, "synth-%04d", i + 1);
        const std::string name = std::string(id) + (s.jpegQuality ? ".jpg" : ".png");
        std::ofstream(fs::path(outDir) / "images" / name, std::ios::binary)
            .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
        const double ri = s.rInnerEqMm(), ro = s.rOuterEqMm();
        const double muTrue = model.estimate({ro - ri, n, 0, 10, 15}).mu;
        char line[512];
        std::snprintf(line, sizeof line, "%s,images/%s,%.4f,%d,10,15,%.7f\n", id, name.c_str(), n, int(U(250, 1250)),
                      s.mmPerPx);
        man << line;
        std::snprintf(line, sizeof line, "%s,%.5f,%.5f,%.5f,%.5f,%.4f,%.2f,%.2f,%.2f,%.1f\n", id, muTrue, ro - ri, ri,
                      ro, s.rMaxMm, (ro - ri) / s.mmPerPx, s.blurSigmaPx, s.noiseSigma, s.face - s.ica);
        truth << line;
    }
    std::cerr << "icacam synth: wrote " << int(count) << " images to " << outDir << "\n";
    return 0;
}

} // namespace icacam::host
