#include "host_tools/synth_loop_set.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <stdexcept>

#include "friction/paper_model.h"
#include "friction/radii_consistency.h"
#include "friction/reduction_corrected_model.h"
#include "host_tools/end_face_renderer.h"
#include "host_tools/model_inverse.h"

namespace icacam::host {

namespace fs = std::filesystem;

namespace {

// A lab's materials: one declared n and K each (n and μ where the FE snapshots and the
// paper's model both have data).
struct Material {
    const char *name;
    double n;
    int kMpa;
};
constexpr Material kMaterials[] = {
    {"AlMgSi1", 0.14, 290}, {"C15E", 0.22, 760}, {"CuZn37", 0.34, 680}, {"X5CrNi18-10", 0.44, 1150}};
constexpr int kMaterialCount = int(sizeof kMaterials / sizeof kMaterials[0]);
const char *const kCameras[] = {"cam-1", "cam-2", "cam-3"};

} // namespace

namespace {

struct EffectName {
    const char *name;
    LoopEffect effect;
};
constexpr EffectName kEffectNames[] = {
    {"null", LoopEffect::Null},         {"process", LoopEffect::Process},
    {"optical", LoopEffect::Optical},   {"camera", LoopEffect::Camera},
    {"material", LoopEffect::Material}, {"speed", LoopEffect::Speed},
    {"drift", LoopEffect::Drift},       {"speed_material", LoopEffect::SpeedInMaterial},
    {"rate", LoopEffect::Rate}};

} // namespace

bool parseLoopEffect(const std::string &names, LoopEffect *out)
{
    LoopEffect set = LoopEffect::Null;
    size_t begin = 0;
    while (begin <= names.size()) {
        const size_t end = std::min(names.find(',', begin), names.size());
        const std::string name = names.substr(begin, end - begin);
        bool known = false;
        for (const EffectName &e : kEffectNames)
            if (name == e.name) set = set | e.effect, known = true;
        if (!known) return false;
        begin = end + 1;
    }
    *out = set;
    return true;
}

std::string loopEffectNames(LoopEffect set)
{
    std::string s;
    for (const EffectName &e : kEffectNames)
        if (has(set, e.effect)) s += (s.empty() ? "" : "+") + std::string(e.name);
    return s.empty() ? "null" : s;
}

std::string writeLoopSet(const std::string &dir, const LoopSetOptions &opt)
{
    fs::create_directories(fs::path(dir) / (opt.radii ? "" : "images"));
    const std::string manifestPath = (fs::path(dir) / "manifest.csv").string();
    const bool rate = has(opt.effect, LoopEffect::Rate);
    std::ofstream man(manifestPath), truth(fs::path(dir) / "truth.csv");
    if (!man || !truth) throw std::runtime_error("cannot write to '" + dir + "'");
    man << "id," << (opt.radii ? "r_inner_mm,r_outer_mm,r_bulge_mm" : "image,mm_per_px")
        << ",n,k_mpa,d0_mm,h0_mm,mu_ref,h_final_mm,material,camera_id,lens,operator,press_speed_mm_s,ambient_c,"
           "sequence"
        << (rate ? ",force_kn" : "") << "\n";
    truth << "id,mu,n_true,n_declared,reduction,scale_error,speed_factor,u_mm,r_inner_mm,r_outer_mm,r_bulge_mm,"
             "material,camera_id,effects,camera_error,drift_error,mu_camera_shift,mu_drift_shift,mu_speed_shift,"
             "mu_n_shift"
          << (rate ? ",m_true" : "") << "\n";
    const std::string effects = loopEffectNames(opt.effect);
    std::mt19937 rng(opt.seed);
    auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    std::normal_distribution<double> refNoise(0, opt.muRefSigma), radiusNoise(0, opt.radiusSigmaMm);
    const char *ops[] = {"A", "B", "C"};
    const char *lenses[] = {"L16", "L25"};
    // The set's hidden fault: which camera and which material, and the material's wrong n.
    const int badCamera = int(rng() % 3), badMaterial = int(rng() % uint32_t(kMaterialCount));
    double wrongN = kMaterials[badMaterial].n + (rng() % 2 ? 1 : -1) * U(0.06, 0.10);
    if (wrongN < 0.06 || wrongN > 0.5) wrongN = kMaterials[badMaterial].n + (wrongN < 0.06 ? 1 : -1) * 0.08;
    const friction::PaperModel paper; // the truth: μ from u at 50 %
    // The rate effect draws from its own stream: every other set stays as it was.
    std::mt19937 rateRng(opt.seed * 7919u + 17u);
    double mOf[kMaterialCount] = {};
    for (double &m : mOf) m = rate ? std::uniform_real_distribution<double>(0, kRateMMax)(rateRng) : 0.0;
    std::normal_distribution<double> forceNoise(0, kForceRelSigma);
    // The specimens' own barrels, from a stream of their own: every other column stays as it was.
    std::mt19937 bulgeRng(opt.seed * 7057u + 29u);
    std::normal_distribution<double> bulgeNoise(0, opt.bulgeRelSigma);
    for (int i = 0; i < opt.count; ++i) {
        const int m = int(rng() % uint32_t(kMaterialCount)), cam = int(rng() % 3);
        const Material &mat = kMaterials[m];
        const double n = mat.n, mu = U(0.08, 0.22);
        const double nDeclared = has(opt.effect, LoopEffect::Material) && m == badMaterial ? wrongN : n;
        const std::string op = ops[rng() % 3], lens = lenses[rng() % 2];
        const double speed = U(0.5, 5), ambient = U(18, 28);
        // The press holds 50 % unless the process effect is on; the recorded final height
        // carries the height gauge's ±0.015 mm either way.
        const double r = has(opt.effect, LoopEffect::Process) ? U(0.46, 0.54) : 0.5;
        const double hFinalRecorded = 15 * (1 - r) + U(-0.015, 0.015);
        // Geometry from the FE: the ring's width from the paper's model at 50 % carried by the
        // FE du/dr (the physics the model lacks), the contact edge and the silhouette from the
        // FE snapshots at (n, μ, r). A speed effect (the lubricant's friction) widens the ring with the speed.
        double speedFactor = 1.0;
        if (has(opt.effect, LoopEffect::Speed))
            speedFactor *= 1 + kSpeedLogSlope * std::log(speed / kSpeedReferenceMmS);
        if (has(opt.effect, LoopEffect::SpeedInMaterial) && m == badMaterial)
            speedFactor *= 1 + kMaterialSpeedLogSlope * std::log(speed / kMaterialSpeedReferenceMmS);
        const double u =
            (uForMu(paper, mu, n) + friction::ReductionCorrectedModel::slopeAt(n, mu) * (r - 0.5)) * speedFactor;
        double ro = 0, rMax = 0;
        if (!friction::feRadiusAt(friction::FeRadius::Outer, n, mu, r, &ro) ||
            !friction::feRadiusAt(friction::FeRadius::Max, n, mu, r, &rMax))
            throw std::runtime_error("no FE snapshot data at the drawn (n, mu, r)");
        // A stale calibration: the lab's mm_per_px is too large, so every length comes out
        // large by the same factor (L25 was fitted later and kept L16's scale; one camera
        // was moved after it was calibrated).
        // The drift: the camera creeping away over the run, a little more with every specimen.
        double scaleError = 0, cameraError = 0, driftError = 0;
        if (has(opt.effect, LoopEffect::Camera) && cam == badCamera) cameraError = kCameraScaleError;
        if (has(opt.effect, LoopEffect::Drift) && opt.count > 1) driftError = kDriftScaleError * i / (opt.count - 1);
        scaleError = (1 + cameraError) * (1 + driftError) - 1;
        if (has(opt.effect, LoopEffect::Optical) && lens == std::string("L25"))
            scaleError = (1 + scaleError) * 1.08 - 1;
        // What each hidden effect adds to the paper model's μ at this record (the truth a run's
        // design is judged against: how large an effect is against the records' scatter).
        auto paperMu = [&](double uMm, double nAt) {
            friction::ModelInputs in;
            in.uMm = uMm, in.n = nAt;
            return paper.estimate(in).mu;
        };
        const double uCamera = u * (1 + driftError);
        const double muCameraShift = paperMu(uCamera * (1 + cameraError), nDeclared) - paperMu(uCamera, nDeclared);
        const double muDriftShift = paperMu(u * (1 + driftError), nDeclared) - paperMu(u, nDeclared);
        const double muSpeedShift = paperMu(u, n) - paperMu(u / speedFactor, n);
        const double muNShift = paperMu(u, nDeclared) - paperMu(u, n);
        char id[32];
        std::snprintf(id, sizeof id, "loop-%03d", i + 1);
        std::string measured;
        double ri = ro - u, roEq = ro;
        char line[640];
        if (opt.radii) {
            const double k = 1 + scaleError;
            std::snprintf(line, sizeof line, "%.5f,%.5f,%.5f", (ri + radiusNoise(rng)) * k, (ro + radiusNoise(rng)) * k,
                          (rMax * (1 + bulgeNoise(bulgeRng)) + radiusNoise(rng)) * k);
            measured = line;
        } else {
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
            const cv::Mat img = renderEndFace(s);
            const auto bytes = encodeEndFace(s, img);
            const std::string name = std::string(id) + (s.jpegQuality ? ".jpg" : ".png");
            std::ofstream(fs::path(dir) / "images" / name, std::ios::binary)
                .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
            std::snprintf(line, sizeof line, "images/%s,%.7f", name.c_str(), s.mmPerPx * (1 + scaleError));
            measured = line;
            ri = s.rInnerEqMm(), roEq = s.rOuterEqMm();
        }
        std::snprintf(line, sizeof line, "%s,%s,%.4f,%d,10,15,%.4f,%.3f,%s,%s,%s,%s,%.2f,%.1f,%d", id, measured.c_str(),
                      nDeclared, mat.kMpa, mu + refNoise(rng), hFinalRecorded, mat.name, kCameras[cam], lens.c_str(),
                      op.c_str(), speed, ambient, i + 1);
        man << line;
        if (rate) {
            // The slab method's upsetting force at the final height, the flow stress at the
            // strain rate the press's speed gives there.
            const double h = 15 * (1 - r), radius = 5 * std::sqrt(15 / h), strain = std::log(15 / h);
            const double flow = mat.kMpa * std::pow(strain, n) * std::pow(speed / h, mOf[m]);
            const double kN = flow * std::numbers::pi * radius * radius * (1 + 2 * mu * radius / (3 * h)) / 1000;
            std::snprintf(line, sizeof line, ",%.3f", kN * (1 + forceNoise(rateRng)));
            man << line;
        }
        man << "\n";
        std::snprintf(line, sizeof line,
                      "%s,%.5f,%.4f,%.4f,%.4f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%s,%s,%s,%.5f,%.5f,%.6f,%.6f,%.6f,%.6f", id,
                      mu, n, nDeclared, r, scaleError, speedFactor, roEq - ri, ri, roEq, rMax, mat.name, kCameras[cam],
                      effects.c_str(), cameraError, driftError, muCameraShift, muDriftShift, muSpeedShift, muNShift);
        truth << line;
        if (rate) {
            std::snprintf(line, sizeof line, ",%.4f", mOf[m]);
            truth << line;
        }
        truth << "\n";
    }
    return manifestPath;
}

} // namespace icacam::host
