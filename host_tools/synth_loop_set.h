#pragma once
// Image record sets for closing the loop (docs/loop.md, issue 6 item 3): rendered end faces
// with a reference μ and recorded columns, carrying one effect the μ model does not contain.
// `icacam synth --effect process|optical|null` writes them; tests/loop checks that
// `icacam loop` finds the effect without being told.
#include <cstdint>
#include <string>

namespace icacam::host {

enum class LoopEffect {
    Null,    // every specimen at 50 %, every lens calibrated: nothing to find
    Process, // the press stops at 46–54 % reduction (recorded in h_final_mm): u follows the FE
    Optical, // lens L25's images carry an 8 % scale error (the lab kept L16's mm_per_px)
};
bool parseLoopEffect(const std::string &name, LoopEffect *out);

struct LoopSetOptions {
    LoopEffect effect = LoopEffect::Null;
    int count = 48;
    uint32_t seed = 1;
    double muRefSigma = 0.003; // the reference method's scatter (../shared/data/README.md)
    // Small frames keep a test's run time down; the pipeline is scale-free.
    int width = 720, height = 560;
};

// Writes DIR/images/*.png, DIR/manifest.csv (what the lab recorded: id, image, n, k_mpa,
// d0_mm, h0_mm, mm_per_px, mu_ref, h_final_mm, operator, lens, press_speed_mm_s, ambient_c,
// sequence) and DIR/truth.csv (the hidden effect per record). Returns the manifest's path.
std::string writeLoopSet(const std::string &dir, const LoopSetOptions &opt);

} // namespace icacam::host
