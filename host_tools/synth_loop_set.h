#pragma once
// Record sets for closing the loop (docs/loop.md): specimens with a reference μ and what a lab
// records, carrying one effect the μ model does not contain, as rendered end faces or as
// measured radii. `icacam synth --effect ...` writes them; tests/loop checks that `icacam loop`
// finds the effect without being told.
#include <cstdint>
#include <string>

namespace icacam::host {

enum class LoopEffect {
    Null,     // every specimen at 50 % (the recorded final height carries the gauge's ±0.015 mm),
              // every camera calibrated, every n right: nothing to find
    Process,  // the press stops at 46–54 % reduction (recorded in h_final_mm): u follows the FE
    Optical,  // lens L25's images carry an 8 % scale error (the lab kept L16's mm_per_px)
    Camera,   // one of three cameras measures every length 4 % large (a stale calibration)
    Material, // one material's declared n is off by 0.06–0.10 (its flow curve fitted over the
              // wrong strain range); its specimens deformed with the true n
    Speed,    // a rate-sensitive material: u grows with the press speed, u·(1 + 0.06 ln(v/1.6))
};
bool parseLoopEffect(const std::string &name, LoopEffect *out);

struct LoopSetOptions {
    LoopEffect effect = LoopEffect::Null;
    int count = 48;
    uint32_t seed = 1;
    double muRefSigma = 0.003; // the reference method's scatter (../shared/data/README.md)
    // Measured radii (r_inner_mm, r_outer_mm, r_bulge_mm, each with radiusSigmaMm of
    // measurement scatter) instead of rendered images.
    bool radii = false;
    double radiusSigmaMm = 0.003;
    // Small frames keep a test's run time down; the pipeline is scale-free.
    int width = 720, height = 560;
};

// The hidden effects' sizes (truth.csv carries them per record).
constexpr double kCameraScaleError = 0.04;
constexpr double kSpeedLogSlope = 0.06, kSpeedReferenceMmS = 1.6;

// Writes DIR/manifest.csv (what the lab recorded: id, image + mm_per_px or the three radii, n,
// k_mpa, d0_mm, h0_mm, mu_ref, h_final_mm, material, camera_id, lens, operator,
// press_speed_mm_s, ambient_c, sequence), DIR/images/* (images only) and DIR/truth.csv (per
// record: the true μ, n and reduction, the declared n, the length scale error, the speed
// factor of u, the true radii). Returns the manifest's path.
std::string writeLoopSet(const std::string &dir, const LoopSetOptions &opt);

} // namespace icacam::host
