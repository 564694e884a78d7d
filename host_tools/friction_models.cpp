#include "friction_models.h"

#include "vision/fe_model.h"
#include "vision/paper_model.h"

namespace icacam::host {
std::unique_ptr<vision::FrictionModel> makeFrictionModel(const std::string &name)
{
    if (name == "paper") return std::make_unique<vision::PaperModel>();
    if (name == "fe") return std::make_unique<vision::FeModel>(); // generated: docs/fe.md
    return nullptr;
}
} // namespace icacam::host
