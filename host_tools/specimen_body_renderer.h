#pragma once
// The upset specimen as a solid body photographed through any camera (tilted, distorting,
// close): the end face (original face disc and immigrated ring, the scene's texture) in
// the plane at the final height, and the barrelled lateral surface from the contact edge
// down to the fixture, bulging to R_max at half height. Every ray meets the nearest
// surface (the end face, the barrel or the fixture), so the barrel is seen where it really
// shows: wide on the side facing the camera, hidden behind the end face on the far side.
// The barrel is shaded by the LED ring around the lens: its brightness follows how far its
// normal turns away from the lens.
#include <opencv2/core.hpp>

#include "host_tools/calibration_renderer.h"
#include "host_tools/end_face_renderer.h"

namespace icacam::host {

// The barrel's profile: radius at height z (0 at the fixture, heightMm at the end face) is
// R_o + (R_max − R_o) · 4t(1 − t), t = z / heightMm: the contact edge at both ends, R_max at
// half height, leaving the end face at a slope 4 (R_max − R_o) / height (about 0.5 for the
// paper's specimen at 50 %: the lateral surface rolls over steeply, not tangentially).
double barrelRadiusMm(double rOuterMm, double rMaxMm, double heightMm, double zMm);

// The end face of `scene` (its mm geometry and texture; its pixel scale and position are
// ignored) standing on the fixture at (xMm, yMm) with the end face heightMm above it, seen
// through `cam`. Pixels near an occluding or surface edge are supersampled (4 × 4 rays);
// elsewhere one ray. The scene's illumination, blur and noise are applied in the camera's
// frame.
cv::Mat renderSpecimenBody(const CameraModel &cam, const EndFaceScene &scene, double xMm, double yMm, double heightMm);

} // namespace icacam::host
