#pragma once
// The contact edge between the nodes, tracked through the run (docs/fe.md).
//
// At one snapshot the contact edge R_o is only known to one node spacing of the former
// lateral surface: the outermost node on the platen. Along the run, though, every node's
// touchdown is an exact event of the FE solution. Between two touchdowns the edge moves from
// one node's material position to the next one's, so with the frames of a dense output
// (every 1 % of reduction) the edge's material position is interpolated in reduction between
// the events and mapped to the deformed side: u then grows smoothly instead of in steps of
// one node, which is what the mesh study and the independent model compare.
#include <cstddef>
#include <vector>

namespace icacam::host::fe {

// One output frame: the former lateral nodes from the mid-plane (index 0) to the corner
// (last index), their gap to the platen and their deformed radius.
struct SideFrame {
    double reduction = 0;
    std::vector<double> gapMm; // platen height − node height (≤ tol: on the platen)
    std::vector<double> rMm;
    // Nodes per element edge along the side: 1 linear elements, 2 quadratic (corner and
    // mid-side nodes alternate; trackedContactEdge follows each kind and takes the mean).
    int nodesPerEdge = 1;
};

// True when a former-lateral node is on the platen (gap ≤ tol) below a free node of the zone
// that grows from the corner: a node inside the zone has lifted off (seen with a stiff contact
// penalty: a mid-side node hovering a µm above the platen). The tracking follows the zone down
// from the corner, so the touchdowns below such a node come late and the edge lags.
bool contactZoneBroken(const SideFrame &frame, double tolMm);

// The reduction at which each node joins the contact zone that grows from the corner (its
// gap, followed from the free frames before it as c·(t* − t)^p with p between 1, a side
// meeting the platen at an angle, and 2, a tangent one, reaches tol), or -1 when it never
// does within the frames;
// made non-decreasing from the corner down (a node below cannot roll on before one above).
std::vector<double> touchdownReductions(const std::vector<SideFrame> &frames, double tolMm);

// R_o of frame k with the edge tracked between touchdowns: the edge's material position runs
// from node a (the last one down) to node b (the next) linearly in reduction between their
// touchdowns, and its radius is taken at that fraction of the deformed segment a–b; with
// quadratic elements, along the corner nodes and along the mid-side nodes separately, and the
// mean of the two. Before the first side node touches down the edge is the corner (u = 0, as
// with the node count). After the last event the next node's touchdown is predicted from its
// gap's approach in the frames so far (tolMm: as for the touchdowns).
double trackedContactEdge(const std::vector<SideFrame> &frames, const std::vector<double> &touchdown, std::size_t k,
                          double tolMm);

} // namespace icacam::host::fe
