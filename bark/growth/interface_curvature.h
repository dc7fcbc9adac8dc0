// The curvature term of reversed growth (Kratt et al., sec. 4.3): negated growth alone lets a
// shrinking surface fold into itself where it is concave, so each step also moves every
// interface vertex a fraction of the way to the mean of its interface neighbours, along its
// normal only (a mean-curvature flow step: the surface does not slide, so UVs stay put). Each
// move is halved or dropped if it would invert a tetrahedron.
#pragma once

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

// `rate` in [0, 1]: the fraction of the normal component of (neighbour mean − vertex).
// `only_outwards`: only vertices below their neighbours move (pits rise; a convex surface
// does not shrink). Returns the number of vertices moved. Deterministic (Jacobi: all targets
// from the old positions).
long smooth_interface_curvature(TetComplex& c, double rate, bool only_outwards = false);
// The same with what a growth step already holds: the adjacency and the interface faces sorted
// (as TetComplex::interface_faces() returns them), so nothing is rebuilt from all tetrahedra.
// With `owed` (advance_interface's, by point), what the term lifts a vertex by repays what its
// blocked moves owe (without it the two together overshot: 0.7 mm ahead on the large-growth
// benchmark).
long smooth_interface_curvature(TetComplex& c, const TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double rate, bool only_outwards = false, std::vector<double>* owed = nullptr);

}  // namespace phellem::bark
