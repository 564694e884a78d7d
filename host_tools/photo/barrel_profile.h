#pragma once
// The barrel's free surface from the project's own CalculiX runs: the deformed former
// lateral nodes of the axisymmetric quarter model (host_tools/fe), from the mid-plane up to
// the contact edge on the platen, at each snapshot reduction. The photographic bench builds
// the specimen's side from it (a surface of revolution), so the outline a close camera sees
// and the light the side throws back follow the FE's shape, not a drawn band.
//
// A profile is stored as it was solved (mm, D0 10 mm, H0 15 mm). Its shape, normalised
// between the contact edge and the widest section, is interpolated in (n, μ, reduction) and
// scaled onto the FE base's R_o and R_max (friction/radii_consistency.h) at render time: the
// coarse mesh these runs use gives the shape; the base gives the radii it is best at.
#include <string>
#include <vector>

#include "host_tools/fe/fe_case.h"

namespace icacam::host::photo {

struct BarrelProfile {
    std::string caseLabel;
    double n = 0, mu = 0, kMpa = 0, reduction = 0;
    // From the mid-plane (z 0, the widest section) to the contact edge (z = h/2, r = R_o of
    // this run), in order along the former lateral surface.
    std::vector<double> zMm, rMm;
};

// The free-surface profile of one snapshot of a solved case (its frd coordinates and
// displacements), or an empty profile when the snapshot is not in the results.
BarrelProfile extractBarrelProfile(const fe::FeCase &c, const fe::NodeXY &coords, const fe::NodeXY &disp,
                                   double reduction);

// The CSV (case,n,mu,k_mpa,reduction,point,z_mm,r_mm): one row per point.
void writeBarrelProfiles(const std::string &path, const std::vector<BarrelProfile> &profiles);
// Throws std::runtime_error when the file is missing or malformed.
std::vector<BarrelProfile> readBarrelProfiles(const std::string &path);

// The shape at (n, μ, reduction), resampled at kShapePoints positions along the surface:
// zeta = z / (h/2) (0 mid-plane … 1 platen) and s = (r − R_o) / (R_max − R_o) (1 at the
// widest section, 0 at the contact edge). Interpolated linearly between the nearest solved
// n, μ and reduction (held at the grid's ends).
struct BarrelShape {
    std::vector<double> zeta, s;
};
// 32 points along the side: the FE's own nodes are 0.1–0.5 mm apart (25–30 per side); more
// only slow the renderer's surface of revolution (its cost grows with the segments).
constexpr int kShapePoints = 32;
BarrelShape barrelShapeAt(const std::vector<BarrelProfile> &table, double n, double mu, double reduction);

// The grid the committed table is solved on, and the mesh that solves it.
fe::FeCase profileCase(double n, double mu);
const std::vector<double> &profileGridN();
const std::vector<double> &profileGridMu();
const std::vector<double> &profileReductions();

// Runs (or, with reuse, post-processes again) every case of the grid in workDir and writes
// the table. Progress on stderr.
void makeBarrelProfiles(const std::string &outCsv, const std::string &workDir, const std::string &ccx);

} // namespace icacam::host::photo
