#include "friction_models.h"

#include "vision/aspect_corrected_model.h"
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
    // The carried models also take other slenderness (H0/D0 1.0–2.0) to the paper's 1.5.
    static const vision::ReductionCorrectedModel paperCarry(paper, "paper_reduction");
    static const vision::ReductionCorrectedModel feCarry(fe, "fe_reduction");
    if (name == "paper_reduction") return std::make_unique<vision::AspectCorrectedModel>(paperCarry);
    if (name == "fe_reduction") return std::make_unique<vision::AspectCorrectedModel>(feCarry);
    return nullptr;
}
} // namespace icacam::host
