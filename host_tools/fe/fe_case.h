#pragma once
// One upsetting case for CalculiX: the deck (axisymmetric quarter model, CAX4R, Coulomb
// friction against a rigid platen row, NLGEOM, σ = K(0.002 + ε_p)^n, or with a press speed
// the rate-sensitive σ = K ε^n (ε̇/ε̇₀)^m) and the post-processing of its results into R_i,
// R_o, R_max, u and the force–stroke curve.
#include <map>
#include <string>
#include <vector>

namespace icacam::host::fe {

struct FeCase {
    double kMpa = 500;
    double n = 0.25;
    double mu = 0.2;
    double eMpa = 210000;
    double nu = 0.3;
    double d0Mm = 10;
    double h0Mm = 15;
    double reductionMax = 0.5;                           // total height reduction of the run
    std::vector<double> reductions{0.3, 0.4, 0.45, 0.5}; // result snapshots (≤ reductionMax)
    double elemMm = 0.2;                                 // element edge length (structured mesh)
    // > 0: graded mesh, cornerMm at the end-face corner, growing by 1.2 per element
    // towards the axis and the mid-plane until elemMm (the ICA is then resolved to cornerMm).
    double cornerMm = 0;
    // > 0 (with cornerMm): the lateral surface keeps cornerMm elements over this length below
    // the corner before the grading starts, so the nodes that fold onto the platen (the ICA,
    // ≈ u × 1.3 of former side at 50 %) are evenly spaced instead of ×1.2 sparser per node.
    double foldZoneMm = 0;
    double platenMm = 0; // platen (master) segment length; 0: max(cornerMm, elemMm / 2)
    // Specimen element: "CAX4R" (linear, reduced integration) or "CAX8R" (quadratic,
    // reduced integration: follows the fold-over at high μ where CAX4R diverges).
    std::string element = "CAX4R";
    // Contact discretisation: "node" (NODE TO SURFACE: each slave node against the platen's
    // faces, the base setup) or "surface" (SURFACE TO SURFACE: the slave faces integrated
    // against the platen — another discretisation of the same law, for the independent model).
    std::string contact = "node";
    double contactSlope = 1e5;                            // N/mm³, linear pressure–overclosure
    double stickSlope = 1e4;                              // N/mm³, friction stick slope (1e4 and 1e5 give the same u)
    double incInit = 0.005, incMin = 1e-7, incMax = 0.01; // of the step time 1
    // > 0: extra output frames every trackStep of reduction, so the contact edge can be
    // tracked between the nodes' touchdowns (fe_contact_track.h); 0: the 5 % snapshots only.
    double trackStep = 0;
    // > 0: the press closes at this speed (mm/s, the whole stroke H0 · reductionMax in
    // stroke / speed seconds) and the material is rate-sensitive, σ = K ε^n (ε̇/ε̇₀)^m, run
    // as Norton time hardening in a *VISCO step (docs/fe.md, "Rate dependence"); m = 0 is
    // that form without a rate term. 0: the rate-independent *PLASTIC table in a *STATIC step.
    double pressSpeedMmS = 0;
    double m = 0;     // strain-rate sensitivity (needs pressSpeedMmS > 0 when not 0)
    double rate0 = 1; // ε̇₀, 1/s: the rate at which σ = K ε^n
    // *VISCO's CETOL: the largest difference in viscous strain over an increment between the
    // rates at its start and end (ccx manual, *VISCO). 1e-3 costs about three times as much on
    // the upsetting case (data/fe/studies/rate/README.md).
    double creepTol = 1e-2;
    bool rateSensitive() const { return pressSpeedMmS > 0; }
    std::string label() const; // a file-safe name from the inputs
};

// The step time of the deck: 1 for the *STATIC step, stroke / press speed (s) for *VISCO.
// Output frames and force totals come back in it; reduction = time / stepTime · reductionMax.
double stepTime(const FeCase &c);

// Node numbering of the generated mesh (needed to post-process). Nodes sit on a grid of
// q·nr + 1 by q·nz + 1 points (q = 2 for quadratic elements: mid-side nodes; the element
// centres of that grid are not written); i, j below index that node grid.
struct FeMesh {
    int nr = 0, nz = 0;         // specimen elements radially / axially
    int q = 1;                  // nodes per element edge minus one (1 linear, 2 quadratic)
    std::vector<double> r, z;   // element corner coordinates along the axes (nr + 1, nz + 1 values)
    std::vector<double> rn, zn; // node-grid coordinates (q·nr + 1, q·nz + 1 values)
    int platenFirstNode = 0;    // first node id of the platen
    int cols() const { return q * nr + 1; }
    int rows() const { return q * nz + 1; }
    int node(int i, int j) const { return 1 + i + j * cols(); }
    int cornerNode() const { return node(q * nr, q * nz); }
    int lateralNode(int j) const { return node(q * nr, j); } // j = 0 … q·nz (mid-plane … corner)
};

FeMesh meshFor(const FeCase &c);
std::string makeDeck(const FeCase &c);

struct Radii {
    double reduction = 0;
    double riMm = 0;       // original end face edge (the former corner node)
    double roMm = 0;       // outermost former-lateral node touching the platen
    double roInterpMm = 0; // R_o with the edge interpolated between nodes (tangent contact)
    double rMaxMm = 0;     // silhouette: the largest radius of the deformed lateral surface
    double uMm() const { return roMm - riMm; }
    double uInterpMm() const { return roInterpMm - riMm; }
    int contactNodes = 0;  // former lateral nodes in contact
    double roTrackMm = -1; // R_o tracked between touchdowns (fe_contact_track.h); -1: no frames
    double uTrackMm() const { return roTrackMm < 0 ? -1 : roTrackMm - riMm; }
};

// Node coordinates (x = r, y = z) and one displacement field.
using NodeXY = std::map<int, std::pair<double, double>>;

// A lateral node with a gap up to this is on the platen (the penalty contact lets it sink in).
constexpr double kGapTolMm = 1e-4;

// The output reductions of the deck: the snapshots and, with trackStep, the tracking frames.
std::vector<double> outputReductions(const FeCase &c);

Radii computeRadii(const FeCase &c, const FeMesh &m, const NodeXY &coords, const NodeXY &disp, double reduction,
                   double gapTolMm = kGapTolMm);

} // namespace icacam::host::fe
