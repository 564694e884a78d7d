#pragma once
// Selecting a μ model by name for the host tools.
#include <memory>
#include <string>

#include "vision/friction_model.h"

namespace icacam::host {
// Names: "paper" (Duran & Karadogan 2016, corrected). Returns nullptr for an unknown name.
std::unique_ptr<vision::FrictionModel> makeFrictionModel(const std::string &name);
} // namespace icacam::host
