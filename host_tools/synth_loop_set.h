#pragma once
// Record sets for closing the loop (docs/loop.md): specimens with a reference μ and what a lab
// records, carrying one effect the μ model does not contain, as rendered end faces or as
// measured radii. `icacam synth --effect ...` writes them; tests/loop checks that `icacam loop`
// finds the effect without being told.
#include <cstdint>
#include <string>

namespace icacam::host {

// The hidden effects, as bits: a set may carry several at once (Camera | Material).
enum class LoopEffect : unsigned {
    Null = 0,                 // every specimen at 50 % (the recorded final height carries the gauge's ±0.015 mm),
                              // every camera calibrated, every n right: nothing to find
    Process = 1 << 0,         // the press stops at 46–54 % reduction (recorded in h_final_mm): u follows the FE
    Optical = 1 << 1,         // lens L25's images carry an 8 % scale error (the lab kept L16's mm_per_px)
    Camera = 1 << 2,          // one of three cameras measures every length 4 % large (a stale calibration)
    Material = 1 << 3,        // one material's declared n is off by 0.06–0.10 (its flow curve fitted over the
                              // wrong strain range); its specimens deformed with the true n
    Speed = 1 << 4,           // u grows with the press speed (friction that depends on it), u·(1 + 0.06 ln(v/1.6))
    Drift = 1 << 5,           // the scale drifts along the run: 0 at the first record to +8 % at the last
    SpeedInMaterial = 1 << 6, // in one material only u grows with the speed: its u·(1 + 0.10 ln(v/2.4))
    Rate = 1 << 7,            // each material's flow stress rises with the strain rate, σ = K ε^n (ε̇/1 s⁻¹)^m,
                              // m 0–0.12 per material: u does not move, the press's force (force_kn) does
};
constexpr LoopEffect operator|(LoopEffect a, LoopEffect b)
{
    return LoopEffect(unsigned(a) | unsigned(b));
}
constexpr bool has(LoopEffect set, LoopEffect e)
{
    return (unsigned(set) & unsigned(e)) != 0;
}
// One name (null, process, optical, camera, material, speed, drift, speed_material, rate) or a
// comma-separated list of them.
bool parseLoopEffect(const std::string &names, LoopEffect *out);
// The set's effects as the names above, joined by '+' ("null" for none).
std::string loopEffectNames(LoopEffect set);

struct LoopSetOptions {
    LoopEffect effect = LoopEffect::Null; // one effect or several (Camera | Material)
    int count = 48;
    uint32_t seed = 1;
    double muRefSigma = 0.003; // the reference method's scatter (../shared/data/README.md)
    // Measured radii (r_inner_mm, r_outer_mm, r_bulge_mm, each with radiusSigmaMm of
    // measurement scatter) instead of rendered images.
    bool radii = false;
    double radiusSigmaMm = 0.003;
    // The barrel's widest radius varies from specimen to specimen about the FE's (the bar's
    // anisotropy, the friction not quite uniform, the end face's tilt) and a silhouette is read
    // to about half a per cent (friction::kMeasuredRMaxRelSigma): relative, on r_bulge_mm.
    double bulgeRelSigma = 0.005;
    // Small frames keep a test's run time down; the pipeline is scale-free.
    int width = 720, height = 560;
};

// The hidden effects' sizes (truth.csv carries them per record).
constexpr double kCameraScaleError = 0.04;
constexpr double kSpeedLogSlope = 0.06, kSpeedReferenceMmS = 1.6;
// SpeedInMaterial: the one material whose u moves with the speed, about the run's typical speed (the
// geometric mean of the speeds drawn), so that the effect is a slope and not a shift of that
// material's u (which would read as its n).
constexpr double kMaterialSpeedLogSlope = 0.10, kMaterialSpeedReferenceMmS = 2.4;
constexpr double kDriftScaleError = 0.08; // Drift: the last record's scale error
// Rate: each material's m uniform in [0, kRateMMax]; the load cell's reading to kForceRelSigma.
constexpr double kRateMMax = 0.12, kForceRelSigma = 0.01;

// Writes DIR/manifest.csv (what the lab recorded: id, image + mm_per_px or the three radii, n,
// k_mpa, d0_mm, h0_mm, mu_ref, h_final_mm, material, camera_id, lens, operator,
// press_speed_mm_s, ambient_c, sequence), DIR/images/* (images only) and DIR/truth.csv (per
// record: the true μ, n and reduction, the declared n, the length scale error, the speed
// factor of u, the true radii, the set's effects, the camera's and the drift's share of the
// scale error, and the μ each of the camera, the drift, the speed and a wrong declared n adds
// to the paper model's μ at the record). With the rate effect the manifest also carries the
// press's peak force at the final height (force_kn: the slab method's K ε^n (ε̇/1 s⁻¹)^m ·
// πR²·(1 + 2μR/3h), ε̇ the speed over the final height) and truth.csv each record's m (m_true).
// Returns the manifest's path.
std::string writeLoopSet(const std::string &dir, const LoopSetOptions &opt);

} // namespace icacam::host
