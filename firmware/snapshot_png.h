#pragma once
// A snapshot for a PC: the full frame as a PNG with the measured boundaries drawn in colour
// (the fitted inner boundary red, the fitted outer one green, their edge points yellow, the
// barrel's silhouette circle blue), so the set-up can be judged at full resolution. An
// 8-bit palette image (252 grey levels and the four colours), encoded row by row: no
// full-frame copy is made.
#include <string>

#include "reading/reading.h"
#include "vision/luma_view.h"

namespace icacam::fw {

// Appends the PNG to *out. Returns "" or what went wrong.
std::string encodeSnapshotPng(const vision::LumaView &v, const reading::Reading &m, std::string *out);

} // namespace icacam::fw
