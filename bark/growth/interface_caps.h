// Caps on the growing interface: a triangle whose vertex has come to lie on (or near) its
// opposite edge, an angle near 180°. A vertex that lags behind its neighbours (a blocked move)
// drifts onto the line between two of them; the triangle then has no short edge for the
// coarsening to collapse, and it flattens towards zero area, which the stress mesh of crack
// coupling cannot take. DSC removes such a cap (after Misztal and Bærentzen) by splitting the
// long edge at the foot of the cap vertex and collapsing the new point into it: the cap
// vertex keeps its place (it may lie on a crack), the two triangles become one edge.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

struct CapStats {
  long found = 0;    // interface triangles with an angle above the bound
  long removed = 0;  // split and collapsed
  // (gone, survivor) of each collapse: a crack edge a–b that a cap split follows its split
  // point into the survivor (crack coupling).
  std::vector<std::pair<uint32_t, uint32_t>> merged;
  // The interface's faces after the removal, sorted (as c.interface_faces()): those the last
  // pass found when it changed nothing, else found again at the end.
  std::vector<std::array<uint32_t, 3>> faces;
};

// Removes interface caps with an angle above `max_angle` (radians), each split kept only when
// every tetrahedron around the edge stays positive (exact predicate). A point on a crack stays
// where it is (interface_coarsening.h); the split point, on a crack edge or not, merges into
// it. Deterministic.
CapStats remove_interface_caps(TetComplex& c, TetAdjacency& adj, double max_angle);

}  // namespace phellem::bark
