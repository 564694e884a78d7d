#pragma once
#include <string>
#include <vector>

namespace icacam::host::photo {

// `icacam synth --renderer povray …`: the photographic bench (docs/photobench.md).
int photoSynthCommand(const std::vector<std::string> &args);

// True when args ask for the POV-Ray renderer (`--renderer povray` or `--renderer=povray`).
bool wantsPovray(const std::vector<std::string> &args);

} // namespace icacam::host::photo
