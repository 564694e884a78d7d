#pragma once
// The physical form of an effect the ranking found (docs/loop-method.md, "The chosen effect
// in its physical form"): a grouping of images → a length scale per group (a camera's
// calibration), a material → the strain-hardening exponent n that makes its records
// consistent, a process variable the FE does not model → the size of its best form. The
// reduction's physical form (the FE du/dr) is host_tools/fe/reduction_slope.h.
#include <string>
#include <vector>

#include "friction/friction_model.h"
#include "host_tools/loop/loop_analysis.h"

namespace icacam::host::loop {

// How a grouping (a categorical column) enters the model physically.
enum class GroupReading {
    Scale, // every length in a group's images off by one factor: u_measured = s · u_true
    N,     // a group's declared n off by one shift: μ = model(u, n + Δn_group)
};
const char *formName(GroupReading reading); // the ranking's form: "factor" or "n"

// A grouping named as a material (material, alloy, grade), or whose every level carries one
// declared n (and at least two levels differ), is a material: its physical form is a shift of
// n. Any other grouping is read as images grouped by camera.
GroupReading readingOf(const std::vector<LoopRecord> &usable, const Candidate &grouping);

struct GroupFit {
    std::string level;
    int records = 0;
    double value = 0;    // the group's factor s (measured/true length) or its n (declared + fitted Δn)
    double sigma = 0;    // standard uncertainty of value (1 σ, from the pooled scatter)
    double declared = 0; // what the records declared: 1 for a factor, the level's n
    bool fitted = false; // fewer than 3 records: left at the declared value
    // Scale reading, radii with a silhouette: the group's R_max against the FE's R_max at its
    // records' n, μ_ref and reduction, relative to the other groups whose factor is consistent
    // with 1 (a check from the geometry alone, independent of μ); 0 when there is none.
    double silhouette = 0, silhouetteSigma = 0;
    // Scale reading: value and sigma are μ's and the outline's together (loop_silhouette.h).
    bool withOutline = false;
};

struct PhysicalFit {
    GroupReading reading = GroupReading::Scale;
    std::vector<GroupFit> groups; // fitted on every usable record
    double scatter = 0;           // pooled RMS of μ − μ_ref after the fit (per degree of freedom)
    std::vector<double> muAfter;  // μ per record with the fit on every record (for plots)
    std::vector<double> cvErrors; // held-out μ − μ_ref per record, each fold fitted on the others
};

// Fits one parameter per level by least squares of model(...) − μ_ref (Gauss–Newton), and the
// same per fold for the held-out error.
PhysicalFit fitGrouping(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                        const Candidate &grouping, GroupReading reading, const std::vector<int> &fold, int folds);

// Fits the grouping's parameter per level on the records where `train` holds and applies it
// to every record (u/s, or n + Δn): the effect taken out before the loop looks for the next.
// A level the training records never saw stays as declared. onlyDiffering: the levels are
// taken relative to the typical level (the median of three or more, else the one nearest the
// declared value), and a level within 2σ of the declared value stays declared.
void applyGrouping(const friction::FrictionModel &model, std::vector<LoopRecord> *records, const Candidate &grouping,
                   GroupReading reading, const std::vector<bool> &train, bool onlyDiffering = false);

// The estimates relative to the typical level (the median of three or more, else the one
// nearest the declared value): a factor over the typical factor, n shifted by minus the
// typical shift. With several effects fitted together a scale common to every group cannot
// be told from the other effects' common part; most cameras are taken as calibrated right,
// most materials as declared right.
void relativeToTypical(PhysicalFit *fit);

// The grouping's physical form for the ranking: its held-out errors, and those of its baseline,
// the same form with one parameter for every record (a global scale, a global Δn), so that a
// grouping is credited only for what telling its groups apart adds.
FittedForm groupingForm(const friction::FrictionModel &model, const std::vector<LoopRecord> &usable,
                        const Candidate &grouping, const std::vector<int> &fold, int folds);

// A numeric recorded condition in its best linear form: residual = sens·(a + b·x), b with its
// standard uncertainty, on every usable record.
struct LinearEffect {
    std::string form;          // "mu", "scale" or "u" (as in RankedCandidate)
    double slope = 0;          // b: μ, relative u or mm of u per unit of x
    double sigma = 0;          // standard uncertainty of b
    double xMin = 0, xMax = 0; // the recorded range (as recorded, also for a logarithmic x)
    bool logarithmic = false;  // the slope is per unit of ln x (a rate: isRate)
    double muSpan = 0;         // the μ the effect moves across the recorded range, at the median sensitivity
};
LinearEffect fitLinearEffect(const Candidate &c, const std::vector<double> &residual, const std::string &form,
                             const std::vector<double> &scaleSens, const std::vector<double> &uSens);

// A length factor taken out of a record: every length its image gave (u and the outline's
// R_max) divided by it.
void takeOutLengthFactor(LoopRecord *r, double factor);

// The model inputs of a record as it was measured.
friction::ModelInputs inputsOf(const LoopRecord &r);

} // namespace icacam::host::loop
