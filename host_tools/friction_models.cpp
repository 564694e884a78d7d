#include "friction_models.h"

#include "vision/fe_model.h"
#include "vision/paper_model.h"
#include "vision/reduction_corrected_model.h"

namespace icacam::host {
std::unique_ptr<vision::FrictionModel> makeFrictionModel(const std::string &name)
{
    // The base models hold no state: one instance each serves every decorator.
    static const vision::PaperModel paper;
    static const vision::FeModel fe;
    if (name == "paper") return std::make_unique<vision::PaperModel>();
    if (name == "fe") return std::make_unique<vision::FeModel>(); // generated: docs/fe.md
    if (name == "paper_reduction") return std::make_unique<vision::ReductionCorrectedModel>(paper, "paper_reduction");
    if (name == "fe_reduction") return std::make_unique<vision::ReductionCorrectedModel>(fe, "fe_reduction");
    return nullptr;
}
} // namespace icacam::host
