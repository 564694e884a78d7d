#pragma once
// The μ models by name. Each is one static instance built at compile time: choosing a model
// (on the device, by config; in the host tools, by --model) allocates nothing.
#include <array>
#include <string_view>

#include "friction/friction_model.h"

namespace icacam::friction {

// "paper" (Duran & Karadogan 2016, corrected: the published reference, valid at 50 %
// reduction and H0/D0 1.5), "fe" (our CalculiX runs, docs/fe.md), and each of them carried
// to 50 % from a declared h_final_mm with the FE du/dr and to H0/D0 1.5 with the FE
// slenderness ratio ("paper_reduction", "fe_reduction": docs/loop.md, docs/fe.md).
inline constexpr std::array<std::string_view, 4> kModelNames = {"paper_reduction", "paper", "fe_reduction", "fe"};
inline constexpr const char *kKnownModels = "paper_reduction, paper, fe_reduction, fe";
// What `icacam measure` and the device use unless told otherwise.
inline constexpr const char *kDefaultModel = "paper_reduction";

// The model of that name, nullptr for an unknown name. The instance lives for the program.
const FrictionModel *frictionModel(std::string_view name);

} // namespace icacam::friction
