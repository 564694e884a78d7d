#pragma once
// The second half of a measurement: the end face's geometry (boundaries and silhouette in
// pixels, image-quality flags) and what the instrument was told (SpecimenSpec, a camera
// calibration) → radii in mm, u, μ, its uncertainty budget, status and flags. The device,
// `icacam measure` and `icacam loop` all read through `Instrument`, which calls this.
//
// The budget follows the GUM (JCGM 100): every component is a standard uncertainty of an
// input carried into μ by the friction model's own sensitivity (central differences of the
// model, never a hand-derived slope):
//   edges      u's scatter from the boundary fits, a 0.1 px edge-location floor per
//              boundary, and an uncalibrated camera's tilt (the boundaries' shared ellipticity);
//   scale      mm_per_px's tolerance, or the calibration's own and the end-face plane's
//              height (which follows the reduction);
//   reduction  the final height: declared with its tolerance, or inferred (below), and the
//              carry to 50 % itself (the FE slope is not exact);
//   n          the declared n's tolerance;
//   model      the 50 % model's own fit error.
//
// The silhouette R_max ties scale and reduction together: ln(R_max / R_max,FE) = δk + β·δr
// (δk the scale's relative error, β = ∂ln R_max,FE/∂r). A silhouette that fits the FE's
// shape (R_max/R_o within what the FE and the edges allow) is one observation of δk + β·δr;
// with the priors of the declared scale and reduction it gives their posterior (a linear
// Gaussian update; past χ² = 1 the posterior is widened by χ², as for a Birge ratio). With a
// declared final height the discrepancy is mostly the scale's (and past 3 σ neither is
// corrected: both are widened to explain it alone). Without one the silhouette cannot tell
// a specimen pressed further (the undeclared reduction's prior, 45–55 %) from the nominal
// half height read through a scale grossly off (measured on the fixture, or a wrong edge):
// the reading is the mixture of the posteriors, weighted by how well each predicts the
// discrepancy, and its covariance includes their spread, so that whichever is true lies
// within the budget. In a view the image shows to be oblique, a silhouette foreshortened by
// the camera's closeness and distortion (the nominal height, u's scale as declared) is a
// further explanation; and in every view, a silhouette taken on a wrong edge inside the
// outline, which tells nothing (the priors kept). The silhouette's own error is the FE's and
// the per-ray points' scatter about their fit. A calibrated scale is not checked by the
// silhouette (a camera close enough to need a calibration sees the barrel's widest section
// partly hidden behind the end face's rim).
//
// Status: from the checks alone: ok when none finds a condition the budget may not cover,
// else warn with the finding named. The lab's tolerance is a decision on U = 2σ_μ (within or
// beyond, its own field), and the advice names the declared input that would shrink U most.
// Pure C++20: no heap, no OS calls, no exceptions. The steps are in interpretation_steps.h.
#include "friction/friction_model.h"
#include "reading/reading.h"
#include "reading/specimen_spec.h"
#include "vision/end_face_geometry.h"
#include "vision/plane_calibration.h"

namespace icacam::reading {

// A reading of a measured end face. calibration: the camera's, or nullptr (the spec's scale).
// A geometry that carries an error gives a reading with that error.
Reading interpret(const vision::EndFaceGeometry &geometry, const SpecimenSpec &spec,
                  const vision::PlaneCalibration *calibration, const friction::FrictionModel &model);

// A reading of radii measured elsewhere (a record set's r_inner_mm, r_outer_mm and, where
// given, the silhouette): the same interpretation without the image's own checks.
Reading interpret(const FaceInMm &face, const SpecimenSpec &spec, const friction::FrictionModel &model);

// The silhouette's relative 1-σ error against the FE: the FE's and the measurement's, from
// the per-ray fit's scatter (friction/radii_consistency.h).
double silhouetteRelSigma(const vision::EndFaceGeometry &g);

} // namespace icacam::reading
