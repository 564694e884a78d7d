// `icacam synth`: render a set of synthetic end-face images with a manifest and the truth.
#include "synth_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "end_face_renderer.h"
#include "manifest.h"
#include "synth_conditions.h"
#include "synth_loop_set.h"
#include "vision/model/paper_model.h"

namespace icacam::host {

namespace fs = std::filesystem;

double uForMu(double mu, double n)
{
    vision::PaperModel model;
    double lo = 0.0, hi = 1.25;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (model.estimate({mid, n, 0, 10, 15}).mu < mu ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

int synthCommand(const std::vector<std::string> &args)
{
    std::string outDir, effect, conditions;
    double count = 10, seed = 1;
    bool hard = false, radii = false;
    for (size_t i = 0; i < args.size(); ++i) {
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) throw std::runtime_error(args[i] + " needs a value");
            return args[++i];
        };
        if (args[i] == "--out") outDir = value();
        else if (args[i] == "--count") { if (!parseNumber(value(), &count) || count < 1) throw std::runtime_error("bad --count"); }
        else if (args[i] == "--seed") { if (!parseNumber(value(), &seed)) throw std::runtime_error("bad --seed"); }
        else if (args[i] == "--hard") hard = true;
        else if (args[i] == "--effect") effect = value();
        else if (args[i] == "--radii") radii = true;
        else if (args[i] == "--condition") conditions = value();
        else if (args[i] == "-h" || args[i] == "--help") {
            std::cout << "usage: icacam synth --out DIR [--count N] [--seed S] [--hard]\n"
                         "       icacam synth --out DIR --condition all|NAME[,NAME...] [--count N] [--seed S] [--hard]\n"
                         "       icacam synth --out DIR --effect process|optical|camera|material|speed|null\n"
                         "                    [--radii] [--count N] [--seed S]\n"
                         "Writes DIR/images/*, DIR/manifest.csv and DIR/truth.csv. With --effect: a record\n"
                         "set for `icacam loop` (mu_ref and recorded columns) carrying that hidden effect,\n"
                         "as images or (--radii) as measured radii (docs/loop.md). With --condition: N records\n"
                         "per condition a manifest does not declare (" + conditionNames() + "),\n"
                         "truth.csv naming the condition and its true parameters; score a measurement with\n"
                         "`icacam score` (docs/uncertainty.md).\n";
            return 0;
        } else throw std::runtime_error("unknown option '" + args[i] + "'");
    }
    if (outDir.empty()) throw std::runtime_error("--out is required");
    if (radii && effect.empty()) throw std::runtime_error("--radii applies to --effect sets");
    if (!effect.empty() && !conditions.empty()) throw std::runtime_error("--effect and --condition do not combine");
    if (!effect.empty()) {
        LoopSetOptions opt;
        if (!parseLoopEffect(effect, &opt.effect))
            throw std::runtime_error("--effect: process, optical, camera, material, speed or null");
        if (hard) throw std::runtime_error("--hard does not apply to --effect sets");
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
            throw std::runtime_error("--condition: all, or a comma-separated list of " + conditionNames());
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
    vision::PaperModel model;
    for (int i = 0; i < int(count); ++i) {
        const double n = U(0.05, 0.5), mu = U(0.06, 0.29);
        const double u = uForMu(mu, n);
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
        std::snprintf(line, sizeof line, "%s,images/%s,%.4f,%d,10,15,%.7f\n", id, name.c_str(), n,
                      int(U(250, 1250)), s.mmPerPx);
        man << line;
        std::snprintf(line, sizeof line, "%s,%.5f,%.5f,%.5f,%.5f,%.4f,%.2f,%.2f,%.2f,%.1f\n", id, muTrue,
                      ro - ri, ri, ro, s.rMaxMm, (ro - ri) / s.mmPerPx, s.blurSigmaPx, s.noiseSigma,
                      s.face - s.ica);
        truth << line;
    }
    std::cerr << "icacam synth: wrote " << int(count) << " images to " << outDir << "\n";
    return 0;
}

} // namespace icacam::host
