#include "friction/friction_models.h"

#include "friction/aspect_corrected_model.h"
#include "friction/fe_model.h"
#include "friction/paper_model.h"
#include "friction/reduction_corrected_model.h"

namespace icacam::friction {

namespace {
// The models hold no state: constant-initialised, so no start-up order and no guard.
constinit const PaperModel kPaper;
constinit const FeModel kFe;
constinit const ReductionCorrectedModel kPaperCarry(kPaper, "paper_reduction");
constinit const ReductionCorrectedModel kFeCarry(kFe, "fe_reduction");
constinit const AspectCorrectedModel kPaperReduction(kPaperCarry);
constinit const AspectCorrectedModel kFeReduction(kFeCarry);
} // namespace

const FrictionModel *frictionModel(std::string_view name)
{
    if (name == "paper_reduction") return &kPaperReduction;
    if (name == "paper") return &kPaper;
    if (name == "fe_reduction") return &kFeReduction;
    if (name == "fe") return &kFe;
    return nullptr;
}

} // namespace icacam::friction
