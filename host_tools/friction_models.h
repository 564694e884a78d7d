#pragma once
// Selecting a μ model by name for the host tools.
#include <memory>
#include <string>

#include "vision/friction_model.h"

namespace icacam::host {
// Names: "paper" (Duran & Karadogan 2016, corrected: the published reference, valid at 50 %
// reduction), "fe" (our CalculiX runs, docs/fe.md), and each of them carried to 50 % from a
// declared h_final_mm with the FE du/dr ("paper_reduction", "fe_reduction": docs/loop.md).
// Returns nullptr for an unknown name.
std::unique_ptr<vision::FrictionModel> makeFrictionModel(const std::string &name);

// What `icacam measure` uses unless told otherwise (the firmware uses the same).
inline constexpr const char *kDefaultModel = "paper_reduction";
inline constexpr const char *kKnownModels = "paper_reduction, paper, fe_reduction, fe";
} // namespace icacam::host
