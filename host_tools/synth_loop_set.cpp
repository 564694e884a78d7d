#include "synth_loop_set.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include "end_face_renderer.h"
#include "synth_command.h"
#include "vision/model/radii_consistency.h"
#include "vision/model/reduction_corrected_model.h"

namespace icacam::host {

namespace fs = std::filesystem;

bool parseLoopEffect(const std::string &name, LoopEffect *out)
{
    if (name == "null") *out = LoopEffect::Null;
    else if (name == "process") *out = LoopEffect::Process;
    else if (name == "optical") *out = LoopEffect::Optical;
    else return false;
    return true;
}

std::string writeLoopSet(const std::string &dir, const LoopSetOptions &opt)
{
    fs::create_directories(fs::path(dir) / "images");
    const std::string manifestPath = (fs::path(dir) / "manifest.csv").string();
    std::ofstream man(manifestPath), truth(fs::path(dir) / "truth.csv");
    if (!man || !truth) throw std::runtime_error("cannot write to '" + dir + "'");
    man << "id,image,n,k_mpa,d0_mm,h0_mm,mm_per_px,mu_ref,h_final_mm,operator,lens,press_speed_mm_s,ambient_c,"
           "sequence\n";
    truth << "id,mu,reduction,scale_error,u_mm,r_inner_mm,r_outer_mm,r_bulge_mm\n";
    std::mt19937 rng(opt.seed);
    auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    std::normal_distribution<double> refNoise(0, opt.muRefSigma);
    const char *ops[] = {"A", "B", "C"};
    const char *lenses[] = {"L16", "L25"};
    for (int i = 0; i < opt.count; ++i) {
        // μ and n where the FE snapshots and the paper's model both have data.
        const double n = U(0.1, 0.45), mu = U(0.08, 0.22);
        const std::string op = ops[rng() % 3], lens = lenses[rng() % 2];
        const double speed = U(1, 5), ambient = U(18, 28);
        // The press holds 50 % within ±0.1 % unless the process effect is on.
        const double r = opt.effect == LoopEffect::Process ? U(0.46, 0.54) : 0.5 + U(-0.001, 0.001);
        // Geometry from the FE: the ring's width from the paper's model at 50 % carried by the
        // FE du/dr (the physics the model lacks), the contact edge and the silhouette from the
        // FE snapshots at (n, μ, r).
        const double u = uForMu(mu, n) + vision::ReductionCorrectedModel::slopeAt(n, mu) * (r - 0.5);
        double ro = 0, rMax = 0;
        if (!vision::feRadiusAt(vision::FeRadius::Outer, n, mu, r, &ro) ||
            !vision::feRadiusAt(vision::FeRadius::Max, n, mu, r, &rMax))
            throw std::runtime_error("no FE snapshot data at the drawn (n, mu, r)");
        EndFaceScene s = nominalScene(u);
        s.width = opt.width, s.height = opt.height;
        s.mmPerPx = 2.0 * rMax * 1.06 / std::min(opt.width, opt.height) * U(1.0, 1.15);
        const double rMaxPx = rMax / s.mmPerPx;
        s.cxPx = U(rMaxPx + 8, std::max(rMaxPx + 9, s.width - rMaxPx - 8));
        s.cyPx = U(rMaxPx + 8, std::max(rMaxPx + 9, s.height - rMaxPx - 8));
        s.rOuterMm = ro, s.rInnerMm = ro - u, s.rMaxMm = rMax;
        s.noiseSigma = U(1, 3);
        s.blurSigmaPx = U(0.6, 1.2);
        s.seed = opt.seed * 1000u + uint32_t(i);
        // The optical effect: L25 was fitted later and nobody recalibrated, so its images are
        // declared at L16's scale: every radius comes out 8 % large.
        const double scaleError = opt.effect == LoopEffect::Optical && lens == "L25" ? 0.08 : 0.0;
        const cv::Mat img = renderEndFace(s);
        const auto bytes = encodeEndFace(s, img);
        char id[32];
        std::snprintf(id, sizeof id, "loop-%03d", i + 1);
        const std::string name = std::string(id) + (s.jpegQuality ? ".jpg" : ".png");
        std::ofstream(fs::path(dir) / "images" / name, std::ios::binary)
            .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
        char line[512];
        std::snprintf(line, sizeof line, "%s,images/%s,%.4f,%d,10,15,%.7f,%.4f,%.3f,%s,%s,%.2f,%.1f,%d\n", id,
                      name.c_str(), n, int(U(400, 900)), s.mmPerPx * (1 + scaleError), mu + refNoise(rng),
                      15 * (1 - r), op.c_str(), lens.c_str(), speed, ambient, i + 1);
        man << line;
        std::snprintf(line, sizeof line, "%s,%.5f,%.4f,%.3f,%.5f,%.5f,%.5f,%.5f\n", id, mu, r, scaleError,
                      s.rOuterEqMm() - s.rInnerEqMm(), s.rInnerEqMm(), s.rOuterEqMm(), rMax);
        truth << line;
    }
    return manifestPath;
}

} // namespace icacam::host
