// Caps on the growing interface: a triangle whose vertex has come to lie on (or near) its
// opposite edge, an angle near 180°. A vertex that lags behind its neighbours (a blocked move)
// drifts onto the line between two of them; the triangle then has no short edge for the
// coarsening to collapse, and it flattens towards zero area, which the stress mesh of crack
// coupling cannot take. DSC removes such a cap (after Misztal and Bærentzen) by splitting the
// long edge at the foot of the cap vertex and collapsing the new point into it: the cap
// vertex keeps its place (it may lie on a crack), the two triangles become one edge.
#pragma once

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

struct CapStats {
  long found = 0;    // interface triangles with an angle above the bound
  long removed = 0;  // split and collapsed
};

// Removes interface caps with an angle above `max_angle` (radians), each split kept only when
// every tetrahedron around the edge stays positive (exact predicate), and none whose long edge
// joins two crack points (it may be a crack edge). Deterministic.
CapStats remove_interface_caps(TetComplex& c, TetAdjacency& adj, double max_angle);

}  // namespace phellem::bark
